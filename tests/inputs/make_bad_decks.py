#!/usr/bin/env python3
"""Writes the broken decks of tests/inputs/bad/ and their manifest.tsv.

Each deck is the small base model below with one thing broken. The line the error must point at
is marked with '>>' in the text (or the text starts with '@@' for errors about the deck as a whole,
line 0) (the marker is removed when the file is written), so the manifest's
line numbers cannot drift from the decks. manifest.tsv columns:
    deck <TAB> expected exit code of `styk solve` <TAB> expected line (0 = the deck as a whole)
    <TAB> substring the message must contain
Decks named solver_*.inp are valid input that the solver must reject (the reader accepts them):
inverted elements, mechanisms, inconsistent constraints, and features the solver cannot act on
yet.
Run from anywhere: python3 tests/inputs/make_bad_decks.py
"""
import os

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "bad")

NODES = """*NODE, NSET=ALL
1, 0., 0., 0.
2, 1., 0., 0.
3, 1., 1., 0.
4, 0., 1., 0.
5, 0., 0., 1.
6, 1., 0., 1.
7, 1., 1., 1.
8, 0., 1., 1.
"""
ELEMENTS = """*ELEMENT, TYPE=C3D8, ELSET=BLOCK
1, 1, 2, 3, 4, 5, 6, 7, 8
"""
SETS = """*NSET, NSET=FIXED
1, 4, 5, 8
*NSET, NSET=TIP
2, 3, 6, 7
"""
MATERIAL = """*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
"""
SECTION = "*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL\n"
BOUNDARY = "*BOUNDARY\nFIXED, 1, 3\n"
STEP = """*STEP
*STATIC
*CLOAD
TIP, 3, -1.
*NODE PRINT, NSET=TIP
U
*END STEP
"""
BASE = NODES + ELEMENTS + SETS + MATERIAL + SECTION + BOUNDARY + STEP
# Pieces for the steady heat decks.
HEAT_MATERIAL = "*MATERIAL, NAME=STEEL\n*CONDUCTIVITY\n50.\n"
HEAT_STEP = """*STEP
*HEAT TRANSFER, STEADY STATE
*BOUNDARY
FIXED, 11, 11, 100.
TIP, 11, 11, 20.
*NODE PRINT, NSET=TIP
NT
*END STEP
"""
# Pieces for the contact decks: two faces of the block as surfaces, an interaction, a pair.
CONTACT_SURFACES = "*SURFACE, NAME=BOTTOM_FACE\n1, S1\n*SURFACE, NAME=TOP_FACE\nBLOCK, S2\n"
INTERACTION = "*SURFACE INTERACTION, NAME=DRY\n*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=HARD\n" \
              "*FRICTION\n0.2\n"
CONTACT_PAIR = "*CONTACT PAIR, INTERACTION=DRY\nTOP_FACE, BOTTOM_FACE\n"


# Pieces for the beam decks: a two-element B31 frame over nodes 1 -> 2 -> 3 of NODES.
BEAM_ELEMENTS = "*ELEMENT, TYPE=B31, ELSET=FRAME\n1, 1, 2\n2, 2, 3\n"
BEAM_SETS = "*NSET, NSET=FIXED\n1\n*NSET, NSET=TIP\n3\n"
BEAM_SECTION = "*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=RECT\n0.1, 0.2\n"
BEAM_BOUNDARY = "*BOUNDARY\nFIXED, 1, 6\n"
BEAM_STEP = "*STEP\n*STATIC\n*CLOAD\nTIP, 3, -1.\n*END STEP\n"


SHELL_ELEMENTS = "*ELEMENT, TYPE=S4, ELSET=PLATE\n1, 1, 2, 3, 4\n"
SHELL_SETS = "*NSET, NSET=FIXED\n1, 4\n*NSET, NSET=TIP\n2, 3\n"
SHELL_SECTION = "*SHELL SECTION, ELSET=PLATE, MATERIAL=STEEL\n0.01\n"


def shell(**replace):
    """The shell deck (one S4 on the base's bottom face) with parts replaced."""
    parts = dict(ELEMENTS=SHELL_ELEMENTS, SETS=SHELL_SETS, SECTION=SHELL_SECTION,
                 BOUNDARY=BEAM_BOUNDARY, STEP=BEAM_STEP)
    parts.update(replace)
    return base(**parts)


