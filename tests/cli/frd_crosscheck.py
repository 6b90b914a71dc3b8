"""The .frd output of `styk solve` against ccx's own .frd of the same deck, read by an independent
reader (frd_reader.py), and `styk export --frd` against the .frd `styk solve` wrote
(docs/results.md, "The .frd file").

Usage: frd_crosscheck.py STYK WORKDIR SOURCE_DIR

Compared field by field: the nodes, the elements (the .frd element type and node order ccx writes),
and every result block of every step (the same blocks, the same nodes, each value within
TOLERANCE times the block's largest value: the .frd prints six significant digits, E12.5, so two
equal numbers may differ by one unit of the sixth digit after rounding).
A Gmsh cantilever (gmsh -> styk import -> *INCLUDE) is solved too: its tip deflection against
Timoshenko beam theory (BEAM_TOLERANCE: 1e-3; measured 2.7e-4 with h = 0.5) and its .frd against ccx's."""
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from frd_reader import read_frd  # noqa: E402

TOLERANCE = 1e-5
# ccx solves a heat step by Newton iterations to its residual tolerance: its nodal fluxes carry
# that error (transverse components of 5e-4 where the exact flux has none, 4e-5 of the largest
# value along the flow in heat_c3d8), its temperatures agree to the print precision.
HEAT_FLUX_TOLERANCE = 1e-4
# The Gmsh cantilever (2958 dofs): the two solutions differ by 5e-7 of the largest displacement
# (measured; the small decks agree to the print precision), which the nodal strains show as up to
# 1.04e-5 of their largest value: its stresses and strains are compared to 3e-5.
LARGER_MODEL_TOLERANCE = {"gmsh_cantilever": 3e-5}
BEAM_TOLERANCE = 1e-3
# Nodal stresses and strains of wedges are not compared: their integration-point values agree with
# ccx's to the .dat's seven digits, but the recovery to the nodes differs. Styk fits the point
# values by least squares in the first space they determine (docs/results.md: the 2-point C3D6 rule
# determines only a constant, the 9-point C3D15 rule a linear field), ccx extrapolates through the
# thickness.
RECOVERY_DIFFERS = {"beam_c3d6": ("STRESS", "TOSTRAIN"), "beam_c3d15": ("STRESS", "TOSTRAIN")}
FILE_REQUESTS = "*NODE FILE\nU, RF\n*EL FILE\nS, E\n"

failures = []


def fail(message):
    failures.append(message)
    print("FAIL " + message)


def run(command, cwd):
    result = subprocess.run(command, cwd=cwd, shell=True, capture_output=True, text=True)
    if result.returncode != 0:
        raise SystemExit("command failed (%d): %s\n%s\n%s"
                         % (result.returncode, command, result.stdout, result.stderr))
    return result


def with_file_requests(deck_text):
    """Adds *NODE FILE U, RF and *EL FILE S, E to every step (before its *END STEP)."""
    return deck_text.replace("*END STEP", FILE_REQUESTS + "*END STEP")


def compare_mesh(case, ours, theirs):
    if sorted(ours.nodes) != sorted(theirs.nodes):
        fail("%s: node ids differ" % case)
        return
    scale = max(abs(c) for x in theirs.nodes.values() for c in x) or 1.0
    worst = max(abs(a - b) for n in ours.nodes for a, b in zip(ours.nodes[n], theirs.nodes[n]))
    if worst > TOLERANCE * scale:
        fail("%s: node coordinates differ by %.3g" % (case, worst))
    if ours.elements != theirs.elements:
        differing = [e for e in theirs.elements if ours.elements.get(e) != theirs.elements[e]]
        fail("%s: elements differ (type or node order), e.g. %s: styk %s, ccx %s"
             % (case, differing[:1], ours.elements.get(differing[0]) if differing else None,
                theirs.elements.get(differing[0]) if differing else None))


def blocks_by_key(frd):
    return {(b.step, b.name): b for b in frd.blocks}


