#!/usr/bin/env python3
"""Writes the deck set (tests/inputs/decks/*.inp and manifest.tsv).

Each deck is assembled for Styk from a keyword description of the CalculiX 2.20 or Abaqus manual,
the way a user would write it: a small model that exercises one keyword (or option) the way the
manual describes it. The first line of every deck says which keyword it follows and what it checks.
tests/cli/deck_set_test.cpp solves every deck with `styk solve` and, where the manifest names ccx
as the reference, with ccx, and compares the .dat reports block by block.

Manifest columns: deck, reference (ccx: the ccx .dat; none: Styk alone, checked by the unit test
named in the note), relative tolerance (of each block's largest value), the .dat blocks compared
(all, or a comma list of block-title prefixes), note.

Run from anywhere: python3 tests/inputs/decks/make_decks.py
"""
import os

HERE = os.path.dirname(os.path.abspath(__file__))


# ----------------------------------------------------------------------------------------------
# Meshes


class Brick:
    """A structured block of C3D8 or C3D20 elements on [x0, x0+lx] x [y0, ...] x [z0, ...]."""

    def __init__(self, n, size, origin=(0.0, 0.0, 0.0), etype="C3D8", first_node=1,
                 first_element=1):
        self.n, self.size, self.origin, self.etype = n, size, origin, etype
        quadratic = etype.startswith("C3D20")
        self.step = 2 if quadratic else 1
        g = [k * self.step for k in n]
        self.ids = {}
        self.coords = {}
        nid = first_node
        for k in range(g[2] + 1):
            for j in range(g[1] + 1):
                for i in range(g[0] + 1):
                    odd = (i % 2) + (j % 2) + (k % 2) if quadratic else 0
                    if odd > 1:
                        continue
                    x = [origin[d] + size[d] * [i, j, k][d] / g[d] for d in range(3)]
                    self.ids[(i, j, k)] = nid
                    self.coords[nid] = x
                    nid += 1
        self.elements = {}
        eid = first_element
        s = self.step
        for k in range(n[2]):
            for j in range(n[1]):
                for i in range(n[0]):
                    a, b, c = i * s, j * s, k * s
                    corners = [(a, b, c), (a + s, b, c), (a + s, b + s, c), (a, b + s, c),
                               (a, b, c + s), (a + s, b, c + s), (a + s, b + s, c + s),
                               (a, b + s, c + s)]
                    nodes = [self.ids[p] for p in corners]
                    if quadratic:
                        h = 1
                        mids = [(a + h, b, c), (a + s, b + h, c), (a + h, b + s, c), (a, b + h, c),
                                (a + h, b, c + s), (a + s, b + h, c + s), (a + h, b + s, c + s),
                                (a, b + h, c + s), (a, b, c + h), (a + s, b, c + h),
                                (a + s, b + s, c + h), (a, b + s, c + h)]
                        nodes += [self.ids[p] for p in mids]
                    self.elements[eid] = ((i, j, k), nodes)
                    eid += 1
        self.last_node = nid - 1
        self.last_element = eid - 1

    def nodes_where(self, test):
        return sorted(n for n, x in self.coords.items() if test(x))

    def faces(self, side):
        """Element faces on a side of the block: 'x0', 'x1', 'y0', 'y1', 'z0', 'z1'."""
        label = {"z0": "S1", "z1": "S2", "y0": "S3", "x1": "S4", "y1": "S5", "x0": "S6"}[side]
        axis = "xyz".index(side[0])
        upper = side[1] == "1"
        out = []
        for eid, (ijk, _) in self.elements.items():
            if (ijk[axis] == self.n[axis] - 1) if upper else (ijk[axis] == 0):
                out.append((eid, label))
        return out

    def node_text(self, nset=None):
        lines = ["*NODE" + (", NSET=" + nset if nset else "")]
        for nid, x in self.coords.items():
            lines.append("%d, %s, %s, %s" % (nid, fmt(x[0]), fmt(x[1]), fmt(x[2])))
        return "\n".join(lines) + "\n"

    def element_text(self, elset):
        lines = ["*ELEMENT, TYPE=%s, ELSET=%s" % (self.etype, elset)]
        for eid, (_, nodes) in self.elements.items():
            row = [str(eid)] + [str(v) for v in nodes]
            if len(row) > 16:
                lines.append(", ".join(row[:16]) + ",")
                lines.append(", ".join(row[16:]))
            else:
                lines.append(", ".join(row))
        return "\n".join(lines) + "\n"


def fmt(v):
    text = repr(float(v))
    return text[:-2] + "." if text.endswith(".0") else text


def nset(name, ids):
    lines = ["*NSET, NSET=" + name]
    ids = list(ids)
    for k in range(0, len(ids), 16):
        lines.append(", ".join(str(i) for i in ids[k:k + 16]))
    return "\n".join(lines) + "\n"


def elset(name, ids):
    return nset(name, ids).replace("*NSET, NSET=", "*ELSET, ELSET=")


def surface(name, faces):
    return "*SURFACE, NAME=%s\n" % name + "".join("%d, %s\n" % f for f in faces)


STEEL = "*MATERIAL, NAME=STEEL\n*ELASTIC\n210000., 0.3\n"


def clamp_block(b, name="FIX"):
    """A node set on x = x0 of the block, fixed in all directions."""
    return nset(name, b.nodes_where(lambda x: abs(x[0] - b.origin[0]) < 1e-9)) + \
        "*BOUNDARY\n%s, 1, 3\n" % name


def symmetric_supports(b):
    """x = 0, y = 0, z = 0 faces held normal to themselves: free lateral contraction."""
    o = b.origin
    return (nset("X0", b.nodes_where(lambda x: abs(x[0] - o[0]) < 1e-9)) +
            nset("Y0", b.nodes_where(lambda x: abs(x[1] - o[1]) < 1e-9)) +
            nset("Z0", b.nodes_where(lambda x: abs(x[2] - o[2]) < 1e-9)) +
            "*BOUNDARY\nX0, 1\nY0, 2\nZ0, 3\n")


def step(body, prints):
    return "*STEP\n*STATIC\n" + body + prints + "*END STEP\n"


DECKS = []


def deck(name, reference="ccx", tolerance="1e-6", compare="all", note=""):
    def register(fn):
        DECKS.append((name, fn, reference, tolerance, compare, note))
        return fn
    return register


# ----------------------------------------------------------------------------------------------
# Reader robustness (issue 15 item 8)


