#!/usr/bin/env python3
"""C3D20 cantilever scale series, Styk side by side with CalculiX (ccx) on the same decks.

The model is PERFORMANCE.md's: a 10 x 1 x 1 block, E = 210 000, nu = 0.3, clamped at x = 0, unit
tip shear as consistent nodal forces on x = 10. For every size the deck is written once by
`make_cantilever`, solved by `styk solve` and (up to --ccx-max-dofs) by `ccx`, each under
`/usr/bin/time -v`. Recorded: wall time, peak memory, mean tip deflection uz, and Styk's time
split (read, assemble, factorise/solve, recover, write) from its progress lines.

With --type C3D10 or C3D4 the bricks are split into 6 tetrahedra each (`make_tet_cantilever`,
mesher/split.hpp) and the tip shear is the consistent load of a uniform traction on their faces.

Usage: bench/run_cantilever_series.py [--sizes 36x4x4,56x8x8,...] [--ccx-max-dofs N]
       [--build build] [--out bench/out] [--solver auto|cholmod|iterative]
       [--type C3D20|C3D10|C3D4]
Prints a Markdown table and writes OUT/cantilever-series.csv.
"""
import argparse
import csv
import os
import re
import subprocess
import sys

DEFAULT_SIZES = "36x4x4,56x8x8,100x12x12,140x16x16,200x20x20"


def time_v(cmd, cwd, env=None):
    """Runs cmd under /usr/bin/time -v; returns (exit code, wall s, peak MB, stderr text)."""
    proc = subprocess.run(["/usr/bin/time", "-v"] + cmd, cwd=cwd, env=env,
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    err = proc.stderr
    wall = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): (\S+)", err).group(1)
    parts = [float(p) for p in wall.split(":")]
    seconds = sum(p * 60 ** i for i, p in enumerate(reversed(parts)))
    peak_kb = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", err).group(1))
    return proc.returncode, seconds, peak_kb / 1024.0, err


def mean_tip_uz(dat_path):
    """Mean uz of the last 'displacements ... for set TIP' block of a .dat file."""
    values, current = None, None
    with open(dat_path) as f:
        for line in f:
            if "displacements" in line and "set TIP" in line:
                current = []
                values = current
                continue
            if current is not None:
                fields = line.split()
                if len(fields) == 4:
                    current.append(float(fields[3].replace("D", "E")))
                elif fields and current:
                    current = None
    return sum(values) / len(values) if values else float("nan")


def styk_phases(stderr_text):
    phases = {}
    for name, seconds in re.findall(r"styk: (\w[\w ]*?) done in ([0-9.]+) s", stderr_text):
        phases[name] = phases.get(name, 0.0) + float(seconds)
    return phases


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sizes", default=DEFAULT_SIZES)
    ap.add_argument("--ccx-max-dofs", type=int, default=250000,
                    help="run ccx only up to this many DOFs (ccx needs 13 GB at 471k, fails at 1M)")
    ap.add_argument("--build", default="build")
    ap.add_argument("--out", default="bench/out")
    ap.add_argument("--solver", default="auto")
    ap.add_argument("--type", default="C3D20", choices=["C3D20", "C3D10", "C3D4"])
    args = ap.parse_args()

    os.makedirs(args.out, exist_ok=True)
    tets = args.type != "C3D20"
    make = os.path.abspath(os.path.join(args.build, "bench",
                                        "make_tet_cantilever" if tets else "make_cantilever"))
    styk = os.path.abspath(os.path.join(args.build, "cli", "styk"))
    rows = []
    for size in args.sizes.split(","):
        nx, ny, nz = size.split("x")
        job = f"cantilever_{args.type}_{size}"
        work = os.path.abspath(os.path.join(args.out, job))
        os.makedirs(work, exist_ok=True)
        gen = subprocess.run([make, nx, ny, nz, f"{job}.inp"] + (["--type", args.type] if tets else []),
                             cwd=work, stderr=subprocess.PIPE, text=True, check=True)
        dofs_total = int(re.search(r"(\d+) dofs", gen.stderr).group(1))
        code, wall, peak, err = time_v([styk, "solve", f"{job}.inp", "-o", "styk",
                                        "--solver", args.solver], work)
        if code != 0:
            print(err, file=sys.stderr)
            sys.exit(f"styk failed on {job}")
        phases = styk_phases(err)
        solver_line = re.search(r"styk:\s+(.*(?:CHOLMOD|GAMG|CG).*)", err)
        row = {
            "mesh": size, "dofs": dofs_total,
            "styk_wall_s": round(wall, 2), "styk_peak_mb": round(peak),
            "styk_tip_uz": mean_tip_uz(os.path.join(work, "styk", f"{job}.dat")),
            "read_s": phases.get("read", 0.0), "assemble_s": phases.get("assemble", 0.0),
            "order_s": phases.get("order", 0.0), "factorise_s": phases.get("factorise", 0.0),
            "solve_s": phases.get("solve", 0.0), "recover_s": phases.get("recover", 0.0),
            "write_s": phases.get("write", 0.0),
            "solver": solver_line.group(1) if solver_line else "",
        }
        if dofs_total <= args.ccx_max_dofs:
            env = dict(os.environ, OMP_NUM_THREADS=str(os.cpu_count()))
            code, wall, peak, err = time_v(["ccx", "-i", job], work, env)
            row.update({"ccx_wall_s": round(wall, 2), "ccx_peak_mb": round(peak),
                        "ccx_tip_uz": mean_tip_uz(os.path.join(work, f"{job}.dat")) if code == 0 else float("nan")})
        rows.append(row)
        print(f"{size}: {row}", file=sys.stderr)
        # The decks and outputs of the large cases are gigabytes: keep only the numbers.
        subprocess.run(["rm", "-rf", work])

    fields = sorted({k for r in rows for k in r}, key=lambda k: list(rows[-1].keys()).index(k)
                    if k in rows[-1] else 99)
    with open(os.path.join(args.out, f"cantilever-series-{args.type}.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        w.writerows(rows)

    print("| mesh | DOF | styk wall | styk peak | ccx wall | ccx peak | wall ratio ccx/styk | memory ratio ccx/styk | styk tip uz | ccx tip uz | outside factorise+solve |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        inner = r["order_s"] + r["factorise_s"] + r["solve_s"]
        outside = 100.0 * (r["styk_wall_s"] - inner) / r["styk_wall_s"]
        ccx_wall = r.get("ccx_wall_s")
        ccx_peak = r.get("ccx_peak_mb")
        ratio_t = f"{ccx_wall / r['styk_wall_s']:.1f}" if ccx_wall else "-"
        ratio_m = f"{ccx_peak / r['styk_peak_mb']:.1f}" if ccx_peak else "-"
        print(f"| {r['mesh']} | {r['dofs']} | {r['styk_wall_s']:.2f} s | {r['styk_peak_mb']} MB | "
              f"{(str(ccx_wall) + ' s') if ccx_wall else '-'} | {(str(ccx_peak) + ' MB') if ccx_peak else '-'} | "
              f"{ratio_t} | {ratio_m} | {r['styk_tip_uz']:.6e} | "
              f"{r.get('ccx_tip_uz', float('nan')):.6e} | {outside:.0f} % |")
    print()
    print("| mesh | read | assemble | order | factorise | solve | recover | write | solver |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['mesh']} | {r['read_s']:.2f} | {r['assemble_s']:.2f} | {r['order_s']:.2f} | "
              f"{r['factorise_s']:.2f} | {r['solve_s']:.2f} | {r['recover_s']:.2f} | {r['write_s']:.2f} | {r['solver']} |")


if __name__ == "__main__":
    main()
