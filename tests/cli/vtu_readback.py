#!/usr/bin/python3
"""VTU output read back by independent readers (docs/results.md "VTU"): each deck is solved with
`styk solve`, exported with `styk export --vtu`, and the .vtu read by meshio (Debian's
python3-meshio), the results file by h5py (python3-h5py); none of Styk's own readers takes part.
Asserted, exactly (the VTU carries float64 and int64 in base64, so nothing may change):
  - the points are /model/nodes/coordinates;
  - one cell per element, in the model's order (cell data element_id = /model/elements/ids), each
    cell made of nodes of its element (the first k of its connectivity, k the cell's node count);
  - U (and UR, NT where the model has them) are the last increment's datasets.
Usage: vtu_readback.py STYK WORKDIR DECK...   (exit 0 when every deck passes)."""
import os
import subprocess
import sys

import h5py
import meshio
import numpy as np


def run(args):
    done = subprocess.run(args, capture_output=True, text=True)
    if done.returncode != 0:
        raise AssertionError(f"{' '.join(args)}: exit {done.returncode}\n{done.stderr}")


def last_increment(h5):
    steps = sorted(h5["steps"], key=lambda s: int(s.split("_")[1]))
    step = h5["steps"][steps[-1]]
    increments = sorted(step, key=lambda s: int(s.split("_")[1]))
    return step[increments[-1]]


def check(styk, work, deck):
    name = os.path.splitext(os.path.basename(deck))[0]
    run([styk, "solve", "-q", deck, "-o", work])
    results = os.path.join(work, name + ".styk.h5")
    vtu = os.path.join(work, name + ".vtu")
    run([styk, "export", results, "--vtu", "-o", vtu])
    mesh = meshio.read(vtu)
    with h5py.File(results, "r") as h5:
        xyz = h5["/model/nodes/coordinates"][:]
        ids = h5["/model/elements/ids"][:]
        connectivity = h5["/model/elements/connectivity"][:]
        offsets = h5["/model/elements/offsets"][:]
        increment = last_increment(h5)
        fields = {key: increment[key][:] for key in ("U", "UR")
                  if key in increment and increment[key].size > 0}
        if "scalar" in increment and "value" in increment["scalar"]:
            fields["NT"] = increment["scalar"]["value"][:]
    assert np.array_equal(mesh.points, xyz), f"{name}: points differ from the nodes"
    cells = [c for block in mesh.cells for c in block.data]
    assert len(cells) == len(ids), f"{name}: {len(cells)} cells for {len(ids)} elements"
    element_ids = np.concatenate([np.ravel(b) for b in mesh.cell_data["element_id"]])
    assert np.array_equal(element_ids, ids), f"{name}: cells out of the model's element order"
    for e, cell in enumerate(cells):
        own = set(connectivity[offsets[e]:offsets[e + 1]][:len(cell)])
        assert set(cell) <= own, f"{name}: cell {e} (element {ids[e]}) uses foreign nodes"
    for key, value in fields.items():
        assert key in mesh.point_data, f"{name}: the VTU lacks {key}"
        got = np.asarray(mesh.point_data[key]).reshape(value.shape)
        assert np.array_equal(got, value), f"{name}: {key} differs from the results file"
    print(f"{name}: {len(xyz)} points, {len(cells)} cells, fields {sorted(fields)}: identical")


def main():
    styk, work, decks = sys.argv[1], sys.argv[2], sys.argv[3:]
    os.makedirs(work, exist_ok=True)
    failures = 0
    for deck in decks:
        try:
            check(styk, work, deck)
        except AssertionError as e:
            print(f"FAIL {e}")
            failures += 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