@deck("r01_digit_set_names")
def _():
    b = Brick((3, 1, 1), (3.0, 1.0, 1.0))
    return ("** Deck set r01 (CalculiX manual, *NSET/*ELSET): set names that start with a digit.\n" +
            b.node_text() + b.element_text("EALL") + STEEL +
            "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n" + clamp_block(b) +
            nset("1TOP", b.nodes_where(lambda x: abs(x[0] - 3.0) < 1e-9)) +
            elset("1E", [3]) +
            step("*CLOAD\n1TOP, 3, -10.\n", "*NODE PRINT, NSET=1TOP\nU\n*EL PRINT, ELSET=1E\nS\n"))


@deck("r02_node_id_only")
def _():
    b = Brick((2, 1, 1), (2.0, 1.0, 1.0))
    return ("** Deck set r02 (CalculiX manual, *NODE): a data line with the node number alone puts "
            "the node at the origin.\n" +
            b.node_text() + "*NODE\n500\n" + b.element_text("EALL") + STEEL +
            "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n" + clamp_block(b) +
            nset("TIP", b.nodes_where(lambda x: abs(x[0] - 2.0) < 1e-9) + [500]) +
            step("*CLOAD\n%d, 2, 5.\n" % b.nodes_where(lambda x: abs(x[0] - 2.0) < 1e-9)[0],
                 "*NODE PRINT, NSET=TIP\nU\n"))


@deck("r03_generate_over_gaps")
def _():
    a = Brick((2, 1, 1), (2.0, 1.0, 1.0))
    b = Brick((2, 1, 1), (2.0, 1.0, 1.0), origin=(2.0, 0.0, 0.0), first_node=101,
              first_element=11)
    # The two blocks share the plane x = 2: tie them with equations node by node.
    shared = [(n, m) for n in a.nodes_where(lambda x: abs(x[0] - 2.0) < 1e-9)
              for m in b.nodes_where(lambda x: abs(x[0] - 2.0) < 1e-9)
              if all(abs(a.coords[n][d] - b.coords[m][d]) < 1e-9 for d in range(3))]
    eqs = "*EQUATION\n" + "".join("2\n%d, %d, 1., %d, %d, -1.\n" % (m, d, n, d)
                                  for n, m in shared for d in (1, 2, 3))
    return ("** Deck set r03 (CalculiX manual, *NSET/*ELSET GENERATE): ranges that pass over "
            "numbers that are not nodes or elements.\n" +
            a.node_text() + b.node_text() + a.element_text("EA") + b.element_text("EB") +
            "*ELSET, ELSET=EALL, GENERATE\n1, 12, 1\n" + STEEL +
            "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n" +
            "*NSET, NSET=FIX, GENERATE\n1, 10, 3\n" + eqs +
            "*BOUNDARY\nFIX, 1, 3\n" + "*NSET, NSET=BLOCKB, GENERATE\n101, 200, 1\n" +
            nset("END", b.nodes_where(lambda x: abs(x[0] - 4.0) < 1e-9)) +
            step("*CLOAD\nEND, 3, -2.\nEND, 1, 1.\n", "*NODE PRINT, NSET=BLOCKB\nU\n"))


# ----------------------------------------------------------------------------------------------
# Materials (issue 15 item 3)


def uniaxial_block(material, extra="", load="*CLOAD\nX1, 1, 50.\n", prints=None, n=(2, 2, 2),
                   section_extra="", temperature=""):
    """A unit cube meshed n, held on x=0, y=0, z=0 (normal only), pulled on x=1."""
    b = Brick(n, (1.0, 1.0, 1.0))
    prints = prints or "*NODE PRINT, NSET=NALL\nU\n*EL PRINT, ELSET=EALL\nS, E\n"
    return (b.node_text("NALL") + b.element_text("EALL") + material + extra +
            "*SOLID SECTION, ELSET=EALL, MATERIAL=M%s\n" % section_extra +
            symmetric_supports(b) + nset("X1", b.nodes_where(lambda x: abs(x[0] - 1.0) < 1e-9)) +
            temperature + step(load, prints))


@deck("m01_elastic_temperature_table")
def _():
    return ("** Deck set m01 (CalculiX manual, *ELASTIC, TYPE=ISO): E and nu over temperature, "
            "interpolated at the step's uniform temperature.\n" +
            uniaxial_block("*MATERIAL, NAME=M\n*ELASTIC\n200000., 0.30, 0.\n150000., 0.32, 100.\n"
                           "100000., 0.35, 300.\n",
                           temperature="*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 20.\n",
                           load="*TEMPERATURE\nNALL, 150.\n*CLOAD\nX1, 1, 50.\n".replace(
                               "*TEMPERATURE", "*TEMPERATURE")).replace(
                "*MATERIAL, NAME=M\n", "*MATERIAL, NAME=M\n*EXPANSION\n0.\n"))


@deck("m02_elastic_orthotropic")
def _():
    b = Brick((4, 1, 2), (4.0, 1.0, 1.0))
    return ("** Deck set m02 (CalculiX manual, *ELASTIC, TYPE=ORTHO): the nine constants D1111 .. "
            "D2323 of an orthotropic law in global axes, a cantilever bent about two axes.\n" +
            b.node_text("NALL") + b.element_text("EALL") +
            "*MATERIAL, NAME=M\n*ELASTIC, TYPE=ORTHO\n"
            "150000., 40000., 90000., 30000., 35000., 60000., 25000., 20000.\n15000., 0.\n"
            "*SOLID SECTION, ELSET=EALL, MATERIAL=M\n" + clamp_block(b) +
            nset("TIP", b.nodes_where(lambda x: abs(x[0] - 4.0) < 1e-9)) +
            step("*CLOAD\nTIP, 2, 3.\nTIP, 3, -5.\n",
                 "*NODE PRINT, NSET=TIP\nU\n*EL PRINT, ELSET=EALL\nS\n"))


@deck("m03_engineering_constants_rotated")
def _():
    return ("** Deck set m03 (CalculiX manual, *ELASTIC, TYPE=ENGINEERING CONSTANTS and "
            "*ORIENTATION on *SOLID SECTION): material axes turned 30 degrees about z; stresses "
            "print in them.\n" +
            uniaxial_block("*MATERIAL, NAME=M\n*ELASTIC, TYPE=ENGINEERING CONSTANTS\n"
                           "100000., 50000., 20000., 0.3, 0.2, 0.25, 30000., 20000.\n10000., 0.\n",
                           extra="*ORIENTATION, NAME=ROT\n0.8660254037844387, 0.5, 0., -0.5, "
                                 "0.8660254037844387, 0.\n",
                           section_extra=", ORIENTATION=ROT"))


