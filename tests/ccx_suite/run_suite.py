#!/usr/bin/env python3
"""Runs the CalculiX test suite (Debian package calculix-ccx-test) through Styk.

Selects the decks a linear static solver can run -- a *STATIC step without NLGEOM, no nonlinear
material, no other procedure, every element type known to `styk elements` -- solves each with
`styk solve`, and compares Styk's .dat block by block with the suite's reference .dat.ref (ccx's
own output): the worst difference of a block is max |Styk - ccx| over its rows divided by the
block's largest |ccx| value.

  run_suite.py --styk build/cli/styk --work DIR [--expect expected.tsv] [--table out.md]

Outcomes: match (every block within 1e-4), close (within 1e-2), match-u / close-u (the
displacements within 1e-4 / 1e-2, other blocks not), differs, refused (Styk stops with a message), no-output (the deck prints
nothing). With --expect, every deck's outcome must be the one expected.tsv records (a refusal with
a message substring), so a deck that stops matching or
starts solving fails the run until the file (and docs/ccx-suite.md, generated with --table) say so.
"""
import argparse
import concurrent.futures
import gzip
import os
import re
import shutil
import subprocess
import sys

SUITE = "/usr/share/doc/calculix-ccx-test/examples/test"
OTHER_PROCEDURES = ("*FREQUENCY", "*BUCKLE", "*DYNAMIC", "*HEAT TRANSFER", "*COUPLED TEMPERATURE",
                    "*MODAL DYNAMIC", "*STEADY STATE DYNAMICS", "*VISCO", "*CFD", "*GREEN",
                    "*SENSITIVITY", "*ELECTROMAGNETICS", "*UNCOUPLED", "*COMPLEX FREQUENCY",
                    "*FEASIBLE DIRECTION", "*CRACK PROPAGATION", "*SUBSTRUCTURE")
NONLINEAR_MATERIALS = ("*PLASTIC", "*HYPERELASTIC", "*HYPERFOAM", "*CREEP", "*USER MATERIAL",
                       "*DEFORMATION PLASTICITY", "*CYCLIC HARDENING", "*MOHR COULOMB")
MATCH, CLOSE = 1e-4, 1e-2  # worst block difference, relative to the block's largest value
# Element-result blocks are keyed by element and integration point, nodal blocks by node.
ELEMENT_BLOCKS = ("stresses", "strains", "internal energy density", "heat flux")


def read_text(path):
    opener = gzip.open if path.endswith(".gz") else open
    with opener(path, "rt", errors="replace") as f:
        return f.read()


def suite_file(name, suffix):
    for candidate in (name + suffix, name + suffix + ".gz"):
        if os.path.exists(os.path.join(SUITE, candidate)):
            return os.path.join(SUITE, candidate)
    return None


def why_not_linear_static(text, known_types):
    """Empty when a linear static solver can run the deck, else the first reason it cannot."""
    upper = text.upper()
    cards = [l.strip() for l in upper.splitlines() if l.startswith("*") and not l.startswith("**")]
    keywords = [c.split(",")[0].strip() for c in cards]
    if "*INCLUDE" in keywords:
        return "includes other files"
    if "*STATIC" not in keywords:
        return "no *STATIC step"
    for k in keywords:
        if k.startswith(OTHER_PROCEDURES):
            return "procedure " + k
        if k.startswith(NONLINEAR_MATERIALS):
            return "material " + k
    for c in cards:
        compact = c.replace(" ", "")
        if c.startswith("*STEP") and "NLGEOM" in compact and "NLGEOM=NO" not in compact:
            return "NLGEOM"
    types = set(re.findall(r"^\*ELEMENT\s*,.*?TYPE\s*=\s*([A-Z0-9]+)", upper, re.M))
    missing = sorted(types - known_types)
    return "element types " + " ".join(missing) if missing else ""


