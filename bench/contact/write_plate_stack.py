#!/usr/bin/env python3
"""Writes a flat frictional joint with many contact nodes: a clamp plate pressed onto a base plate
(C3D8 or C3D20, matching meshes), the scale case of the sparse contact solve (bench/contact/README.md,
"Thousands of closed contact nodes").

Base plate [0, L]^2 x [-t, 0], bottom fixed; clamp plate [0, L]^2 x [0, t], its top face held in
x and y. Step CLAMP presses the top with --pressure; step SHIFT moves the top face by --shift in x,
enough for the plate's rim to slip (friction --mu). Slave: the clamp plate's bottom (S1), master:
the base plate's top (S2). --n elements per side give (n + 1)^2 slave nodes with C3D8 (n = 141:
20 164, all closed under the pressure) and 3 n^2 + 4 n + 1 with C3D20 (whose face corners open
under a uniform pressure: their consistent loads pull).

  write_plate_stack.py --n 141 -o plates.inp
"""
import argparse


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=141, help="elements per side")
    parser.add_argument("--element", choices=("C3D8", "C3D20"), default="C3D8")
    parser.add_argument("--layers", type=int, default=2, help="element layers per plate")
    parser.add_argument("--size", type=float, default=100.0, help="plate side L (mm)")
    parser.add_argument("--thickness", type=float, default=4.0, help="plate thickness t (mm)")
    parser.add_argument("--pressure", type=float, default=10.0, help="clamping pressure (MPa)")
    parser.add_argument("--shift", type=float, default=2e-4, help="top face shift in x (mm)")
    parser.add_argument("--mu", type=float, default=0.2, help="friction coefficient")
    parser.add_argument("-o", "--output", required=True)
    args = parser.parse_args()
    n, layers = args.n, args.layers
    h, dz = args.size / n, args.thickness / layers
    m = 2 * n + 1  # half-spacing grid points per side
    ids = {}

    def node_id(plate, i, j, k):
        return ids[(plate, i, j, k)]

    lines = ["*HEADING", f"Clamp plate on base plate, C3D20, {n} x {n} x {layers} per plate, "
             f"mu = {args.mu}, p = {args.pressure} (bench/contact/write_plate_stack.py)", "*NODE"]
    for plate, z0 in ((0, -args.thickness), (1, 0.0)):
        for k in range(2 * layers + 1):
            for j in range(m):
                for i in range(m):
                    odd = (i % 2) + (j % 2) + (k % 2)
                    if odd > 1 or (odd == 1 and args.element == "C3D8"):
                        continue  # serendipity: no face or body centres; C3D8: corners only
                    ids[(plate, i, j, k)] = len(ids) + 1
                    lines.append(f"{len(ids)}, {i * h / 2:.9g}, {j * h / 2:.9g}, "
                                 f"{z0 + k * dz / 2:.9g}")
    corners = [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0), (0, 0, 2), (2, 0, 2), (2, 2, 2), (0, 2, 2)]
    mids = [(1, 0, 0), (2, 1, 0), (1, 2, 0), (0, 1, 0), (1, 0, 2), (2, 1, 2), (1, 2, 2), (0, 1, 2),
            (0, 0, 1), (2, 0, 1), (2, 2, 1), (0, 2, 1)]
    elements = {0: [], 1: []}
    bottom, top = [], []  # (element, plate) of the faces S1 / S2 on z = -t.. or the interface
    eid = 0
    for plate in (0, 1):
        lines.append(f"*ELEMENT, TYPE={args.element}, ELSET={'BASE' if plate == 0 else 'CLAMP'}")
        for k in range(layers):
            for j in range(n):
                for i in range(n):
                    eid += 1
                    conn = [node_id(plate, 2 * i + a, 2 * j + b, 2 * k + c)
                            for a, b, c in corners + (mids if args.element == "C3D20" else [])]
                    if len(conn) > 15:
                        lines.append(f"{eid}, " + ", ".join(map(str, conn[:15])) + ",")
                        lines.append(", ".join(map(str, conn[15:])))
                    else:
                        lines.append(f"{eid}, " + ", ".join(map(str, conn)))
                    elements[plate].append((eid, k))
    lines += ["*NSET, NSET=BASE_BOTTOM"]
    face = [(i, j) for j in range(m) for i in range(m) if (0, i, j, 0) in ids]
    lines += chunk([node_id(0, i, j, 0) for i, j in face])
    lines += ["*NSET, NSET=CLAMP_TOP"]
    lines += chunk([node_id(1, i, j, 2 * layers) for i, j in face])
    lines += ["*SURFACE, NAME=BASE_TOP, TYPE=ELEMENT"]
    lines += [f"{e}, S2" for e, k in elements[0] if k == layers - 1]
    lines += ["*SURFACE, NAME=CLAMP_BOTTOM, TYPE=ELEMENT"]
    lines += [f"{e}, S1" for e, k in elements[1] if k == 0]
    lines += ["*MATERIAL, NAME=STEEL", "*ELASTIC", "210000, 0.3",
              "*SOLID SECTION, ELSET=BASE, MATERIAL=STEEL",
              "*SOLID SECTION, ELSET=CLAMP, MATERIAL=STEEL",
              "*SURFACE INTERACTION, NAME=FACES", "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD",
              "*FRICTION", f"{args.mu}",
              "*CONTACT PAIR, INTERACTION=FACES, TYPE=NODE TO SURFACE", "CLAMP_BOTTOM, BASE_TOP",
              "*BOUNDARY", "BASE_BOTTOM, 1, 3", "CLAMP_TOP, 1, 2",
              "*STEP, NAME=CLAMP", "*STATIC", "*DLOAD"]
    lines += [f"{e}, P2, {args.pressure}" for e, k in elements[1] if k == layers - 1]
    lines += ["*END STEP", "*STEP, NAME=SHIFT", "*STATIC", "*BOUNDARY",
              f"CLAMP_TOP, 1, 1, {args.shift}", "*END STEP"]
    with open(args.output, "w") as out:
        out.write("\n".join(lines) + "\n")
    print(f"{args.output}: {len(ids)} nodes, {eid} {args.element}, {len(face)} slave nodes")


def chunk(values, width=16):
    return [", ".join(map(str, values[i:i + width])) + ("," if i + width < len(values) else "")
            for i in range(0, len(values), width)]


if __name__ == "__main__":
    main()