def anisotropic_constants():
    """A positive definite fully anisotropic stiffness: isotropic steel plus couplings."""
    lam, mu = 121153.846, 80769.231
    D = [[0.0] * 6 for _ in range(6)]
    for i in range(3):
        for j in range(3):
            D[i][j] = lam + (2 * mu if i == j else 0.0)
        D[i + 3][i + 3] = mu
    couplings = {(0, 3): 9000., (1, 4): -7000., (2, 5): 5000., (0, 5): 4000., (3, 4): 3000.,
                 (1, 3): -2500., (4, 5): 2000.}
    for (i, j), v in couplings.items():
        D[i][j] = D[j][i] = v
    values = [D[i][j] for j in range(6) for i in range(j + 1)]
    return values


@deck("m04_elastic_anisotropic")
def _():
    c = anisotropic_constants()
    text = "".join(fmt(v) + (",\n" if (k + 1) % 8 == 0 else ", ") for k, v in enumerate(c))
    text = text + "0.\n"
    return ("** Deck set m04 (CalculiX manual, *ELASTIC, TYPE=ANISO): 21 constants of a fully "
            "anisotropic law, couplings between normal and shear terms.\n" +
            uniaxial_block("*MATERIAL, NAME=M\n*ELASTIC, TYPE=ANISO\n" + text))


@deck("m05_cylindrical_orientation")
def _():
    b = Brick((3, 2, 2), (3.0, 1.0, 1.0), origin=(2.0, -0.5, 0.0))
    return ("** Deck set m05 (CalculiX manual, *ORIENTATION, SYSTEM=CYLINDRICAL on *SOLID "
            "SECTION): orthotropic axes radial/tangential/axial about z, evaluated at each "
            "integration point.\n" +
            b.node_text("NALL") + b.element_text("EALL") +
            "*MATERIAL, NAME=M\n*ELASTIC, TYPE=ENGINEERING CONSTANTS\n"
            "60000., 180000., 40000., 0.25, 0.3, 0.2, 25000., 18000.\n15000., 0.\n"
            "*ORIENTATION, NAME=CYL, SYSTEM=CYLINDRICAL\n0., 0., 0., 0., 0., 1.\n"
            "*SOLID SECTION, ELSET=EALL, MATERIAL=M, ORIENTATION=CYL\n" + clamp_block(b) +
            nset("TIP", b.nodes_where(lambda x: abs(x[0] - 5.0) < 1e-9)) +
            step("*CLOAD\nTIP, 2, 4.\nTIP, 1, -2.\n",
                 "*NODE PRINT, NSET=TIP\nU\n*EL PRINT, ELSET=EALL\nS\n"))


@deck("m06_expansion_table_zero")
def _():
    return ("** Deck set m06 (CalculiX manual, *EXPANSION, ZERO=): a mean expansion coefficient "
            "over temperature referred to ZERO, heated from 20 to 180 under load.\n" +
            uniaxial_block("*MATERIAL, NAME=M\n*ELASTIC\n200000., 0.3\n"
                           "*EXPANSION, ZERO=20.\n1.1E-5, 0.\n1.3E-5, 100.\n1.6E-5, 200.\n",
                           temperature="*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 20.\n",
                           load="*TEMPERATURE\nNALL, 180.\n*CLOAD\nX1, 1, 50.\n"))


@deck("m07_expansion_orthotropic_rotated")
def _():
    return ("** Deck set m07 (CalculiX manual, *EXPANSION, TYPE=ORTHO with *ORIENTATION): "
            "different coefficients along the turned material axes of a heated cube.\n" +
            uniaxial_block("*MATERIAL, NAME=M\n*ELASTIC\n200000., 0.3\n"
                           "*EXPANSION, TYPE=ORTHO\n1.0E-5, 2.5E-5, 0.5E-5\n",
                           extra="*ORIENTATION, NAME=ROT\n0.8660254037844387, 0.5, 0., -0.5, "
                                 "0.8660254037844387, 0.\n",
                           section_extra=", ORIENTATION=ROT",
                           temperature="*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 0.\n",
                           load="*TEMPERATURE\nNALL, 100.\n*CLOAD\nX1, 1, 20.\n"))


@deck("m08_expansion_anisotropic")
def _():
    return ("** Deck set m08 (CalculiX manual, *EXPANSION, TYPE=ANISO): six coefficients, shear "
            "terms included, of a heated cube.\n" +
            uniaxial_block("*MATERIAL, NAME=M\n*ELASTIC\n200000., 0.3\n"
                           "*EXPANSION, TYPE=ANISO\n1.0E-5, 2.0E-5, 1.5E-5, 0.4E-5, 0.2E-5, "
                           "-0.3E-5\n",
                           temperature="*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 0.\n",
                           load="*TEMPERATURE\nNALL, 100.\n"))


@deck("m09_elastic_table_temperature_field")
def _():
    # C3D20: ccx interpolates the temperature linearly from the corner nodes there, which equals
    # the element's own interpolation for a field linear along the beam (C3D8 takes the element
    # mean in ccx; docs/deck-set.md).
    b = Brick((4, 1, 1), (4.0, 1.0, 1.0), etype="C3D20")
    temps = "".join("%d, %s\n" % (n, fmt(20.0 + 40.0 * x[0])) for n, x in b.coords.items())
    return ("** Deck set m09 (CalculiX manual, *ELASTIC over temperature with *TEMPERATURE): a "
            "temperature varying along the beam, so E and nu vary between integration points.\n" +
            b.node_text("NALL") + b.element_text("EALL") +
            "*MATERIAL, NAME=M\n*ELASTIC\n210000., 0.3, 0.\n190000., 0.31, 100.\n150000., 0.33, 200.\n"
            "*EXPANSION, ZERO=20.\n1.2E-5\n*SOLID SECTION, ELSET=EALL, MATERIAL=M\n" +
            clamp_block(b) + "*INITIAL CONDITIONS, TYPE=TEMPERATURE\nNALL, 20.\n" +
            nset("TIP", b.nodes_where(lambda x: abs(x[0] - 4.0) < 1e-9)) +
            step("*TEMPERATURE\n" + temps + "*CLOAD\nTIP, 3, -4.\n",
                 "*NODE PRINT, NSET=TIP\nU\n*EL PRINT, ELSET=EALL\nS\n"))


# ----------------------------------------------------------------------------------------------
# Loads and initial states (issue 15 item 2)


@deck("l01_gravity_c3d20", compare="displacements,stresses",
      note="RF not compared: ccx prints the internal nodal force, which includes each fixed "
           "node's share of the body force")