def compare_block(case, ours, theirs, nodes=None, tolerance=TOLERANCE):
    """Largest difference relative to the block's largest value; fails above `tolerance`."""
    keys = sorted(theirs.values) if nodes is None else nodes
    if nodes is None and sorted(ours.values) != keys:
        fail("%s: step %d %s: styk writes %d nodes, ccx %d"
             % (case, theirs.step, theirs.name, len(ours.values), len(theirs.values)))
        return None
    scale = max(abs(v) for n in keys for v in theirs.values[n]) or 1.0
    worst = max(abs(a - b) for n in keys for a, b in zip(ours.values[n], theirs.values[n]))
    relative = worst / scale
    if relative > tolerance:
        fail("%s: step %d %s differs by %.3g of its largest value %.6g"
             % (case, theirs.step, theirs.name, relative, scale))
    return relative


def compare_with_ccx(case, ours, theirs, force_nodes):
    compare_mesh(case, ours, theirs)
    mine = blocks_by_key(ours)
    # ccx's ERROR block (its error estimator, which *EL FILE S brings) is not written by Styk.
    peer = {k: b for k, b in blocks_by_key(theirs).items() if k[1] != "ERROR"}
    if sorted(mine) != sorted(peer):
        fail("%s: blocks differ: styk %s, ccx %s" % (case, sorted(mine), sorted(peer)))
    summary = []
    for key in sorted(peer):
        if key not in mine:
            continue
        # FORC: ccx writes the internal force, which is the applied load at free loaded nodes;
        # Styk's RF is the reaction at constrained dofs: compared at the constrained nodes.
        nodes = force_nodes if key[1] == "FORC" else None
        if key[1] in RECOVERY_DIFFERS.get(case, ()):
            summary.append("%s/%d not compared (recovery)" % (key[1], key[0]))
            continue
        tolerance = HEAT_FLUX_TOLERANCE if key[1] == "FLUX" else LARGER_MODEL_TOLERANCE.get(case, TOLERANCE)
        relative = compare_block(case, mine[key], peer[key], nodes, tolerance)
        if relative is not None:
            summary.append("%s/%d %.1e" % (key[1], key[0], relative))
    print("%-22s %s" % (case, ", ".join(summary)))


def solve_pair(case, job, deck_text, force_nodes):
    workdir = os.path.join(WORK, case)
    shutil.rmtree(workdir, ignore_errors=True)
    os.makedirs(workdir)
    ccx_dir = os.path.join(workdir, "ccx")
    os.makedirs(ccx_dir)
    for d in (workdir, ccx_dir):
        with open(os.path.join(d, job + ".inp"), "w") as f:
            f.write(deck_text)
    for extra in EXTRA_FILES.get(case, []):
        shutil.copy(os.path.join(workdir, "..", extra), workdir)
        shutil.copy(os.path.join(workdir, "..", extra), ccx_dir)
    run("%s solve %s.inp -q" % (STYK, job), workdir)
    run("OMP_NUM_THREADS=1 ccx -i %s" % job, ccx_dir)
    ours = read_frd(os.path.join(workdir, job + ".frd"))
    theirs = read_frd(os.path.join(ccx_dir, job + ".frd"))
    compare_with_ccx(case, ours, theirs, force_nodes)
    check_export(case, workdir, job, ours)
    return workdir, ours, theirs


def check_export(case, workdir, job, solved):
    """`styk export --frd` of the results file holds every block the solve wrote, equal."""
    run("%s export %s.styk.h5 --frd -o exported.frd" % (STYK, job), workdir)
    exported = read_frd(os.path.join(workdir, "exported.frd"))
    if exported.nodes != solved.nodes or exported.elements != solved.elements:
        fail("%s: export --frd: the mesh differs from the solve's .frd" % case)
    everything = blocks_by_key(exported)
    for key, block in blocks_by_key(solved).items():
        other = everything.get(key)
        if other is None:
            fail("%s: export --frd lacks step %d %s" % (case, key[0], key[1]))
        elif any(other.values[n] != v for n, v in block.values.items()):
            fail("%s: export --frd: step %d %s differs from the solve's" % (case, key[0], key[1]))


def node_ids_of_set(deck_text, name):
    """The ids of a plain *NSET (ids listed, no GENERATE) of a deck."""
    ids, inside = [], False
    for line in deck_text.splitlines():
        if line.startswith("*"):
            inside = line.replace(" ", "").upper().startswith("*NSET,NSET=" + name.upper())
            continue
        if inside:
            ids += [int(t) for t in line.replace(",", " ").split()]
    return sorted(ids)


