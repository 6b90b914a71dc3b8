#!/usr/bin/env python3
"""SPEC 4.2 model B (full 360 degrees, builder default density) turned by a torque up to a given
fraction of its friction capacity, timed with one or more `styk` binaries (bench/contact/README.md).

The deck is `styk mesh shrink-fit --model B` (FIT: heating, TORQUE1: 300 Nm, TORQUE2: 850 Nm) with
TORQUE2's force couples scaled so the step ends at FRACTION x the all-slip capacity (571.35 Nm,
bench/contact/README.md): the run then ends converged, and its wall time is "torque to FRACTION of
the capacity". Each binary solves the same deck in turn; the script prints a Markdown table: wall
time, peak resident memory, the phase times (assembly + ordering + factorisation, contact
compliance, contact iterations, recovery), increments, iterations and how many iterations were
solved by refining the previous factor.

Usage: bench/contact/run_model_b_torque.py STYK [STYK ...] [--fraction 0.95] [--work DIR]
Run it on an otherwise idle machine: the two cores are what the dense kernels use.
"""
import argparse
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from run_cantilever_series import styk_phases  # noqa: E402

CAPACITY_NM = 571.35  # all-slip capacity of the builder's model B (bench/contact/README.md)
TORQUE2_NM = 850.0  # the builder's TORQUE2 step


def write_deck(styk, work, fraction):
    base = os.path.join(work, "model_b.inp")
    subprocess.run([styk, "mesh", "shrink-fit", "--model", "B", "-o", base], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    factor = fraction * CAPACITY_NM / TORQUE2_NM
    out, step, scaling = [], "", False
    with open(base) as f:
        for line in f.read().split("\n"):
            upper = line.upper()
            if upper.startswith("*STEP"):
                step = upper
            if upper.startswith("*"):
                scaling = upper.startswith("*CLOAD") and "TORQUE2" in step
            elif scaling and line.strip():
                node, dof, value = line.split(",")
                line = "%s,%s, %.17g" % (node, dof, float(value) * factor)
            out.append(line)
    deck = os.path.join(work, "model_b_%g.inp" % fraction)
    with open(deck, "w") as f:
        f.write("\n".join(out))
    return deck


def run(styk, deck, work, extra=()):
    """Solves `deck` with `styk solve ... extra`; wall time, peak memory and the log's counts."""
    start = time.monotonic()
    proc = subprocess.run(["/usr/bin/time", "-f", "maxrss %M", styk, "solve", deck, "-o", work,
                           *extra], stderr=subprocess.PIPE, stdout=subprocess.DEVNULL, text=True)
    wall = time.monotonic() - start
    log = proc.stderr
    phases = styk_phases(log)
    converged = re.findall(r"converged in (\d+) iterations", log)
    return {
        "exit": proc.returncode,
        "wall": wall,
        "rss_gb": int(re.search(r"maxrss (\d+)", log).group(1)) / 1e6,
        "setup": sum(phases.get(k, 0.0) for k in ("assemble", "order", "factorise")),
        "compliance": phases.get("contact compliance", 0.0),
        "iterations_s": phases.get("contact iteration", 0.0),
        "recover": phases.get("recover", 0.0),
        "increments": len(converged),
        "iterations": len(re.findall(r": iteration \d+:", log)),
        "refined": log.count("previous factor refined"),
        "failed": log.count("did not converge"),
        "log": log,
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("styk", nargs="+")
    parser.add_argument("--fraction", type=float, default=0.95)
    parser.add_argument("--work", default="bench-model-b")
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    deck = write_deck(args.styk[0], args.work, args.fraction)
    print("| styk | exit | wall s | peak GB | assemble+order+factorise s | compliance s | "
          "contact iterations s | recover s | increments (failed) | iterations (refined) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for styk in args.styk:
        r = run(styk, deck, args.work)
        print("| %s | %d | %.1f | %.2f | %.1f | %.1f | %.1f | %.1f | %d (%d) | %d (%d) |" %
              (styk, r["exit"], r["wall"], r["rss_gb"], r["setup"], r["compliance"],
               r["iterations_s"], r["recover"], r["increments"], r["failed"], r["iterations"],
               r["refined"]), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