def _():
    b = Brick((4, 1, 2), (8.0, 1.0, 2.0), etype="C3D20")
    return ("** Deck set l01 (CalculiX manual, *DLOAD GRAV with *DENSITY): a C3D20 cantilever "
            "under its own weight along -z and a side acceleration along y.\n" +
            b.node_text("NALL") + b.element_text("EALL") +
            STEEL + "*DENSITY\n7.85E-9\n*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n" +
            clamp_block(b) + nset("TIP", b.nodes_where(lambda x: abs(x[0] - 8.0) < 1e-9)) +
            step("*DLOAD\nEALL, GRAV, 9810., 0., 0., -1.\nEALL, GRAV, 2000., 0., 1., 0.\n",
                 "*NODE PRINT, NSET=TIP\nU\n*EL PRINT, ELSET=EALL\nS\n*NODE PRINT, NSET=FIX\nRF\n"))


@deck("l02_centrifugal", compare="displacements,stresses",
      note="RF not compared (as l01)")
def _():
    b = Brick((3, 2, 1), (3.0, 1.0, 0.5), origin=(1.0, -0.5, 0.0))
    return ("** Deck set l02 (CalculiX manual, *DLOAD CENTRIF): a block spinning about the z axis "
            "through the origin, held at its hub end.\n" +
            b.node_text("NALL") + b.element_text("EALL") +
            STEEL + "*DENSITY\n7.85E-9\n*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n" +
            clamp_block(b) + nset("TIP", b.nodes_where(lambda x: abs(x[0] - 4.0) < 1e-9)) +
            step("*DLOAD\nEALL, CENTRIF, 1.0E6, 0., 0., 0., 0., 0., 1.\n",
                 "*NODE PRINT, NSET=TIP\nU\n*EL PRINT, ELSET=EALL\nS\n*NODE PRINT, NSET=FIX\nRF\n"))


@deck("l03_dsload_surface_pressure", compare="displacements",
      note="RF not compared: the pressure also loads the clamped nodes, whose share ccx adds to "
           "their printed force")
def _():
    b = Brick((4, 1, 1), (4.0, 1.0, 1.0), etype="C3D20")
    return ("** Deck set l03 (CalculiX manual, *DSLOAD): a pressure on an element-face surface "
            "(the top of a cantilever).\n" +
            b.node_text("NALL") + b.element_text("EALL") + STEEL +
            "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n" + clamp_block(b) +
            surface("TOP", b.faces("z1")) +
            nset("TIP", b.nodes_where(lambda x: abs(x[0] - 4.0) < 1e-9)) +
            step("*DSLOAD\nTOP, P, 2.5\n", "*NODE PRINT, NSET=TIP\nU\n*NODE PRINT, NSET=FIX, "
                 "TOTALS=YES\nRF\n"))


@deck("l04_initial_stress")
def _():
    b = Brick((2, 2, 2), (1.0, 1.0, 1.0))
    rows = "".join("%d, %d, 100., -40., 25., 10., 0., 5.\n" % (e, p)
                   for e in b.elements for p in range(1, 9))
    return ("** Deck set l04 (CalculiX manual, *INITIAL CONDITIONS, TYPE=STRESS): a residual "
            "stress at every integration point, partly released by the supports, then loaded.\n" +
            b.node_text("NALL") + b.element_text("EALL") + STEEL +
            "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n" +
            "*INITIAL CONDITIONS, TYPE=STRESS\n" + rows + symmetric_supports(b) +
            nset("X1", b.nodes_where(lambda x: abs(x[0] - 1.0) < 1e-9)) +
            step("*CLOAD\nX1, 1, 10.\n", "*NODE PRINT, NSET=NALL\nU\n*EL PRINT, ELSET=EALL\nS\n"))


@deck("l05_change_solid_section")
def _():
    b = Brick((3, 1, 1), (3.0, 1.0, 1.0))
    return ("** Deck set l05 (CalculiX manual, *CHANGE SOLID SECTION): the second step swaps the "
            "outer elements' material; each linear step solves the total load anew.\n" +
            b.node_text("NALL") + b.element_text("EALL") + elset("OUTER", [3]) +
            elset("INNER", [1, 2]) + STEEL + "*MATERIAL, NAME=ALU\n*ELASTIC\n70000., 0.33\n" +
            "*SOLID SECTION, ELSET=INNER, MATERIAL=STEEL\n"
            "*SOLID SECTION, ELSET=OUTER, MATERIAL=STEEL\n" + clamp_block(b) +
            nset("TIP", b.nodes_where(lambda x: abs(x[0] - 3.0) < 1e-9)) +
            step("*CLOAD\nTIP, 3, -6.\n", "*NODE PRINT, NSET=TIP\nU\n*EL PRINT, ELSET=EALL\nS\n") +
            "*STEP\n*CHANGE SOLID SECTION, ELSET=OUTER, MATERIAL=ALU\n*STATIC\n"
            "*NODE PRINT, NSET=TIP\nU\n*EL PRINT, ELSET=EALL\nS\n*END STEP\n")


@deck("l06_boundary_fixed")
def _():
    b = Brick((3, 1, 1), (3.0, 1.0, 1.0))
    tip = b.nodes_where(lambda x: abs(x[0] - 3.0) < 1e-9)
    return ("** Deck set l06 (CalculiX manual, *BOUNDARY, FIXED): the tip displacement reached in "
            "step 1 is held in step 2 while the load changes.\n" +
            b.node_text("NALL") + b.element_text("EALL") + STEEL +
            "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n" + clamp_block(b) + nset("TIP", tip) +
            nset("MID", b.nodes_where(lambda x: abs(x[0] - 1.0) < 1e-9)) +
            step("*CLOAD\nTIP, 3, -8.\n", "*NODE PRINT, NSET=NALL\nU\n") +
            "*STEP\n*STATIC\n*BOUNDARY, FIXED\nTIP, 3, 3\n*CLOAD, OP=NEW\nMID, 2, 5.\n"
            "*NODE PRINT, NSET=NALL\nU\n*NODE PRINT, NSET=TIP, TOTALS=YES\nRF\n*END STEP\n")


def bolt(etype="C3D8"):
    """A square bolt 1 x 1 x 4 along z, 2 x 2 x 4 elements, clamped at both ends."""
    return Brick((2, 2, 4), (1.0, 1.0, 4.0), etype=etype)