def dat_blocks(text):
    """{(quantity, set, time): {row key: values}} of a ccx-layout .dat file."""
    blocks, rows, quantity = {}, None, None
    for line in text.splitlines():
        s = line.strip()
        if not s:
            continue
        head = re.match(r"(.+?) for set (\S+) and time\s+(\S+)", s)
        if head:
            quantity = head.group(1).split("(")[0].strip()
            key = (quantity, head.group(2).upper(), float(head.group(3).replace("D", "E")))
            rows = blocks.setdefault(key, {})
            continue
        if rows is None:
            continue
        fields = s.split()
        if fields[-1] == "L":
            fields.pop()  # ccx 2.20 marks a *TRANSFORM node's local components with L
        try:
            values = [float(x.replace("D", "E")) for x in fields[1:]]
        except ValueError:
            rows = None  # a line that is not a row ends the block
            continue
        width = 2 if quantity in ELEMENT_BLOCKS else 1
        rows[tuple(fields[:width])] = values[width - 1:]
    return blocks


def worst_difference(reference, styk):
    """(worst relative difference, where, rows compared, missing blocks or rows)."""
    worst, where, compared, missing = 0.0, "", 0, []
    for key, ref_rows in reference.items():
        same = [k for k in styk if k[:2] == key[:2] and abs(k[2] - key[2]) <= 1e-6 * max(1, abs(key[2]))]
        if not same:
            missing.append("%s %s t=%g" % key)
            continue
        rows = styk[same[0]]
        scale = max((abs(v) for vs in ref_rows.values() for v in vs), default=0.0) or 1.0
        for row, ref in ref_rows.items():
            mine = rows.get(row)
            if mine is None and all(v == 0.0 for v in ref):
                continue  # ccx prints zero rows for set ids that are not nodes
            if mine is None or len(mine) != len(ref):
                missing.append("%s row %s" % (key[0], " ".join(row)))
                break
            compared += 1
            d = max(abs(a - b) for a, b in zip(ref, mine)) / scale
            if d > worst:
                worst, where = d, "%s %s %s" % (key[0], key[1], " ".join(row))
    return worst, where, compared, missing


def first_error(stderr):
    for line in stderr.splitlines():
        if re.search(r"\.inp(:\d+)?: ", line):
            return line.strip()
    lines = [l for l in stderr.splitlines() if l.strip()]
    return lines[-1].strip() if lines else ""


def run_deck(name, deck, styk, work):
    folder = os.path.join(work, name)
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    with open(os.path.join(folder, name + ".inp"), "w") as f:
        f.write(read_text(deck))
    try:
        done = subprocess.run([styk, "solve", name + ".inp"], cwd=folder, capture_output=True,
                              text=True, timeout=300)
    except subprocess.TimeoutExpired:
        return name, "refused", "timed out after 300 s"
    if done.returncode != 0:
        return name, "refused", first_error(done.stderr)
    reference = dat_blocks(read_text(suite_file(name, ".dat.ref")))
    if not reference:
        return name, "no-output", "the deck prints nothing to compare"
    styk_blocks = dat_blocks(read_text(os.path.join(folder, name + ".dat")))
    worst, where, compared, missing = worst_difference(reference, styk_blocks)
    if not missing and worst <= CLOSE:
        outcome = "match" if worst <= MATCH else "close"
        if worst == 0.0:
            return name, outcome, "identical to the printed digits (%d rows)" % compared
        return name, outcome, "%.1e (%s, %d rows)" % (worst, where, compared)
    # The displacements alone: ccx prints beams, shells and plane elements at the integration
    # points of their 3D expansion and its reaction blocks include applied loads, so those blocks
    # can differ in layout or meaning where the solution itself agrees.
    displacements = {k: v for k, v in reference.items() if k[0] == "displacements"}
    u_worst, u_where, u_compared, u_missing = worst_difference(displacements, styk_blocks)
    if displacements and not u_missing and u_worst <= CLOSE:
        return name, "match-u" if u_worst <= MATCH else "close-u", "displacements %.1e (%d rows); %s" % (
            u_worst, u_compared, "missing " + missing[0] if missing else
            "%.1e at %s" % (worst, where))
    if missing:
        return name, "differs", "missing " + missing[0]
    return name, "differs", "%.1e (%s, %d rows)" % (worst, where, compared)