def beam(**replace):
    """The beam deck with parts replaced."""
    parts = dict(ELEMENTS=BEAM_ELEMENTS, SETS=BEAM_SETS, SECTION=BEAM_SECTION,
                 BOUNDARY=BEAM_BOUNDARY, STEP=BEAM_STEP)
    parts.update(replace)
    return base(**parts)


def base(**replace):
    """The base deck with parts replaced: base(STEP='...')."""
    parts = dict(NODES=NODES, ELEMENTS=ELEMENTS, SETS=SETS, MATERIAL=MATERIAL, SECTION=SECTION,
                 BOUNDARY=BOUNDARY, STEP=STEP)
    parts.update(replace)
    return "".join(parts[k] for k in ("NODES", "ELEMENTS", "SETS", "MATERIAL", "SECTION",
                                      "BOUNDARY", "STEP"))


# (deck, description, text with '>>' marking the offending line, exit code, substring)
DECKS = [
    ("unknown_keyword", "a keyword Styk does not read",
     base(SECTION=SECTION + ">>*RIGID BODY, NSET=TIP, REF NODE=1\n"), 1,
     "unknown keyword *RIGID BODY"),
    ("unknown_parameter", "a misspelt parameter",
     base(NODES=NODES.replace("*NODE, NSET=ALL", ">>*NODE, NSETT=ALL")), 1,
     "unknown parameter NSETT on *NODE"),
    ("unknown_element_type", "an element type nobody registered",
     base(ELEMENTS=">>*ELEMENT, TYPE=C3D99, ELSET=BLOCK\n1, 1, 2, 3, 4, 5, 6, 7, 8\n"), 1,
     "unknown element type C3D99"),
    ("wrong_node_count", "a C3D8 with seven nodes",
     base(ELEMENTS="*ELEMENT, TYPE=C3D8, ELSET=BLOCK\n>>1, 1, 2, 3, 4, 5, 6, 7\n"), 1,
     "needs 8 nodes, the data line gives 7"),
    ("missing_node", "an element using a node that is not defined",
     base(ELEMENTS="*ELEMENT, TYPE=C3D8, ELSET=BLOCK\n>>1, 1, 2, 3, 4, 5, 6, 7, 99\n"), 1,
     "node 99 is not defined"),
    ("duplicate_node", "node 3 defined twice",
     base(NODES=NODES + ">>3, 2., 2., 2.\n"), 1, "node 3 is defined twice"),
    ("duplicate_element", "element 1 defined twice",
     base(ELEMENTS=ELEMENTS + ">>1, 1, 2, 3, 4, 5, 6, 7, 8\n"), 1, "element 1 is defined twice"),
    ("repeated_node_in_element", "an element listing one node twice",
     base(ELEMENTS="*ELEMENT, TYPE=C3D8, ELSET=BLOCK\n>>1, 1, 2, 3, 4, 5, 6, 7, 7\n"), 1,
     "appears twice in the connectivity"),
    ("undefined_nset", "a boundary on a node set that does not exist",
     base(BOUNDARY="*BOUNDARY\n>>FIXD, 1, 3\n"), 1, "node set FIXD is not defined"),
    ("undefined_elset", "a section on an element set that does not exist",
     base(SECTION=">>*SOLID SECTION, ELSET=BLOK, MATERIAL=STEEL\n"), 1,
     "element set BLOK, which is not defined"),
    ("undefined_material", "a section naming a material that does not exist",
     base(SECTION=">>*SOLID SECTION, ELSET=BLOCK, MATERIAL=ALUMINIUM\n"), 1,
     "material ALUMINIUM, which is not defined"),
    ("section_without_material", "a section without MATERIAL=",
     base(SECTION=">>*SOLID SECTION, ELSET=BLOCK\n"), 1, "*SOLID SECTION needs MATERIAL="),
    ("material_without_elastic", "a material with a density but no elastic constants",
     base(MATERIAL=">>*MATERIAL, NAME=STEEL\n*DENSITY\n7.85e-9\n"), 1,
     "material STEEL has no *ELASTIC"),
    ("elastic_missing_value", "*ELASTIC with E but no Poisson's ratio",
     base(MATERIAL="*MATERIAL, NAME=STEEL\n*ELASTIC\n>>210000.\n"), 1, "expected E, nu"),
    ("elastic_unknown_type", "an elastic type Styk does not read",
     base(MATERIAL="*MATERIAL, NAME=STEEL\n>>*ELASTIC, TYPE=TRACTION\n1., 1., 1.\n"),
     1, "TYPE=TRACTION is not known"),
    ("elastic_orthotropic_not_definite", "orthotropic constants without a positive definite law",
     base(MATERIAL="*MATERIAL, NAME=STEEL\n*ELASTIC, TYPE=ORTHO\n"
                   ">>1., 1., 1., 1., 1., 1., 1., 1.\n1.\n"),
     1, "do not give a positive definite stiffness"),
    ("poisson_out_of_range", "Poisson's ratio 0.5",
     base(MATERIAL="*MATERIAL, NAME=STEEL\n*ELASTIC\n>>210000., 0.5\n"), 1,
     "Poisson's ratio must lie in (-1, 0.5)"),
    ("negative_thickness", "a negative section thickness",
     base(SECTION=SECTION + ">>-2.\n"), 1, "thickness must be positive"),
    ("zero_thickness", "a zero section thickness",
     base(SECTION=SECTION + ">>0.\n"), 1, "thickness must be positive"),
    ("non_numeric_field", "a coordinate that is not a number",
     base(NODES=NODES.replace("7, 1., 1., 1.", ">>7, 1., 1.0x, 1.")), 1,
     "field 3 (y coordinate): expected a number, read '1.0x'"),
    ("two_exponents", "a number with two exponent letters (one D exponent is read, as CalculiX does)",
     base(MATERIAL="*MATERIAL, NAME=STEEL\n*ELASTIC\n>>2.1D5D1, 0.3\n"), 1,
     "expected a number, read '2.1D5D1'"),
    ("nan_coordinate", "a coordinate that reads as NaN",
     base(NODES=NODES.replace("6, 1., 0., 1.", ">>6, nan, 0., 1.")), 1,
     "expected a finite number, read 'nan'"),
    ("number_out_of_range", "a coordinate beyond the range of a double",
     base(NODES=NODES.replace("6, 1., 0., 1.", ">>6, 1e999, 0., 1.")), 1,
     "out of range for a double"),
    ("negative_node_id", "a node id below 1",
     base(NODES=NODES + ">>-4, 2., 2., 2.\n"), 1, "ids must be positive"),
    ("node_id_beyond_32_bits", "a node id beyond CalculiX's 32-bit ids (docs/input.md \"Ids\")",
     base(NODES=NODES + ">>3000000000, 2., 2., 2.\n"), 1,
     "3000000000 is larger than the largest id, 2147483647"),
    ("element_id_beyond_32_bits", "an element id beyond 32 bits",
     base(ELEMENTS=ELEMENTS + ">>2147483648, 1, 2, 3, 4, 5, 6, 7, 8\n"), 1,
     "2147483648 is larger than the largest id, 2147483647"),
    ("empty_mesh", "materials and a step but no nodes or elements",
     "@@" + MATERIAL + "*STEP\n*STATIC\n*END STEP\n", 1, "the deck defines no nodes"),
    ("no_elements", "nodes but no elements",
     "@@" + NODES + MATERIAL + "*STEP\n*STATIC\n*END STEP\n", 1, "the deck defines no elements"),
    ("no_steps", "a model without an analysis step",
     "@@" + base(STEP=""), 1, "the deck has no analysis step"),
    ("truncated", "a deck that ends inside a step (no *END STEP)",
     base(STEP=">>*STEP\n*STATIC\n*CLOAD\nTIP, 3, -1.\n"), 1, "*END STEP is missing"),
    ("step_inside_step", "a second *STEP before *END STEP",
     base(STEP="*STEP\n*STATIC\n>>*STEP\n*STATIC\n*END STEP\n"), 1, "has no *END STEP"),
    ("step_without_procedure", "a step without *STATIC",
     base(STEP="*STEP\n*CLOAD\nTIP, 3, -1.\n>>*END STEP\n"), 1, "has no procedure"),
    ("nlgeom", "geometric nonlinearity requested",
     base(STEP=">>*STEP, NLGEOM\n*STATIC\n*END STEP\n"), 1,
     "geometric nonlinearity is not supported"),
    ("unknown_solver", "*STATIC, SOLVER= with a name Styk does not know",
     base(STEP="*STEP\n>>*STATIC, SOLVER=MUMPS\n*END STEP\n"), 1, "SOLVER=MUMPS is not known"),
    ("cload_outside_step", "a load in the model part of the deck",
     base(BOUNDARY=BOUNDARY + ">>*CLOAD\nTIP, 3, -1.\n"), 1,
     "*CLOAD is only allowed inside a step"),
    ("node_inside_step", "model data inside a step",
     base(STEP="*STEP\n*STATIC\n>>*NODE\n9, 3., 3., 3.\n*END STEP\n"), 1,
     "*NODE is not allowed inside a step"),
    ("dload_bad_label", "a distributed load type Styk does not read",
     base(STEP="*STEP\n*STATIC\n*DLOAD\n>>BLOCK, BX, 9.81\n*END STEP\n"), 1,
     "load label 'BX' is not supported"),
    ("dof_out_of_range", "a dof beyond the six a node can have",
     base(BOUNDARY="*BOUNDARY\n>>FIXED, 1, 7\n"), 1, "last dof 7 is out of range"),
    ("temperature_dof", "dof 11 (temperature) for every step of a mechanical deck",
     base(BOUNDARY="*BOUNDARY\nFIXED, 1, 3\n>>TIP, 11, 11, 20.\n"), 1,
     "dof 11 (temperature) is prescribed for every step"),
    ("boundary_encastre", "an Abaqus named boundary type",
     base(BOUNDARY="*BOUNDARY\n>>FIXED, ENCASTRE\n"), 1, "ENCASTRE are not supported"),
    ("unknown_output_variable", "a stress request in *NODE PRINT",
     base(STEP="*STEP\n*STATIC\n*NODE PRINT, NSET=TIP\n>>U, S\n*END STEP\n"), 1,
     "output variable 'S' is not supported by *NODE PRINT"),
    ("generate_bad_range", "*NSET, GENERATE with last < first",
     base(SETS=SETS + "*NSET, NSET=MORE, GENERATE\n>>8, 1, 1\n"), 1,
     "last is smaller than first"),
    ("data_before_keyword", "a data line before any keyword",
     "** the next line has no keyword above it\n>>1, 0., 0., 0.\n" + BASE, 1,
     "before the first keyword"),
    ("data_after_dataless_keyword", "data lines under *MATERIAL itself",
     base(MATERIAL="*MATERIAL, NAME=STEEL\n>>210000., 0.3\n*ELASTIC\n210000., 0.3\n"), 1,
     "*MATERIAL takes no data lines"),
    ("elastic_outside_material", "*ELASTIC without *MATERIAL above it",
     base(SECTION=SECTION + ">>*ELASTIC\n1., 0.3\n"), 1, "*ELASTIC must follow *MATERIAL"),
    ("element_without_section", "an element that no section covers",
     base(ELEMENTS=ELEMENTS + "*ELEMENT, TYPE=C3D8\n>>2, 1, 2, 3, 4, 5, 6, 7, 8\n"), 1,
     "element 2 (C3D8) has no section"),
    ("element_in_two_sections", "an element claimed by two sections",
     base(SECTION=SECTION + ">>*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL\n"), 1,
     "already has a section"),
    ("continuation_then_keyword", "a keyword line ending with ',' followed by a keyword",
     base(SETS="*NSET, NSET=FIXED,\n>>*NSET, NSET=TIP\n2, 3, 6, 7\n"), 1,
     "ends with ',' (a continuation)"),
    ("include_missing", "*INCLUDE of a file that does not exist",
     base(SETS=SETS + ">>*INCLUDE, INPUT=no_such_part.inp\n"), 1, "no such file"),
    # Contact, constraints and temperatures (docs/input.md).
    ("contact_unknown_surface", "a contact pair naming a surface that does not exist",
     base(SECTION=SECTION + CONTACT_SURFACES + "*CONTACT PAIR, INTERACTION=DRY\n>>TOP_FACE, BOTOM\n"
          + INTERACTION), 1, "names surface BOTOM, which is not defined"),
    ("surface_face_s7", "a face label a hexahedron does not have",
     base(SECTION=SECTION + "*SURFACE, NAME=TOP_FACE\n>>1, S7\n"), 1,
     "S7 is not a face of element 1 (C3D8 has faces S1..S6)"),
    ("friction_outside_interaction", "*FRICTION without *SURFACE INTERACTION above it",
     base(SECTION=SECTION + ">>*FRICTION\n0.2\n"), 1,
     "*FRICTION must follow *SURFACE INTERACTION"),
    ("friction_anisotropic_without_orientation", "anisotropic friction without its directions",
     base(SECTION=SECTION + "*SURFACE INTERACTION, NAME=DRY\n>>*FRICTION, ANISOTROPIC\n0.1, 0.3\n"),
     1, "ANISOTROPIC needs ORIENTATION="),
    ("friction_rough_with_coefficient", "ROUGH (no slip) with a friction coefficient",
     base(SECTION=SECTION + "*SURFACE INTERACTION, NAME=DRY\n*FRICTION, ROUGH\n>>0.2\n"), 1,
     "ROUGH means no slip at all"),
    ("friction_negative", "a negative friction coefficient",
     base(SECTION=SECTION + "*SURFACE INTERACTION, NAME=DRY\n*FRICTION\n>>-0.2\n"), 1,
     "friction coefficient mu must not be negative"),
    ("clearance_unknown_pair", "*CLEARANCE for a slave/master pair that is not a contact pair",
     base(SECTION=SECTION + CONTACT_SURFACES + INTERACTION + CONTACT_PAIR
          + ">>*CLEARANCE, SLAVE=BOTTOM_FACE, MASTER=TOP_FACE, VALUE=0.01\n"), 1,
     "no *CONTACT PAIR has them"),
    ("contact_print_outside_step", "*CONTACT PRINT in the model part of the deck",
     base(BOUNDARY=BOUNDARY + ">>*CONTACT PRINT\nCSTR\n"), 1,
     "*CONTACT PRINT is only allowed inside a step"),
    ("equation_one_term", "an equation with a single term",
     base(BOUNDARY=BOUNDARY + "*EQUATION\n>>1\n2, 1, 1.\n"), 1,
     "an equation needs at least 2 terms"),
    ("equation_zero_coefficient", "an equation whose dependent term has coefficient 0",
     base(BOUNDARY=BOUNDARY + "*EQUATION\n2\n>>2, 1, 0., 3, 1, 1.\n"), 1,
     "the first coefficient of an equation must not be zero"),
    ("equation_temperature_dof", "an equation on dof 11 (temperature)",
     base(BOUNDARY=BOUNDARY + "*EQUATION\n2\n>>2, 11, 1., 3, 11, -1.\n"), 1,
     "11 (temperature) is not supported yet"),
    ("transform_undefined_nset", "*TRANSFORM on a node set that does not exist",
     base(BOUNDARY=">>*TRANSFORM, NSET=SYMMETRY, TYPE=R\n1., 0., 0., 0., 1., 0.\n" + BOUNDARY), 1,
     "NSET=SYMMETRY of *TRANSFORM is not defined"),
    ("temperature_unknown_node", "a step temperature on a node that does not exist",
     base(STEP="*STEP\n*STATIC\n*TEMPERATURE\nTIP, 100.\n>>99, 100.\n*END STEP\n"), 1,
     "node 99 is not defined"),
    # Beams and *BEAM SECTION (docs/input.md).
    ("beam_section_shape", "a *BEAM SECTION shape Styk does not read",
     beam(SECTION=">>*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=I\n"
                  "0.1, 0.2, 0.1, 0.1, 0.01, 0.01\n"), 1, "SECTION=I is not supported"),
    ("beam_section_dimensions", "a RECT section with one dimension",
     beam(SECTION="*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=RECT\n>>0.1\n"), 1,
     "expected the dimensions of SECTION=RECT (a, b)"),
    ("beam_section_offset", "a beam section offset (CalculiX OFFSET1)",
     beam(SECTION=">>*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=RECT, OFFSET1=0.05\n"
                  "0.1, 0.2\n"), 1, "section offsets are not supported"),
    ("beam_section_on_solid", "a *BEAM SECTION covering a brick",
     base(SECTION=">>*BEAM SECTION, ELSET=BLOCK, MATERIAL=STEEL, SECTION=RECT\n0.1, 0.2\n"), 1,
     "neither a beam nor a shell: it takes a *SOLID SECTION"),
    ("solid_section_on_beam", "a *SOLID SECTION covering beams",
     beam(SECTION=">>*SOLID SECTION, ELSET=FRAME, MATERIAL=STEEL\n"), 1,
     "a beam: it takes a *BEAM SECTION"),
    ("shell_section_orientation", "ORIENTATION= on a *SHELL SECTION",
     shell(SECTION=">>*SHELL SECTION, ELSET=PLATE, MATERIAL=STEEL, ORIENTATION=OR1\n0.01\n"), 1,
     "ORIENTATION= on *SHELL SECTION is not supported"),
    ("shell_section_composite", "a composite *SHELL SECTION",
     shell(SECTION=">>*SHELL SECTION, ELSET=PLATE, MATERIAL=STEEL, COMPOSITE\n0.01\n"), 1,
     "COMPOSITE on *SHELL SECTION is not supported"),
    ("shell_section_points_even", "an even number of section points (Simpson needs odd)",
     shell(SECTION="*SHELL SECTION, ELSET=PLATE, MATERIAL=STEEL\n>>0.01, 4\n"), 1,
     "must be an odd integer from 3 to 15"),
    ("shell_thickness_zero", "a shell thickness of zero",
     shell(SECTION="*SHELL SECTION, ELSET=PLATE, MATERIAL=STEEL\n>>0.\n"), 1,
     "the shell thickness must be positive"),
    ("shell_offset_outside", "a reference surface outside the shell (OFFSET=0.7)",
     shell(SECTION=">>*SHELL SECTION, ELSET=PLATE, MATERIAL=STEEL, OFFSET=0.7\n0.01\n"), 1,
     "the reference surface must lie inside the shell"),
    ("shell_section_on_solid", "a *SHELL SECTION covering a brick",
     base(SECTION=">>*SHELL SECTION, ELSET=BLOCK, MATERIAL=STEEL\n0.01\n"), 1,
     "neither a beam nor a shell: it takes a *SOLID SECTION"),
    ("solid_section_on_shell", "a *SOLID SECTION covering a shell",
     shell(SECTION=">>*SOLID SECTION, ELSET=PLATE, MATERIAL=STEEL\n"), 1,
     "a shell: it takes a *SHELL SECTION"),
    ("shell_pressure_on_solid", "the shell pressure label P on a brick",
     base(STEP="*STEP\n*STATIC\n*DLOAD\n>>BLOCK, P, 1.\n*END STEP\n"), 1,
     "load label P (a shell pressure) on element 1 (C3D8), which is not a shell"),
    ("beam_full_on_reduced_type", "INTEGRATION=FULL on CalculiX's always-reduced B31R",
     beam(ELEMENTS=BEAM_ELEMENTS.replace("B31", "B31R"),
          SECTION=">>*BEAM SECTION, ELSET=FRAME, MATERIAL=STEEL, SECTION=RECT, INTEGRATION=FULL\n"
                  "0.1, 0.2\n"), 1, "whose name fixes reduced integration"),
    ("solver_beam_axis_parallel", "a vertical beam with the default first section axis (0, 0, -1)",
     beam(ELEMENTS="*ELEMENT, TYPE=B31, ELSET=FRAME\n1, 1, 5\n",
          SETS="*NSET, NSET=FIXED\n1\n*NSET, NSET=TIP\n5\n",
          SECTION=">>" + BEAM_SECTION, STEP=BEAM_STEP.replace("TIP, 3", "TIP, 1")), 1,
     "is parallel to the axis of element 1"),
    ("solver_beam_planar_p1", "a line load along axis 1 of a planar beam (out of its plane)",
     beam(ELEMENTS=BEAM_ELEMENTS.replace("B31", "B21"), BOUNDARY="*BOUNDARY\nFIXED, 1, 6\n",
          STEP="*STEP\n*STATIC\n*DLOAD\n>>FRAME, P1, 1.\n*END STEP\n"), 1,
     "P1 has nothing to load"),
    # Valid input the solver cannot act on yet: refused by name and line, never ignored.
    ("solver_contact_iterative", "a contact model asking for the iterative solver",
     base(SECTION=SECTION + CONTACT_SURFACES + INTERACTION + CONTACT_PAIR,
          STEP="*STEP\n>>*STATIC, SOLVER=ITERATIVE CHOLESKY\n*CLOAD\nTIP, 3, -1.\n*END STEP\n"), 1,
     "contact analysis needs the direct solver"),
    ("solver_rotation_on_solid", "rotations (dofs 4-6) at nodes of solid elements only",
     base(BOUNDARY="*BOUNDARY\n>>FIXED, 1, 6\n"), 1, "which carries no rotations"),
    ("solver_equation_prescribed", "an equation eliminating a dof that a step also prescribes",
     base(BOUNDARY=BOUNDARY + "*EQUATION\n>>2\n2, 3, 1., 3, 3, -1.\n",
          STEP="*STEP\n*STATIC\n*BOUNDARY\n2, 3, 3, 0.01\n*END STEP\n"), 1,
     "is eliminated by the constraint equation of this line"),
    ("solver_equation_cycle", "two equations eliminating each other's dof",
     base(BOUNDARY=BOUNDARY + "*EQUATION\n>>2\n2, 3, 1., 3, 3, -1.\n2\n3, 3, 1., 2, 3, -1.\n"),
     1, "depend on each other in a cycle"),
    ("solver_transform_on_axis", "a cylindrical transform whose axis passes through set nodes",
     base(BOUNDARY=">>*TRANSFORM, NSET=FIXED, TYPE=C\n0., 0., 0., 0., 0., 1.\n" + BOUNDARY), 1,
     "lies on the axis: it has no radial direction"),
    ("solver_temperature_no_expansion", "a step temperature on a material without *EXPANSION",
     base(MATERIAL=">>" + MATERIAL,
          STEP="*STEP\n*STATIC\n*CLOAD\nTIP, 3, -1.\n*TEMPERATURE\nTIP, 100.\n*END STEP\n"),
     1, "*EXPANSION (thermal expansion coefficient) is required"),
    ("solver_inverted_element", "an inside-out element: valid input, the solver rejects it",
     base(ELEMENTS="*ELEMENT, TYPE=C3D8, ELSET=BLOCK\n>>1, 5, 6, 7, 8, 1, 2, 3, 4\n"), 1,
     "Jacobian"),
    ("solver_unconstrained", "no boundary conditions: valid input, the solver rejects it",
     "@@" + base(BOUNDARY=""), 1, "free"),
    # Steady heat and electric potential (docs/input.md): scalar and mechanical data kept apart.
    ("heat_missing_conductivity", "a heat step whose material has no *CONDUCTIVITY",
     base(MATERIAL=">>" + MATERIAL, BOUNDARY="", STEP=HEAT_STEP), 1, "has no *CONDUCTIVITY"),
    ("heat_dof_in_static_step", "dof 11 prescribed inside a *STATIC step",
     base(STEP="*STEP\n*STATIC\n*BOUNDARY\n>>TIP, 11, 11, 20.\n*END STEP\n"), 1,
     "dof 11 (temperature) in a *STATIC step"),
    ("heat_transient", "*HEAT TRANSFER without STEADY STATE",
     base(MATERIAL=HEAT_MATERIAL, BOUNDARY="",
          STEP="*STEP\n>>*HEAT TRANSFER\n1., 1.\n*END STEP\n"), 1,
     "transient analysis, which Styk does not solve"),
    ("heat_displacement_dof", "a displacement boundary condition in a heat step",
     base(MATERIAL=HEAT_MATERIAL, BOUNDARY="",
          STEP="*STEP\n*HEAT TRANSFER, STEADY STATE\n*BOUNDARY\n>>FIXED, 1, 3\n*END STEP\n"),
     1, "*HEAT TRANSFER steps take dof 11 (temperature) only"),
    ("heat_cload", "*CLOAD in a heat step",
     base(MATERIAL=HEAT_MATERIAL, BOUNDARY="",
          STEP="*STEP\n*HEAT TRANSFER, STEADY STATE\n*BOUNDARY\nFIXED, 11, 11, 0.\n*CLOAD\n"
               ">>TIP, 3, 1.\n*END STEP\n"), 1, "use *CFLUX"),
    ("heat_cecur", "*CECUR (current) in a heat step",
     base(MATERIAL=HEAT_MATERIAL, BOUNDARY="",
          STEP="*STEP\n*HEAT TRANSFER, STEADY STATE\n*BOUNDARY\nFIXED, 11, 11, 0.\n*CECUR\n"
               ">>TIP, 9, 1.\n*END STEP\n"), 1, "*CECUR in a *HEAT TRANSFER step"),
    ("heat_output_variable", "a stress request in a heat step",
     base(MATERIAL=HEAT_MATERIAL, BOUNDARY="",
          STEP="*STEP\n*HEAT TRANSFER, STEADY STATE\n*BOUNDARY\nFIXED, 11, 11, 0.\n"
               ">>*EL PRINT\nS\n*END STEP\n"), 1, "output variable S in a *HEAT TRANSFER step"),
    ("electric_missing_conductivity", "an electric step whose material has only *CONDUCTIVITY",
     base(MATERIAL=">>" + HEAT_MATERIAL, BOUNDARY="",
          STEP="*STEP\n*COUPLED THERMAL-ELECTRICAL, STEADY STATE\n*BOUNDARY\nFIXED, 9, 9, 0.\n"
               "*END STEP\n"), 1, "has no *ELECTRICAL CONDUCTIVITY"),
    ("solver_heat_after_static", "a heat step after a static step",
     base(MATERIAL=MATERIAL.rstrip("\n") + "\n*CONDUCTIVITY\n50.\n", BOUNDARY="",
          STEP="*STEP\n*STATIC\n*BOUNDARY\nFIXED, 1, 3\n*END STEP\n*STEP\n"
               ">>*HEAT TRANSFER, STEADY STATE\n*BOUNDARY\nFIXED, 11, 11, 0.\n*END STEP\n"), 1,
     "Styk runs decks whose steps are all mechanical"),
    ("solver_heat_unprescribed", "a heat step with no temperature prescribed anywhere",
     base(MATERIAL=HEAT_MATERIAL, BOUNDARY="",
          STEP="*STEP\n>>*HEAT TRANSFER, STEADY STATE\n*CFLUX\nTIP, 11, 1.\n*END STEP\n"), 1,
     "its steady field is determined only up to a constant"),
]