def pretension_deck(title, load, etype="C3D8"):
    b = bolt(etype)
    lower = [e for e, (ijk, _) in b.elements.items() if ijk[2] == 1]  # faces at z = 2
    return (title + b.node_text("NALL") + "*NODE\n9000, 0., 0., 0.\n" + b.element_text("EALL") +
            STEEL + "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n" +
            surface("CUT", [(e, "S2") for e in lower]) +
            "*PRE-TENSION SECTION, SURFACE=CUT, NODE=9000\n0., 0., 1.\n" +
            nset("ENDS", b.nodes_where(lambda x: abs(x[2]) < 1e-9 or abs(x[2] - 4.0) < 1e-9)) +
            "*BOUNDARY\nENDS, 1, 3\n" + nset("REF", [9000]) +
            nset("MIDS", b.nodes_where(lambda x: abs(x[2] - 2.0) < 1e-9)) +
            step(load, "*NODE PRINT, NSET=REF\nU\n*NODE PRINT, NSET=MIDS\nU\n"
                       "*EL PRINT, ELSET=EALL\nS\n"))


@deck("l07_pretension_force")
def _():
    return pretension_deck(
        "** Deck set l07 (CalculiX manual, *PRE-TENSION SECTION with *CLOAD on the reference "
        "node): a bolt clamped at both ends, cut at mid height, pulled together by 1000 N.\n",
        "*CLOAD\n9000, 1, 1000.\n")


@deck("l08_pretension_shortening")
def _():
    return pretension_deck(
        "** Deck set l08 (CalculiX manual, *PRE-TENSION SECTION with *BOUNDARY on the reference "
        "node): the same bolt (C3D20) shortened by 0.002 across the section.\n",
        "*BOUNDARY\n9000, 1, 1, 0.002\n", etype="C3D20")


# ----------------------------------------------------------------------------------------------
# Constraints and couplings (issue 15 item 1)


def two_blocks(lower_n, upper_n, etype="C3D8", upper_etype=None, gap=0.0):
    """Two blocks stacked along z: lower [0,2]x[0,1]x[0,1], upper on top (its own nodes)."""
    lower = Brick(lower_n, (2.0, 1.0, 1.0), etype=etype)
    upper = Brick(upper_n, (2.0, 1.0, 1.0), origin=(0.0, 0.0, 1.0 + gap),
                  etype=upper_etype or etype, first_node=lower.last_node + 1,
                  first_element=lower.last_element + 1)
    return lower, upper


def tie_deck(title, lower, upper, tie_line, slave_surface=None):
    slave_surface = slave_surface or surface("UPPERBOT", upper.faces("z0"))
    top = upper.nodes_where(lambda x: abs(x[2] - upper.origin[2] - 1.0) < 1e-9)
    return (title + lower.node_text("NALL") + upper.node_text("NALL") +
            lower.element_text("ELOW") + upper.element_text("EUP") + STEEL +
            "*MATERIAL, NAME=ALU\n*ELASTIC\n70000., 0.33\n"
            "*SOLID SECTION, ELSET=ELOW, MATERIAL=STEEL\n*SOLID SECTION, ELSET=EUP, MATERIAL=ALU\n" +
            surface("LOWERTOP", lower.faces("z1")) + slave_surface + tie_line +
            nset("BASE", lower.nodes_where(lambda x: abs(x[2]) < 1e-9)) +
            "*BOUNDARY\nBASE, 1, 3\n" + nset("TOP", top) +
            step("*CLOAD\nTOP, 1, 2.\nTOP, 3, -3.\n",
                 "*NODE PRINT, NSET=TOP\nU\n*EL PRINT, ELSET=EUP\nS\n"))


@deck("c01_tie_matching")
def _():
    lower, upper = two_blocks((2, 2, 1), (2, 2, 1))
    return tie_deck("** Deck set c01 (CalculiX manual, *TIE): two blocks with coincident nodes at "
                    "their interface tied together.\n", lower, upper,
                    "*TIE, NAME=T1\nUPPERBOT, LOWERTOP\n")


@deck("c02_tie_nonmatching")
def _():
    lower, upper = two_blocks((2, 2, 1), (3, 3, 1))
    return tie_deck("** Deck set c02 (CalculiX manual, *TIE): a fine block tied onto a coarse one "
                    "(slave nodes inside the master faces).\n", lower, upper,
                    "*TIE, NAME=T1\nUPPERBOT, LOWERTOP\n")


@deck("c03_tie_c3d20_nonmatching")
def _():
    lower, upper = two_blocks((2, 1, 1), (3, 2, 1), etype="C3D20")
    return tie_deck("** Deck set c03 (CalculiX manual, *TIE): quadratic (C3D20) blocks of "
                    "different meshes tied.\n", lower, upper,
                    "*TIE, NAME=T1\nUPPERBOT, LOWERTOP\n")


@deck("c04_tie_node_surface")
def _():
    lower, upper = two_blocks((2, 2, 1), (3, 2, 1))
    slaves = upper.nodes_where(lambda x: abs(x[2] - 1.0) < 1e-9)
    return tie_deck("** Deck set c04 (CalculiX manual, *TIE with a nodal slave surface): the slave "
                    "surface given as nodes (*SURFACE, TYPE=NODE).\n", lower, upper,
                    "*TIE, NAME=T1\nUPNODES, LOWERTOP\n",
                    nset("UPBOT", slaves) + "*SURFACE, NAME=UPNODES, TYPE=NODE\nUPBOT\n")


@deck("c05_tie_tolerance_no_adjust")
def _():
    lower, upper = two_blocks((2, 2, 1), (3, 3, 1), gap=0.001)
    return tie_deck("** Deck set c05 (CalculiX manual, *TIE, POSITION TOLERANCE, ADJUST=NO): a "
                    "0.001 gap bridged without moving the slave nodes.\n", lower, upper,
                    "*TIE, NAME=T1, POSITION TOLERANCE=0.01, ADJUST=NO\nUPPERBOT, LOWERTOP\n")


def coupling_deck(title, coupling, load, prints="*NODE PRINT, NSET=TIP\nU\n"):
    b = Brick((4, 2, 2), (4.0, 1.0, 1.0))
    return (title + b.node_text("NALL") + "*NODE\n9000, 4.5, 0.5, 0.5\n" +
            b.element_text("EALL") + STEEL + "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n" +
            clamp_block(b) + surface("END", b.faces("x1")) + coupling +
            nset("TIP", b.nodes_where(lambda x: abs(x[0] - 4.0) < 1e-9)) + nset("REF", [9000]) +
            step(load, prints))


@deck("c06_kinematic_coupling")
def _():
    return coupling_deck(
        "** Deck set c06 (CalculiX manual, *COUPLING with *KINEMATIC): the end face of a "
        "cantilever follows its reference node rigidly; the load acts on the reference node.\n",
        "*COUPLING, REF NODE=9000, SURFACE=END, CONSTRAINT NAME=KC\n*KINEMATIC\n1, 3\n",
        "*CLOAD\n9000, 3, -10.\n9000, 2, 4.\n",
        "*NODE PRINT, NSET=TIP\nU\n*NODE PRINT, NSET=REF\nU\n")


