#!/usr/bin/env python3
"""The flat frictional joint of write_plate_stack.py at several sizes, solved with the dense and
the sparse contact solve side by side (bench/contact/README.md, "Thousands of closed contact
nodes"). Prints a Markdown table: slave nodes, path, exit code, wall time, peak resident memory,
phase times, Newton iterations, sparse LU factorisations and the final stick / slip counts.

Usage: bench/contact/run_plate_stack.py STYK [--n 50 70 141] [--paths dense sparse] [--work DIR]
A path whose dense compliance would not fit (8 (3 nodes)^2 bytes beyond --dense-limit-gb) is
skipped for that size. Run it on an otherwise idle machine.
"""
import argparse
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from run_model_b_torque import run  # noqa: E402


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("styk")
    parser.add_argument("--n", type=int, nargs="+", default=[50, 70, 141])
    parser.add_argument("--paths", nargs="+", default=["dense", "sparse"])
    parser.add_argument("--dense-limit-gb", type=float, default=4.0)
    parser.add_argument("--work", default="bench-plate-stack")
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    print("| elements per side | slave nodes | path | exit | wall s | peak GB | "
          "assemble+order+factorise s | compliance s | contact iterations s | "
          "iterations | LU factorisations | stick / slip at the end |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for n in args.n:
        deck = os.path.join(args.work, "plates_%d.inp" % n)
        subprocess.run([sys.executable, os.path.join(HERE, "write_plate_stack.py"), "--n", str(n),
                        "-o", deck], check=True, stdout=subprocess.DEVNULL)
        nodes = (n + 1) ** 2
        for path in args.paths:
            if path == "dense" and 8.0 * (3 * nodes) ** 2 > args.dense_limit_gb * 1e9:
                continue
            r = run(args.styk, deck, args.work, ("--contact-solver", path))
            log = r["log"]
            factorisations = re.findall(r"sparse contact solve, (\d+) LU factorisations", log)
            final = re.findall(r"iteration \d+: (\d+) stick, (\d+) slip", log)
            print("| %d | %d | %s | %d | %.1f | %.2f | %.1f | %.1f | %.1f | %d | %s | %s |" %
                  (n, nodes, path, r["exit"], r["wall"], r["rss_gb"], r["setup"],
                   r["compliance"], r["iterations_s"], r["iterations"],
                   factorisations[-1] if factorisations else "-",
                   "%s / %s" % final[-1] if final else "-"), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