def mesher_case(case, builder_args, fixed_set):
    deck = os.path.join(WORK, case + "_built.inp")
    run("%s mesh %s -o %s" % (STYK, builder_args, deck), WORK)
    text = with_file_requests(open(deck).read())
    solve_pair(case, case, text, node_ids_of_set(text, fixed_set))


GEO = """L = 10; h = 0.5;
Point(1) = {0, 0, 0, h}; Point(2) = {0, 1, 0, h}; Point(3) = {0, 1, 1, h}; Point(4) = {0, 0, 1, h};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
out[] = Extrude {L, 0, 0} { Surface{1}; };
Physical Volume("beam") = {out[1]};
Physical Surface("fixed") = {1};
Physical Surface("tip") = {out[0]};
Mesh.ElementOrder = 2;
"""

CANTILEVER = """*HEADING
Gmsh tetrahedral cantilever 10 x 1 x 1, tip force 1 along z
*INCLUDE, INPUT=beam_mesh.inp
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.
*SOLID SECTION, ELSET=BEAM, MATERIAL=STEEL
*BOUNDARY
FIXED, 1, 3
*STEP
*STATIC
*CLOAD
%s
*NODE PRINT, NSET=TIP
U
*NODE FILE
U, RF
*EL FILE
S, E
*END STEP
"""


def gmsh_cantilever():
    """Tip force P = 1 spread over the tip nodes; beam theory (Timoshenko, kappa = 5/6) gives
    PL^3/(3EI) + PL/(kappa G A) at the tip, 0.0191619; the mean tip deflection is compared."""
    base = os.path.join(WORK, "gmsh_mesh")
    shutil.rmtree(base, ignore_errors=True)
    os.makedirs(base)
    with open(os.path.join(base, "beam.geo"), "w") as f:
        f.write(GEO)
    run("gmsh -v 2 -3 beam.geo -format msh41 -o beam.msh", base)
    out = run("%s import beam.msh -o beam_mesh.inp" % STYK, base).stdout
    print(out.strip())
    mesh_text = open(os.path.join(base, "beam_mesh.inp")).read()
    tip = node_ids_of_set(mesh_text, "TIP")
    fixed = node_ids_of_set(mesh_text, "FIXED")
    loads = "\n".join("%d, 3, %.17g" % (n, 1.0 / len(tip)) for n in tip)
    EXTRA_FILES["gmsh_cantilever"] = ["gmsh_mesh/beam_mesh.inp"]
    workdir, ours, _ = solve_pair("gmsh_cantilever", "cantilever", CANTILEVER % loads, fixed)
    disp = [b for b in ours.blocks if b.name == "DISP"][0]
    mean = sum(disp.values[n][2] for n in tip) / len(tip)
    E, L, I, A = 210000.0, 10.0, 1.0 / 12.0, 1.0
    G = E / 2.0
    exact = L ** 3 / (3 * E * I) + L / (5.0 / 6.0 * G * A)
    error = abs(mean - exact) / exact
    print("gmsh cantilever (C3D10, %d nodes): tip deflection %.6g, beam theory %.6g, error %.2e"
          % (len(ours.nodes), mean, exact, error))
    if error > BEAM_TOLERANCE:
        fail("gmsh cantilever: tip deflection %.6g, beam theory %.6g (%.2e > %.0e)"
             % (mean, exact, error, BEAM_TOLERANCE))


EXTRA_FILES = {}

if __name__ == "__main__":
    STYK, WORK, SOURCE = sys.argv[1], sys.argv[2], sys.argv[3]
    shutil.rmtree(WORK, ignore_errors=True)
    os.makedirs(WORK)
    decks = os.path.join(SOURCE, "tests", "inputs", "frd")
    for name in sorted(os.listdir(decks)):
        if name.endswith(".inp"):
            text = open(os.path.join(decks, name)).read()
            solve_pair(name[:-4], name[:-4], text, node_ids_of_set(text, "FIX"))
    for element in ("C3D4", "C3D10", "C3D6", "C3D15"):
        mesher_case("beam_" + element.lower(),
                    "beam-10x2x2 --element %s --load bending --n 2" % element, "ROOT")
    mesher_case("cantilever_c3d20", "cantilever --element C3D20 --mesh 6x1", "ROOT")
    gmsh_cantilever()
    if failures:
        print("%d failure(s)" % len(failures))
        sys.exit(1)
    print("all .frd comparisons passed")