@deck("c07_kinematic_coupling_partial")
def _():
    return coupling_deck(
        "** Deck set c07 (CalculiX manual, *KINEMATIC with a dof range): only the x and y "
        "translations of the end face follow the reference node, which is loaded along them and "
        "held along z.\n",
        "*COUPLING, REF NODE=9000, SURFACE=END, CONSTRAINT NAME=KC\n*KINEMATIC\n1, 2\n",
        "*BOUNDARY\n9000, 3, 3\n*CLOAD\n9000, 1, 5.\n9000, 2, -3.\n",
        "*NODE PRINT, NSET=TIP\nU\n*NODE PRINT, NSET=REF\nU\n")


@deck("c08_distributing_force")
def _():
    return coupling_deck(
        "** Deck set c08 (CalculiX manual, *COUPLING with *DISTRIBUTING): forces on an offset "
        "reference node spread over the end face with the same resultant and moment.\n",
        "*COUPLING, REF NODE=9000, SURFACE=END, CONSTRAINT NAME=DC\n*DISTRIBUTING\n1, 3\n",
        "*CLOAD\n9000, 3, -10.\n9000, 1, 6.\n9000, 2, 2.\n")


@deck("c09_distributing_moment")
def _():
    return coupling_deck(
        "** Deck set c09 (CalculiX manual, *DISTRIBUTING with rotations 4..6): a torque and a "
        "bending moment on the reference node spread over the end face.\n",
        "*COUPLING, REF NODE=9000, SURFACE=END, CONSTRAINT NAME=DC\n*DISTRIBUTING\n4, 6\n",
        "*CLOAD\n9000, 4, 20.\n9000, 5, -8.\n")


def mpc_frame(mpc, held, load):
    """Two cubes linked only by the *MPC: A (nodes 1..8) clamped on x = 0, B (101..108) held as
    `held` says; both deform under `load`."""
    a = Brick((1, 1, 1), (1.0, 1.0, 1.0))
    b = Brick((1, 1, 1), (1.0, 1.0, 1.0), origin=(3.0, 0.0, 0.0), first_node=101,
              first_element=11)
    return (a.node_text("NALL") + b.node_text("NALL") + a.element_text("EA") +
            b.element_text("EB") + STEEL + "*SOLID SECTION, ELSET=EA, MATERIAL=STEEL\n"
            "*SOLID SECTION, ELSET=EB, MATERIAL=STEEL\n" + "*MPC\n" + mpc +
            nset("AX0", a.nodes_where(lambda x: abs(x[0]) < 1e-9)) +
            "*BOUNDARY\nAX0, 1, 3\n" + held +
            step(load, "*NODE PRINT, NSET=NALL\nU\n"))


def scaled_loads(text, scale):
    """*CLOAD data lines with every magnitude multiplied by `scale`."""
    if scale == 1.0:
        return text
    lines = text.strip("\n").split("\n")
    out = [lines[0]]
    for line in lines[1:]:
        node, dof, value = [f.strip() for f in line.split(",")]
        out.append("%s, %s, %.6g" % (node, dof, float(value) * scale))
    return "\n".join(out) + "\n"


MPC_NLGEOM_NOTE = ("ccx turns on nonlinear geometry for BEAM/STRAIGHT/PLANE (log: 'nonlinear geometric "
                   "effects are turned on'); Styk is geometrically linear: the difference is "
                   "proportional to the load (%s, loads x 1e-4, agrees to 1e-6)")
SMALL_LOAD = 1e-4


def mpc_beam(tag, scale):
    return ("** Deck set %s (CalculiX manual, *MPC BEAM): a rigid link of constant length "
            "between two cubes, the second held only at its far face%s.\n" % (tag, loads_note(scale)) +
            mpc_frame("BEAM, 101, 2\n",
                      "*NSET, NSET=BFAR\n102, 104, 106, 108\n*BOUNDARY\nBFAR, 1, 3\n",
                      scaled_loads("*CLOAD\n101, 1, -10.\n101, 2, 5.\n7, 3, 4.\n", scale)))


def mpc_straight(tag, scale):
    return ("** Deck set %s (CalculiX manual, *MPC STRAIGHT): an edge of the second cube stays on "
            "the line through two nodes of the first, which bends%s.\n" % (tag, loads_note(scale)) +
            mpc_frame("STRAIGHT, 1, 2, 101, 102\n",
                      "*NSET, NSET=BTOP\n105, 106, 107, 108\n*BOUNDARY\nBTOP, 1, 2\n",
                      scaled_loads("*CLOAD\n2, 2, 20.\n103, 3, -5.\n101, 2, 3.\n", scale)))


def mpc_plane(tag, scale):
    return ("** Deck set %s (CalculiX manual, *MPC PLANE): three nodes of the second cube stay in "
            "the plane of three nodes of the first, which deforms%s.\n" % (tag, loads_note(scale)) +
            mpc_frame("PLANE, 1, 2, 4, 101, 102, 103\n",
                      "*NSET, NSET=BTOP\n105, 106, 107, 108\n*BOUNDARY\nBTOP, 1, 2\n",
                      scaled_loads("*CLOAD\n2, 3, 20.\n3, 3, -10.\n103, 3, -5.\n", scale)))


def loads_note(scale):
    return "" if scale == 1.0 else (", with loads x %g so that ccx's nonlinear geometry is "
                                    "negligible" % scale)


@deck("c10_mpc_beam", tolerance="5e-4", note=MPC_NLGEOM_NOTE % "c15")
def _():
    return mpc_beam("c10", 1.0)


@deck("c11_mpc_straight", tolerance="2e-3", note=MPC_NLGEOM_NOTE % "c16")
def _():
    return mpc_straight("c11", 1.0)


@deck("c12_mpc_plane", tolerance="6e-4", note=MPC_NLGEOM_NOTE % "c17")
def _():
    return mpc_plane("c12", 1.0)


@deck("c13_equation_node_sets", reference="none",
      note="Abaqus *EQUATION with node sets; ccx 2.20 refuses node sets: checked against a hand "
           "value in KeywordConstraints.EquationWithNodeSetAndElementlessNode and read in "
           "KeywordCoverage.EquationWithNodeSets")
