#!/usr/bin/python3
"""Every sample deck against the value samples/README.md states for it (samples/expected.tsv):
each deck of the manifest is solved with `styk solve`, the results file read with h5py (Debian's
python3-h5py, not Styk's reader), and each row's quantity compared with its expected value.

expected.tsv columns (tab-separated, '#' comments):
  deck       file name in samples/
  quantity   FIELD.COMPONENT of a node set: FIELD U, RF, UR, RM (COMPONENT 1..3), NT / EPOT
             (the scalar field) or RFL / RECUR (its reaction flow; COMPONENT 0), then '@SET' and a
             reduction: sum, mean, min, max, or node=ID (one node of the set by its user id);
             S.k@* (stress component k = 11, 22, 33, 12, 13, 23 as 1..6 at every integration
             point) and CPRESS.0@* (the contact pressure of every slave node) take no set;
             e.g. U.3@TIP:mean, RF.3@BOTTOM:sum, EPOT.0@C:min, CPRESS.0@*:max
  expected   the value README.md states
  tolerance  absolute, from the digits README.md prints (half a unit of the last one) or the
             stated accuracy
  source     where the value comes from (README.md text, SPEC section)
The last increment of the last step is read. Decks too long for the test suite are listed with
quantity '-' (run by `check_samples.py --all`; their rows are checked then too).
Usage: check_samples.py STYK WORKDIR MANIFEST [--all]"""
import os
import subprocess
import sys

import h5py
import numpy as np

SAMPLES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "samples")


def last_increment(h5):
    steps = sorted(h5["steps"], key=lambda s: int(s.split("_")[1]))
    step = h5["steps"][steps[-1]]
    return step[sorted(step, key=lambda s: int(s.split("_")[1]))[-1]]


def quantity(h5, text):
    field_part, rest = text.split("@")
    node_set, reduction = rest.split(":")
    field, component = field_part.split(".")
    increment = last_increment(h5)
    if field == "S":  # every integration point of the model (set '*')
        values = increment["S"][:][:, int(component) - 1]
    elif field == "CPRESS":  # the slave nodes of the model's contact pairs (set '*')
        values = increment["contact"]["pressure"][:]
    else:
        indices = h5["/model/sets/nodes/" + node_set][:]
        if field in ("NT", "EPOT"):
            values = increment["scalar"]["value"][:][indices]
        elif field in ("RFL", "RECUR"):
            values = increment["scalar"]["reaction"][:][indices]
        else:
            values = increment[field][:][indices, int(component) - 1]
    if reduction.startswith("node="):
        ids = h5["/model/nodes/ids"][:][indices]
        hits = np.nonzero(ids == int(reduction[5:]))[0]
        if len(hits) != 1:
            raise ValueError(f"node {reduction[5:]} is not in set {node_set}")
        return float(values[hits[0]])
    return float({"sum": np.sum, "mean": np.mean, "min": np.min, "max": np.max}[reduction](values))


def read_manifest(path):
    rows = []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            if not line.strip() or line.startswith("#"):
                continue
            fields = line.rstrip("\n").split("\t")
            if len(fields) != 5:
                raise SystemExit(f"{path}:{number}: expected 5 tab-separated columns")
            rows.append((number, *fields))
    return rows


def main():
    styk, work, manifest = sys.argv[1:4]
    run_all = "--all" in sys.argv[4:]
    os.makedirs(work, exist_ok=True)
    rows = read_manifest(manifest)
    listed = {row[1] for row in rows}
    decks = sorted(f for f in os.listdir(SAMPLES) if f.endswith(".inp"))
    failures = [f"{deck}: in samples/ but not in {os.path.basename(manifest)}"
                for deck in decks if deck not in listed]
    long_decks = {row[1] for row in rows if row[2] == "-"}
    solved = {}
    for number, deck, what, expected, tolerance, source in rows:
        if what == "-" or (deck in long_decks and not run_all):
            continue
        name = os.path.splitext(deck)[0]
        if deck not in solved:
            done = subprocess.run([styk, "solve", "-q", os.path.join(SAMPLES, deck), "-o", work],
                                  capture_output=True, text=True)
            solved[deck] = done.returncode == 0
            if not solved[deck]:
                failures.append(f"{deck}: styk solve exit {done.returncode}: {done.stderr[-400:]}")
        if not solved[deck]:
            continue
        try:
            with h5py.File(os.path.join(work, name + ".styk.h5"), "r") as h5:
                got = quantity(h5, what)
        except (KeyError, ValueError, IndexError) as e:
            failures.append(f"manifest line {number}: {deck} {what}: {e}")
            continue
        ok = abs(got - float(expected)) <= float(tolerance)
        print(f"{'ok  ' if ok else 'FAIL'} {deck} {what} = {got:.6g} (expected {expected} "
              f"+- {tolerance}; {source})")
        if not ok:
            failures.append(f"manifest line {number}: {deck} {what} = {got:.6g}, expected "
                            f"{expected} +- {tolerance}")
    for failure in failures:
        print("FAIL " + failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