def write(name, description, text):
    whole_deck = text.startswith("@@")
    lines = text[2:].split("\n") if whole_deck else text.split("\n")
    header = [f"** Broken deck: {description}."]
    marked = [i for i, l in enumerate(lines) if l.startswith(">>")]
    assert len(marked) == (0 if whole_deck else 1), name
    line = 0
    if marked:
        lines[marked[0]] = lines[marked[0]][2:]
        line = marked[0] + 1 + len(header)
    with open(os.path.join(HERE, name + ".inp"), "w") as f:
        f.write("\n".join(header + lines))
    return line


def main():
    os.makedirs(HERE, exist_ok=True)
    rows = []
    for name, description, text, code, substring in DECKS:
        line = write(name, description, text)
        rows.append((name + ".inp", code, line, substring))

    # Include cycle: a -> b -> a. Both *INCLUDE lines are line 2, so either deck, read first,
    # reports the cycle at line 2 of the other.
    with open(os.path.join(HERE, "include_cycle_a.inp"), "w") as f:
        f.write("** Broken deck: includes include_cycle_b.inp, which includes this file.\n"
                "*INCLUDE, INPUT=include_cycle_b.inp\n" + BASE)
    with open(os.path.join(HERE, "include_cycle_b.inp"), "w") as f:
        f.write("** Broken deck: includes include_cycle_a.inp, which includes this file.\n"
                "*INCLUDE, INPUT=include_cycle_a.inp\n")
    rows.append(("include_cycle_a.inp", 1, 2, "include cycle"))
    rows.append(("include_cycle_b.inp", 1, 2, "include cycle"))

    # Binary garbage: bytes no text editor would write, NUL on the first line.
    garbage = bytes((i * 37 + 11) % 256 for i in range(512))
    with open(os.path.join(HERE, "binary_garbage.inp"), "wb") as f:
        f.write(b"\x7fELF\x02\x01\x01\x00" + garbage)
    rows.append(("binary_garbage.inp", 1, 1, "not a text line"))

    # An empty file.
    open(os.path.join(HERE, "empty_file.inp"), "w").close()
    rows.append(("empty_file.inp", 1, 0, "the deck defines no nodes"))

    with open(os.path.join(HERE, "manifest.tsv"), "w") as f:
        for row in rows:
            f.write("\t".join(str(x) for x in row) + "\n")


if __name__ == "__main__":
    main()