def _():
    b = Brick((2, 1, 1), (2.0, 1.0, 1.0))
    top = b.nodes_where(lambda x: abs(x[2] - 1.0) < 1e-9 and x[0] > 1.5)
    return ("** Deck set c13 (Abaqus manual, *EQUATION with a node set label): every node of the "
            "set TIP moves along z with node 9000.\n" +
            b.node_text("NALL") + "*NODE\n9000, 3., 0.5, 1.\n" + b.element_text("EALL") + STEEL +
            "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n" + clamp_block(b) + nset("TIP", top) +
            "*EQUATION\n2\nTIP, 3, 1., 9000, 3, -1.\n" + nset("REF", [9000]) +
            step("*CLOAD\n9000, 3, -4.\n", "*NODE PRINT, NSET=TIP\nU\n*NODE PRINT, NSET=REF\nU\n"))


@deck("c14_equation_node_without_element")
def _():
    b = Brick((2, 1, 1), (2.0, 1.0, 1.0))
    tip = b.nodes_where(lambda x: abs(x[0] - 2.0) < 1e-9)
    eqs = "*EQUATION\n" + "".join("2\n%d, 2, 1., 9000, 2, -1.\n" % n for n in tip)
    return ("** Deck set c14 (CalculiX manual, *EQUATION): a node that belongs to no element "
            "drives the tip face through equations and takes the load.\n" +
            b.node_text("NALL") + "*NODE\n9000, 2.5, 0.5, 0.5\n" + b.element_text("EALL") +
            STEEL + "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n" + clamp_block(b) + eqs +
            nset("TIP", tip) + nset("REF", [9000]) +
            step("*CLOAD\n9000, 2, 3.\n", "*NODE PRINT, NSET=TIP\nU\n*NODE PRINT, NSET=REF\nU\n"))


@deck("c15_mpc_beam_small_load")
def _():
    return mpc_beam("c15", SMALL_LOAD)


@deck("c16_mpc_straight_small_load")
def _():
    return mpc_straight("c16", SMALL_LOAD)


@deck("c17_mpc_plane_small_load")
def _():
    return mpc_plane("c17", SMALL_LOAD)


# ----------------------------------------------------------------------------------------------
# Output requests (issue 15 item 5)


def cantilever(etype="C3D8", n=(4, 1, 2)):
    b = Brick(n, (4.0, 1.0, 1.0), etype=etype)
    return b, (b.node_text("NALL") + b.element_text("EALL") + STEEL +
               "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL\n" + clamp_block(b) +
               nset("TIP", b.nodes_where(lambda x: abs(x[0] - 4.0) < 1e-9)))


@deck("o01_node_print_global")
def _():
    b, mesh = cantilever()
    tip = b.nodes_where(lambda x: abs(x[0] - 4.0) < 1e-9)
    return ("** Deck set o01 (CalculiX manual, *NODE PRINT, GLOBAL=): nodes with a *TRANSFORM "
            "print in their local system by default, globally with GLOBAL=YES.\n" + mesh +
            nset("TURNED", tip[:3]) + "*TRANSFORM, NSET=TURNED, TYPE=R\n0., 1., 0., -1., 0., 0.\n" +
            step("*CLOAD\nTIP, 2, 3.\n",
                 "*NODE PRINT, NSET=TIP\nU\n*NODE PRINT, NSET=TIP, GLOBAL=YES\nU\n"
                 "*NODE PRINT, NSET=FIX, GLOBAL=NO, TOTALS=YES\nRF\n"))


@deck("o02_frequency_and_totals_only")
def _():
    b, mesh = cantilever()
    return ("** Deck set o02 (CalculiX manual, FREQUENCY= and TOTALS=ONLY): sums alone, a step "
            "with FREQUENCY=0 prints nothing and the value carries on.\n" + mesh +
            step("*CLOAD\nTIP, 3, -2.\n", "*NODE PRINT, NSET=FIX, TOTALS=ONLY\nRF\n") +
            "*STEP\n*STATIC\n*CLOAD\nTIP, 2, 1.\n*NODE PRINT, NSET=TIP, FREQUENCY=0\nU\n"
            "*END STEP\n*STEP\n*STATIC\n*CLOAD\nTIP, 1, 1.\n"
            "*NODE PRINT, NSET=TIP, FREQUENCY=1\nU\n*NODE PRINT, NSET=FIX, TOTALS=ONLY\nRF\n"
            "*END STEP\n")


@deck("o03_element_energy_volume_centrif")
def _():
    b, mesh = cantilever(etype="C3D20", n=(2, 1, 1))
    return ("** Deck set o03 (CalculiX manual, *EL PRINT ENER, ELSE, EVOL, CENT): energy "
            "density, element energy and volume with their totals, and the CENTRIF speed.\n" +
            mesh.replace("*ELASTIC\n210000., 0.3\n", "*ELASTIC\n210000., 0.3\n*DENSITY\n7.85E-9\n") +
            step("*CLOAD\nTIP, 3, -2.\n*DLOAD\nEALL, CENTRIF, 1.0E5, 0., 0., 0., 1., 0., 0.\n",
                 "*EL PRINT, ELSET=EALL\nENER\n*EL PRINT, ELSET=EALL, TOTALS=YES\nELSE, EVOL, "
                 "CENT\n*EL PRINT, ELSET=EALL, TOTALS=ONLY\nELSE\n"))


@deck("o04_section_print", tolerance="1e-4",
      note="the section forces integrate the nodal averaged stresses, which differ from ccx's "
           "extrapolated nodal stresses by up to 7e-5 relative at the cut (read from ccx's .frd); "
           "measured 5.6e-5 of the block's largest value")
def _():
    b, mesh = cantilever(n=(4, 2, 2))
    cut = [e for e, (ijk, _) in b.elements.items() if ijk[0] == 1]  # faces at x = 2
    return ("** Deck set o04 (CalculiX manual, *SECTION PRINT SOF, SOM): the force and moment "
            "through a cross-section of a cantilever, from the averaged nodal stresses.\n" + mesh +
            surface("CUT", [(e, "S4") for e in cut]) +
            step("*CLOAD\nTIP, 3, -2.\nTIP, 2, 1.\n",
                 "*SECTION PRINT, SURFACE=CUT, NAME=SP1\nSOF, SOM\n"))


@deck("o05_print_requests_carry_over")
def _():
    b, mesh = cantilever()
    return ("** Deck set o05 (CalculiX manual, *NODE PRINT and *EL PRINT across steps): a step "
            "without print requests repeats the previous step's.\n" + mesh +
            step("*CLOAD\nTIP, 3, -2.\n", "*NODE PRINT, NSET=TIP\nU\n*EL PRINT, ELSET=EALL\nE\n") +
            "*STEP\n*STATIC\n*CLOAD\nTIP, 2, 1.\n*END STEP\n"
            "*STEP\n*STATIC\n*CLOAD\nTIP, 1, 1.\n*NODE PRINT, NSET=FIX\nRF\n*END STEP\n")