def select_decks(styk):
    listing = subprocess.run([styk, "elements"], capture_output=True, text=True, check=True).stdout
    known = {line.split()[0] for line in listing.splitlines()[1:] if line.strip()}
    selected, skipped = [], {}
    for entry in sorted(os.listdir(SUITE)):
        if not entry.endswith((".inp", ".inp.gz")):
            continue
        name = entry.split(".inp")[0]
        if not suite_file(name, ".dat.ref"):
            continue
        why = why_not_linear_static(read_text(os.path.join(SUITE, entry)), known)
        if why:
            skipped[why.split(" ")[0]] = skipped.get(why.split(" ")[0], 0) + 1
        else:
            selected.append((name, os.path.join(SUITE, entry)))
    return selected, skipped


def read_expectations(path):
    """{deck: (outcome, refusal message substring, cause)} from expected.tsv."""
    expected = {}
    with open(path) as f:
        for line in f:
            if line.strip() and not line.startswith("#"):
                name, outcome, message, cause = (line.rstrip("\n").split("\t") + ["", "", ""])[:4]
                expected[name] = (outcome, message, cause)
    return expected


def check_expectations(results, expected, path):
    unseen = dict(expected)
    failures = []
    for name, outcome, detail in results:
        want = unseen.pop(name, None)
        if want is None:
            failures.append("%s: %s (%s) is not in %s" % (name, outcome, detail, path))
        elif want[0] != outcome or (outcome == "refused" and want[1] not in detail):
            failures.append("%s: expected %s %s, got %s: %s" % (name, want[0], want[1], outcome, detail))
        elif outcome != "match" and not want[2]:
            failures.append("%s: %s without a cause in %s" % (name, outcome, path))
    failures += ["%s: expected in %s but not selected" % (n, path) for n in unseen]
    return failures


def write_table(results, expected, path):
    with open(path, "w") as f:
        f.write("| deck | outcome | measured | cause |\n|---|---|---|---|\n")
        for name, outcome, detail in results:
            cause = expected.get(name, ("", "", ""))[2]
            measured = "" if outcome == "refused" else detail
            f.write("| %s | %s | %s | %s |\n" % (name, outcome, measured.replace("|", "/"), cause))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--styk", required=True)
    parser.add_argument("--work", required=True)
    parser.add_argument("--expect")
    parser.add_argument("--table")
    parser.add_argument("--jobs", type=int, default=2)
    args = parser.parse_args()
    if not os.path.isdir(SUITE):
        sys.exit("the CalculiX test suite is not installed: apt-get install calculix-ccx-test "
                 "(scripts/install-deps.sh --test installs it)")
    styk = os.path.abspath(args.styk)
    selected, skipped = select_decks(styk)
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        results = sorted(pool.map(lambda d: run_deck(d[0], d[1], styk, args.work), selected))
    counts = {}
    for name, outcome, detail in results:
        counts[outcome] = counts.get(outcome, 0) + 1
        print("%-22s %-9s %s" % (name, outcome, detail))
    print("selected %d decks; %s; skipped: %s" % (
        len(results), ", ".join("%s %d" % kv for kv in sorted(counts.items())),
        ", ".join("%s %d" % kv for kv in sorted(skipped.items()))))
    expected = read_expectations(args.expect) if args.expect else {}
    if args.table:
        write_table(results, expected, args.table)
    if args.expect:
        failures = check_expectations(results, expected, args.expect)
        for failure in failures:
            print("FAIL " + failure)
        sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
