#!/usr/bin/env python3
"""Styk on 1 and on N MPI ranks against CalculiX, on one C3D20 cantilever deck (bench/README.md).

The deck is PERFORMANCE.md's cantilever (`make_cantilever NX NY NZ`), written once and solved, one
after the other, by
  styk solve DECK --threads C              (serial, every core C of the machine)
  styk solve DECK --ranks N                (N ranks, C / N threads each; --threads 0)
  ccx -i DECK                              (OMP_NUM_THREADS = C; skipped with --no-ccx)
Each run's wall time, peak memory summed over its processes (sampled from /proc every 0.1 s, so
the ranks count together), mean tip deflection and Styk's phase split (from rank 0's progress
lines) are printed as Markdown tables and written to OUT/ranks-comparison.csv.

Usage: bench/run_ranks_comparison.py [--size 100x12x12] [--ranks 2] [--solver auto]
       [--build build] [--out bench/out] [--no-ccx]
Run it niced (`nice -n 19`) on an otherwise idle machine: the figures that matter are the ratios.
"""
import argparse
import csv
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_cantilever_series import mean_tip_uz, styk_phases  # noqa: E402


def descendants(pid):
    """pid and every process below it, from /proc."""
    children = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as f:
                fields = f.read().rsplit(")", 1)[1].split()
            children.setdefault(int(fields[1]), []).append(int(entry))
        except OSError:
            continue
    found, stack = [], [pid]
    while stack:
        p = stack.pop()
        found.append(p)
        stack.extend(children.get(p, []))
    return found


def rss_mb(pids):
    total = 0
    for p in pids:
        try:
            with open(f"/proc/{p}/status") as f:
                for line in f:
                    if line.startswith("VmRSS:"):
                        total += int(line.split()[1])
        except OSError:
            continue
    return total / 1024.0


def run_measured(cmd, cwd, env=None):
    """(exit code, wall s, peak summed RSS MB, stderr)."""
    start = time.monotonic()
    err_path = os.path.join(cwd, "stderr.txt")
    with open(err_path, "w") as err:
        proc = subprocess.Popen(cmd, cwd=cwd, env=env, stdout=subprocess.DEVNULL, stderr=err)
        peak = 0.0
        while proc.poll() is None:
            peak = max(peak, rss_mb(descendants(proc.pid)))
            time.sleep(0.1)
    wall = time.monotonic() - start
    with open(err_path) as f:
        text = f.read()
    return proc.returncode, wall, peak, text


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--size", default="100x12x12")
    ap.add_argument("--ranks", type=int, default=2)
    ap.add_argument("--solver", default="auto")
    ap.add_argument("--build", default="build")
    ap.add_argument("--out", default="bench/out")
    ap.add_argument("--no-ccx", action="store_true")
    args = ap.parse_args()

    cores = os.cpu_count() or 1
    nx, ny, nz = args.size.split("x")
    job = f"cantilever_{args.size}"
    work = os.path.abspath(os.path.join(args.out, "ranks-" + job))
    os.makedirs(work, exist_ok=True)
    make = os.path.abspath(os.path.join(args.build, "bench", "make_cantilever"))
    styk = os.path.abspath(os.path.join(args.build, "cli", "styk"))
    gen = subprocess.run([make, nx, ny, nz, f"{job}.inp"], cwd=work, stderr=subprocess.PIPE,
                         text=True, check=True)
    dofs = int(re.search(r"(\d+) dofs", gen.stderr).group(1))

    runs = [("styk 1 rank", [styk, "solve", f"{job}.inp", "-o", "serial", "--solver", args.solver,
                             "--threads", str(cores)], "serial"),
            (f"styk {args.ranks} ranks", [styk, "solve", f"{job}.inp", "-o", "ranks", "--solver",
                                          args.solver, "--ranks", str(args.ranks)], "ranks")]
    rows = []
    for name, cmd, out in runs:
        code, wall, peak, err = run_measured(cmd, work)
        if code != 0:
            print(err, file=sys.stderr)
            sys.exit(f"{name} failed")
        phases = styk_phases(err)
        solver = re.search(r"(MUMPS|CG \+ GAMG|CHOLMOD)[^\n]*", err)
        rows.append({"run": name, "dofs": dofs, "wall_s": round(wall, 2), "peak_mb": round(peak),
                     "tip_uz": mean_tip_uz(os.path.join(work, out, f"{job}.dat")),
                     **{f"{p}_s": round(phases.get(p, 0.0), 2) for p in
                        ("read", "check", "pattern", "assemble", "order", "factorise", "solve",
                         "recover", "write")},
                     "solver": solver.group(0) if solver else ""})
        print(rows[-1], file=sys.stderr)
    if not args.no_ccx:
        env = dict(os.environ, OMP_NUM_THREADS=str(cores))
        code, wall, peak, _ = run_measured(["ccx", "-i", job], work, env)
        rows.append({"run": "ccx", "dofs": dofs, "wall_s": round(wall, 2), "peak_mb": round(peak),
                     "tip_uz": mean_tip_uz(os.path.join(work, f"{job}.dat")) if code == 0
                     else float("nan")})
        print(rows[-1], file=sys.stderr)

    fields = list(rows[0].keys())
    with open(os.path.join(args.out, f"ranks-comparison-{args.size}.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
        w.writeheader()
        w.writerows(rows)
    base = rows[0]
    print("| run | DOF | wall | peak memory (all processes) | serial/this wall | tip uz |")
    print("|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['run']} | {r['dofs']} | {r['wall_s']:.2f} s | {r['peak_mb']} MB | "
              f"{base['wall_s'] / r['wall_s']:.2f} | {r['tip_uz']:.6e} |")
    print()
    print("| run | read | check | pattern | assemble | factorise | solve | recover | write | solver |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        if "read_s" not in r:
            continue
        print(f"| {r['run']} | {r['read_s']:.2f} | {r['check_s']:.2f} | {r['pattern_s']:.2f} | "
              f"{r['assemble_s']:.2f} | {r['factorise_s']:.2f} | {r['solve_s']:.2f} | "
              f"{r['recover_s']:.2f} | {r['write_s']:.2f} | {r['solver']} |")
    subprocess.run(["rm", "-rf", work])


if __name__ == "__main__":
    main()