@deck("o06_el_print_global_with_orientation")
def _():
    return ("** Deck set o06 (CalculiX manual, *EL PRINT, GLOBAL=YES): stresses of an element with "
            "an *ORIENTATION in global axes, beside the default material axes.\n" +
            uniaxial_block("*MATERIAL, NAME=M\n*ELASTIC\n210000., 0.3\n",
                           extra="*ORIENTATION, NAME=ROT\n0.6, 0.8, 0., -0.8, 0.6, 0.\n",
                           section_extra=", ORIENTATION=ROT",
                           prints="*EL PRINT, ELSET=EALL\nS\n*EL PRINT, ELSET=EALL, GLOBAL=YES\n"
                                  "S, E\n"))


# ----------------------------------------------------------------------------------------------
# Contact laws (issue 15 item 4)


@deck("p01_penalty_linear_nonmatching")
def _():
    lower, upper = two_blocks((2, 2, 1), (3, 3, 1))
    o = upper.origin
    top = upper.nodes_where(lambda x: abs(x[2] - o[2] - 1.0) < 1e-9)
    left = [n for n in top if upper.coords[n][0] < 1.0 - 1e-9]
    right = [n for n in top if upper.coords[n][0] >= 1.0 - 1e-9]
    # Loads small enough (strains ~1e-8) that ccx's contact springs, which it evaluates on the
    # deformed geometry, solve the same linear problem as Styk's to 1e-6.
    return ("** Deck set p01 (CalculiX manual, *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR): a "
            "fine block pressed unevenly onto a coarse one through penalty contact (node to "
            "surface, frictionless).\n" + lower.node_text("NALL") + upper.node_text("NALL") +
            lower.element_text("ELOW") + upper.element_text("EUP") + STEEL +
            "*MATERIAL, NAME=ALU\n*ELASTIC\n70000., 0.33\n"
            "*SOLID SECTION, ELSET=ELOW, MATERIAL=STEEL\n*SOLID SECTION, ELSET=EUP, MATERIAL=ALU\n" +
            surface("LOWERTOP", lower.faces("z1")) + surface("UPPERBOT", upper.faces("z0")) +
            "*SURFACE INTERACTION, NAME=SPRING\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR\n"
            "1.e5, 1.e-12\n*CONTACT PAIR, INTERACTION=SPRING, TYPE=NODE TO SURFACE\n"
            "UPPERBOT, LOWERTOP\n" +
            nset("BASE", lower.nodes_where(lambda x: abs(x[2]) < 1e-9)) +
            nset("UPX0", upper.nodes_where(lambda x: abs(x[0]) < 1e-9)) +
            nset("UPY0", upper.nodes_where(lambda x: abs(x[1]) < 1e-9)) +
            "*BOUNDARY\nBASE, 1, 3\nUPX0, 1\nUPY0, 2\n" + nset("TOPL", left) +
            nset("TOPR", right) + nset("TOP", top) +
            step("*CLOAD\nTOPL, 3, -4.e-4\nTOPR, 3, -1.e-4\n",
                 "*NODE PRINT, NSET=TOP\nU\n*EL PRINT, ELSET=EUP\nS\n"))



@deck("p02_penalty_exponential_nonmatching")
def _():
    lower, upper = two_blocks((2, 2, 1), (3, 3, 1))
    o = upper.origin
    top = upper.nodes_where(lambda x: abs(x[2] - o[2] - 1.0) < 1e-9)
    left = [n for n in top if upper.coords[n][0] < 1.0 - 1e-9]
    right = [n for n in top if upper.coords[n][0] >= 1.0 - 1e-9]
    # p01's blocks under the exponential law (c0 = 1e-5, p0 = 50): the upper block, held in z and
    # its tilts by the contact alone, rests on springs open by 1.9e-6 to 2.2e-6, which its top's
    # displacements show (the .dat reader of the deck set compares U and S). Loads of order 1
    # with E ~1e9 (strains ~3e-8): ccx's springs live on the deformed geometry, and with forces of
    # order 1e-4 (p01's loads) ccx accepts an increment 1e-3 off its own equilibrium.
    return ("** Deck set p02 (CalculiX manual, *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL): "
            "a fine block pressed unevenly onto a coarse one through exponential penalty contact "
            "(node to surface, frictionless).\n" + lower.node_text("NALL") +
            upper.node_text("NALL") + lower.element_text("ELOW") + upper.element_text("EUP") +
            "*MATERIAL, NAME=STIFF\n*ELASTIC\n2.1e9, 0.3\n"
            "*MATERIAL, NAME=STIFFALU\n*ELASTIC\n7.e8, 0.33\n"
            "*SOLID SECTION, ELSET=ELOW, MATERIAL=STIFF\n"
            "*SOLID SECTION, ELSET=EUP, MATERIAL=STIFFALU\n" +
            surface("LOWERTOP", lower.faces("z1")) + surface("UPPERBOT", upper.faces("z0")) +
            "*SURFACE INTERACTION, NAME=SPRING\n"
            "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL\n1.e-5, 50.\n"
            "*CONTACT PAIR, INTERACTION=SPRING, TYPE=NODE TO SURFACE\nUPPERBOT, LOWERTOP\n" +
            nset("BASE", lower.nodes_where(lambda x: abs(x[2]) < 1e-9)) +
            nset("UPX0", upper.nodes_where(lambda x: abs(x[0]) < 1e-9)) +
            nset("UPY0", upper.nodes_where(lambda x: abs(x[1]) < 1e-9)) +
            "*BOUNDARY\nBASE, 1, 3\nUPX0, 1\nUPY0, 2\n" + nset("TOPL", left) +
            nset("TOPR", right) + nset("TOP", top) +
            step("*CLOAD\nTOPL, 3, -4.\nTOPR, 3, -1.\n",
                 "*NODE PRINT, NSET=TOP\nU\n*EL PRINT, ELSET=EUP\nS\n"))

# ----------------------------------------------------------------------------------------------


def main():
    manifest = ["# deck\treference\ttolerance\tcompare\tnote"]
    for name, fn, reference, tolerance, compare, note in DECKS:
        with open(os.path.join(HERE, name + ".inp"), "w") as f:
            f.write(fn())
        manifest.append("\t".join([name + ".inp", reference, tolerance, compare, note]))
    with open(os.path.join(HERE, "manifest.tsv"), "w") as f:
        f.write("\n".join(manifest) + "\n")
    print("wrote %d decks" % len(DECKS))


if __name__ == "__main__":
    main()
