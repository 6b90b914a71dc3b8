// read_inp on valid decks: everything the deck says lands in the Model.
#include <gtest/gtest.h>

#include "deck_files.hpp"
#include "fake_elements.hpp"
#include "styk/inp/reader.hpp"

namespace styk {
namespace {

using test::fake_registry;
using test::input_path;
using test::write_deck;

std::vector<Id> element_node_ids(const Model& m, int e) {
  std::vector<Id> ids;
  for (int i = 0; i < m.elements[e].node_count; ++i)
    ids.push_back(m.node_ids[m.element_nodes(e)[i]]);
  return ids;
}

std::vector<Id> nset_ids(const Model& m, const std::string& name) {
  std::vector<Id> ids;
  const NodeSet* set = m.find_nset(name);
  if (set)
    for (int n : set->nodes) ids.push_back(m.node_ids[n]);
  return ids;
}

// Reads `text` as a deck and returns the InputError it raises (fails the test if none).
InputError read_error(const std::string& name, const std::string& text) {
  const ElementRegistry registry = fake_registry();
  try {
    read_inp(write_deck(name, text), registry);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << name << ": no InputError";
  return InputError({}, "");
}

const char* const kMesh = R"(*NODE, NSET=ALL
1, 0., 0., 0.
2, 1., 0., 0.
3, 1., 1., 0.
4, 0., 1., 0.
5, 0., 0., 1.
6, 1., 0., 1.
7, 1., 1., 1.
8, 0., 1., 1.
*ELEMENT, TYPE=C3D8, ELSET=BLOCK
1, 1, 2, 3, 4, 5, 6, 7, 8
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3
*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL
)";

const char* const kStep = R"(*STEP
*STATIC
*END STEP
)";

TEST(ReadInp, C3D8BlockLandsInTheModel) {
  const ElementRegistry registry = fake_registry();
  const std::string path = input_path("good/block_c3d8.inp");
  const Model m = read_inp(path, registry);

  EXPECT_EQ(m.source, path);
  EXPECT_EQ(m.heading, "C3D8 cantilever block, runs unchanged in ccx");
  ASSERT_EQ(m.node_count(), 12);
  const int n12 = m.node_index(12);
  ASSERT_GE(n12, 0);
  EXPECT_EQ(m.coords[n12], (Vec3{2.0, 1.0, 1.0}));
  EXPECT_EQ(m.coords[m.node_index(5)], (Vec3{1.0, 1.0, 0.0}));

  ASSERT_EQ(m.element_count(), 2);
  EXPECT_EQ(m.elements[0].type, "C3D8");
  EXPECT_EQ(m.elements[1].id, 2);
  EXPECT_EQ(element_node_ids(m, 0), (std::vector<Id>{1, 2, 5, 4, 7, 8, 11, 10}));
  EXPECT_EQ(element_node_ids(m, 1), (std::vector<Id>{2, 3, 6, 5, 8, 9, 12, 11}));
  EXPECT_EQ(m.elements[0].where.file, path);
  EXPECT_EQ(m.elements[0].where.line, 18);

  EXPECT_EQ(nset_ids(m, "all").size(), 12u);
  EXPECT_EQ(nset_ids(m, "FIXED"), (std::vector<Id>{1, 4, 7, 10}));
  EXPECT_EQ(nset_ids(m, "Tip"), (std::vector<Id>{3, 6, 9, 12}));
  ASSERT_NE(m.find_elset("BLOCK"), nullptr);
  EXPECT_EQ(m.find_elset("BLOCK")->elements, (std::vector<int>{0, 1}));

  ASSERT_EQ(m.materials.size(), 1u);
  EXPECT_EQ(m.materials[0].name, "STEEL");
  EXPECT_EQ(m.materials[0].young, 210000.0);
  EXPECT_EQ(m.materials[0].poisson, 0.3);
  EXPECT_EQ(m.materials[0].density, 7.85e-9);
  EXPECT_FALSE(m.materials[0].expansion.has_value());
  ASSERT_EQ(m.sections.size(), 1u);
  EXPECT_EQ(m.sections[0].elset, "BLOCK");
  EXPECT_EQ(m.sections[0].material_index, 0);
  EXPECT_FALSE(m.sections[0].thickness.has_value());
  EXPECT_EQ(m.elements[0].section, 0);
  EXPECT_EQ(m.elements[1].section, 0);

  // FIXED, 1, 3: four nodes times three dofs, value 0, in the model part.
  ASSERT_EQ(m.boundaries.size(), 12u);
  EXPECT_EQ(m.node_ids[m.boundaries[0].node], 1);
  EXPECT_EQ(m.boundaries[0].dof, 1);
  EXPECT_EQ(m.boundaries[2].dof, 3);
  EXPECT_EQ(m.boundaries[11].value, 0.0);

  ASSERT_EQ(m.steps.size(), 1u);
  const Step& s = m.steps[0];
  EXPECT_TRUE(s.has_procedure);
  EXPECT_EQ(s.procedure.initial_increment, 1.0);
  EXPECT_EQ(s.procedure.total_time, 1.0);
  EXPECT_EQ(s.procedure.solver, LinearSolverKind::Automatic);
  EXPECT_TRUE(s.boundaries.empty());
  ASSERT_EQ(s.cloads.size(), 4u);
  for (const ConcentratedLoad& c : s.cloads) {
    EXPECT_EQ(c.dof, 3);
    EXPECT_EQ(c.value, -25.0);
  }
  ASSERT_EQ(s.outputs.size(), 3u);
  EXPECT_EQ(s.outputs[0].kind, OutputRequest::Kind::NodePrint);
  EXPECT_EQ(s.outputs[0].set, "TIP");
  EXPECT_EQ(s.outputs[0].vars, (std::vector<std::string>{"U"}));
  EXPECT_FALSE(s.outputs[0].totals);
  EXPECT_TRUE(s.outputs[1].totals);
  EXPECT_EQ(s.outputs[1].vars, (std::vector<std::string>{"RF"}));
  EXPECT_EQ(s.outputs[2].kind, OutputRequest::Kind::ElementPrint);
  EXPECT_EQ(s.outputs[2].set, "BLOCK");
  EXPECT_EQ(s.outputs[2].vars, (std::vector<std::string>{"S", "E"}));
}

TEST(ReadInp, C3D20ConnectivityContinuesOnTheNextLine) {
  const ElementRegistry registry = fake_registry();
  const Model m = read_inp(input_path("good/block_c3d20.inp"), registry);
  ASSERT_EQ(m.element_count(), 2);
  EXPECT_EQ(m.elements[0].node_count, 20);
  const std::vector<Id> first = element_node_ids(m, 0);
  EXPECT_EQ(first.front(), 1);
  EXPECT_EQ(first[14], 42);  // last node on the first line
  EXPECT_EQ(first[15], 36);  // first node on the continuation line
  EXPECT_EQ(first.back(), 26);
  ASSERT_EQ(m.steps.size(), 1u);
  ASSERT_EQ(m.steps[0].dloads.size(), 2u);
  EXPECT_EQ(m.steps[0].dloads[1].element, 1);
  EXPECT_EQ(m.steps[0].dloads[1].face, 2);
  EXPECT_EQ(m.steps[0].dloads[1].magnitude, 1.5);
  ASSERT_EQ(m.steps[0].outputs.size(), 4u);
  EXPECT_EQ(m.steps[0].outputs[2].kind, OutputRequest::Kind::NodeFile);
  EXPECT_EQ(m.steps[0].outputs[3].kind, OutputRequest::Kind::ElementFile);
  EXPECT_EQ(m.steps[0].outputs[3].set, "");
}

TEST(ReadInp, IncludedFilesAreTextualAndRelativeToTheIncluder) {
  const ElementRegistry registry = fake_registry();
  const Model whole = read_inp(input_path("good/block_c3d8.inp"), registry);
  const Model split = read_inp(input_path("good/include_block.inp"), registry);
  EXPECT_EQ(split.node_ids, whole.node_ids);
  EXPECT_EQ(split.coords, whole.coords);
  EXPECT_EQ(split.connectivity, whole.connectivity);
  EXPECT_EQ(nset_ids(split, "ALL").size(), 12u);  // *NODE, NSET=ALL data came from the include
  // Places point into the included file.
  EXPECT_EQ(split.elements[0].where.file, input_path("good/parts/block_elements.inp"));
  EXPECT_EQ(split.elements[0].where.line, 3);
  EXPECT_EQ(split.materials[0].where.file, input_path("good/include_block.inp"));
}

TEST(ReadInp, ErrorsInAnIncludedFileNameThatFile) {
  write_deck("inc_err/sub/part.inp", "** part\n*NODE\n9, 0., 0., zero\n");
  const InputError e =
      read_error("inc_err/main.inp", std::string(kMesh) + "*INCLUDE, INPUT=sub/part.inp\n" + kStep);
  EXPECT_EQ(e.where().file, (test::scratch_dir() / "inc_err/sub/part.inp").string());
  EXPECT_EQ(e.where().line, 3);
  EXPECT_NE(e.message().find("field 4 (z coordinate)"), std::string::npos) << e.what();
}

TEST(ReadInp, IncludeCycleIsReportedWithTheChain) {
  write_deck("cycle/one.inp", "*INCLUDE, INPUT=sub/two.inp\n");
  write_deck("cycle/sub/two.inp", "**\n*INCLUDE, INPUT=../one.inp\n");
  const InputError e = read_error("cycle/main.inp", "*INCLUDE, INPUT=one.inp\n");
  EXPECT_EQ(e.where().line, 2);
  EXPECT_NE(e.message().find("include cycle"), std::string::npos) << e.what();
  EXPECT_NE(e.message().find("two.inp -> "), std::string::npos) << e.what();
}

TEST(ReadInp, KeywordLinesContinueAfterATrailingComma) {
  const std::string deck = R"(*NODE,
   NSET=ALL
1, 0., 0., 0.
2, 1., 0., 0.
3, 1., 1., 0.
4, 0., 1., 0.
5, 0., 0., 1.
6, 1., 0., 1.
7, 1., 1., 1.
8, 0., 1., 1.
*ELEMENT, TYPE=C3D8,
** a comment between a keyword line and its continuation
ELSET=BLOCK
1, 1, 2, 3, 4,
5, 6, 7, 8,
*MATERIAL, NAME=STEEL
*ELASTIC
210000., 0.3,
*SOLID SECTION, ELSET=BLOCK, MATERIAL=STEEL
*STEP
*STATIC
*END STEP
)";
  const ElementRegistry registry = fake_registry();
  const Model m = read_inp(write_deck("continuation.inp", deck), registry);
  EXPECT_EQ(nset_ids(m, "ALL").size(), 8u);
  ASSERT_EQ(m.element_count(), 1);
  EXPECT_EQ(element_node_ids(m, 0), (std::vector<Id>{1, 2, 3, 4, 5, 6, 7, 8}));
  EXPECT_EQ(m.elements[0].where.line, 14);
  EXPECT_EQ(m.find_elset("BLOCK")->elements.size(), 1u);
  EXPECT_EQ(m.materials[0].poisson, 0.3);
}

TEST(ReadInp, KeywordsParametersAndNamesAreCaseInsensitive) {
  const std::string deck = R"(*node, nset=All
1, 0., 0., 0.
2, 1., 0., 0.
3, 1., 1., 0.
4, 0., 1., 0.
5, 0., 0., 1.
6, 1., 0., 1.
7, 1., 1., 1.
8, 0., 1., 1.
*Element, Type=c3d8, Elset=Block
1, 1, 2, 3, 4, 5, 6, 7, 8
*Material, Name=Steel
*elastic, type=isotropic
210000., 0.3
*Solid  Section, elset=BLOCK, material=steel
*boundary
all, 1, 3
*step, name=Load
*static, solver=iterative   cholesky
*cload, op=new
8, 2, 1E+3
*node print, nset=aLL, totals=yes
u, rf
*end step
)";
  const ElementRegistry registry = fake_registry();
  const Model m = read_inp(write_deck("case.inp", deck), registry);
  EXPECT_EQ(m.elements[0].type, "C3D8");
  EXPECT_EQ(m.materials[0].name, "STEEL");
  EXPECT_EQ(m.sections[0].material_index, 0);
  EXPECT_EQ(m.boundaries.size(), 24u);
  ASSERT_EQ(m.steps.size(), 1u);
  EXPECT_EQ(m.steps[0].name, "Load");  // step names keep their case (they are labels)
  EXPECT_EQ(m.steps[0].procedure.solver, LinearSolverKind::Iterative);
  EXPECT_TRUE(m.steps[0].cload_op_new);
  EXPECT_EQ(m.steps[0].cloads[0].value, 1000.0);
  EXPECT_EQ(m.steps[0].outputs[0].set, "ALL");
  EXPECT_EQ(m.steps[0].outputs[0].vars, (std::vector<std::string>{"U", "RF"}));
}

TEST(ReadInp, GenerateAndSetsOfSets) {
  const std::string deck = std::string(kMesh) + R"(*NSET, NSET=ODD, GENERATE
1, 7, 2
*NSET, NSET=LOW, generate
1, 4
*NSET, NSET=BOTH
ODD, LOW, 8,
*NSET, NSET=ODD
8
*ELSET, ELSET=E1, GENERATE
1, 1
*ELSET, ELSET=E2
E1, 1
)" + kStep;
  const ElementRegistry registry = fake_registry();
  const Model m = read_inp(write_deck("generate.inp", deck), registry);
  EXPECT_EQ(nset_ids(m, "LOW"), (std::vector<Id>{1, 2, 3, 4}));
  // A second *NSET of the same name adds to it.
  EXPECT_EQ(nset_ids(m, "ODD"), (std::vector<Id>{1, 3, 5, 7, 8}));
  // BOTH was built before 8 joined ODD.
  EXPECT_EQ(nset_ids(m, "BOTH"), (std::vector<Id>{1, 2, 3, 4, 5, 7, 8}));
  EXPECT_EQ(m.find_elset("E2")->elements, (std::vector<int>{0}));
}

TEST(ReadInp, BoundaryDefaultsAndStepScopes) {
  const std::string deck = std::string(kMesh) + R"(*BOUNDARY
1, 2
2, 1, 3, 0.25
*STEP
*STATIC
0.1, 2., 1e-5, 1.
*BOUNDARY, OP=NEW
3, 3,, -0.5
*END STEP
*STEP
*STATIC, SOLVER=SPOOLES
*DLOAD
BLOCK, p6, 4.
*END STEP
)";
  const ElementRegistry registry = fake_registry();
  const Model m = read_inp(write_deck("scopes.inp", deck), registry);
  ASSERT_EQ(m.boundaries.size(), 4u);
  EXPECT_EQ(m.boundaries[0].dof, 2);
  EXPECT_EQ(m.boundaries[0].value, 0.0);
  EXPECT_EQ(m.boundaries[3].dof, 3);
  EXPECT_EQ(m.boundaries[3].value, 0.25);
  ASSERT_EQ(m.steps.size(), 2u);
  EXPECT_EQ(m.steps[0].procedure.initial_increment, 0.1);
  EXPECT_EQ(m.steps[0].procedure.total_time, 2.0);
  EXPECT_TRUE(m.steps[0].boundary_op_new);
  ASSERT_EQ(m.steps[0].boundaries.size(), 1u);
  EXPECT_EQ(m.steps[0].boundaries[0].value, -0.5);
  EXPECT_EQ(m.steps[1].procedure.solver, LinearSolverKind::Cholmod);
  EXPECT_FALSE(m.steps[1].boundary_op_new);
  ASSERT_EQ(m.steps[1].dloads.size(), 1u);
  EXPECT_EQ(m.steps[1].dloads[0].face, 6);
}

TEST(ReadInp, SolverNamesMapToLinearSolverKinds) {
  const std::pair<const char*, LinearSolverKind> cases[] = {
      {"DEFAULT", LinearSolverKind::Automatic},
      {"CHOLMOD", LinearSolverKind::Cholmod},
      {"SPOOLES", LinearSolverKind::Cholmod},
      {"PARDISO", LinearSolverKind::Cholmod},
      {"AMG", LinearSolverKind::Iterative},
      {"ITERATIVE SCALING", LinearSolverKind::Iterative},
      {"ITERATIVE CHOLESKY", LinearSolverKind::Iterative},
  };
  const ElementRegistry registry = fake_registry();
  for (const auto& [name, kind] : cases) {
    const std::string deck =
        std::string(kMesh) + "*STEP\n*STATIC, SOLVER=" + name + "\n*END STEP\n";
    const Model m = read_inp(write_deck("solver.inp", deck), registry);
    EXPECT_EQ(m.steps[0].procedure.solver, kind) << name;
  }
}

TEST(ReadInp, MaterialAndSetsMayBeDefinedAfterTheSection) {
  const std::string deck = R"(*NODE
1, 0., 0., 0.
2, 1., 0., 0.
3, 1., 1., 0.
4, 0., 1., 0.
5, 0., 0., 1.
6, 1., 0., 1.
7, 1., 1., 1.
8, 0., 1., 1.
*SOLID SECTION, ELSET=LATER, MATERIAL=AL
*ELEMENT, TYPE=C3D8
1, 1, 2, 3, 4, 5, 6, 7, 8
*ELSET, ELSET=LATER
1
*MATERIAL, NAME=AL
*ELASTIC
70000., 0.33
*EXPANSION, ZERO=20.
2.3e-5
)" + std::string(kStep);
  const ElementRegistry registry = fake_registry();
  const Model m = read_inp(write_deck("forward.inp", deck), registry);
  EXPECT_EQ(m.elements[0].section, 0);
  EXPECT_EQ(m.sections[0].material_index, 0);
  EXPECT_EQ(m.materials[0].expansion, 2.3e-5);
  EXPECT_EQ(m.materials[0].expansion_reference, 20.0);
}

TEST(ReadInp, CrLfLineEndsBomAndNoFinalNewline) {
  std::string deck = "\xEF\xBB\xBF" + std::string(kMesh) + kStep;
  std::string crlf;
  for (char c : deck) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  crlf.resize(crlf.size() - 2);  // no line end after *END STEP
  const ElementRegistry registry = fake_registry();
  const Model m = read_inp(write_deck("crlf.inp", crlf), registry);
  EXPECT_EQ(m.node_count(), 8);
  EXPECT_EQ(m.steps.size(), 1u);
}

TEST(ReadInp, UnknownElementTypeListsRegisteredTypesAndPluginPaths) {
  ElementRegistry registry = fake_registry();
  registry.searched_paths = "/opt/styk/plugins";
  const std::string path =
      write_deck("unknown_type.inp", "*NODE\n1, 0, 0, 0\n*ELEMENT, TYPE=C3D14\n1, 1\n");
  try {
    read_inp(path, registry);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 3);
    EXPECT_NE(e.message().find(
                  "unknown element type C3D14; registered types: B21, B31, B31R, C3D20, C3D8, S4"),
              std::string::npos)
        << e.what();
    EXPECT_NE(e.message().find("/opt/styk/plugins"), std::string::npos) << e.what();
  }
}

TEST(ReadInp, UndefinedSetMessageListsExistingSets) {
  const InputError e =
      read_error("undefined_set.inp",
                 std::string(kMesh) + "*NSET, NSET=TOP\n5, 6\n*BOUNDARY\nTPO, 1\n" + kStep);
  EXPECT_EQ(e.where().line, 19);
  EXPECT_NE(e.message().find("node set TPO is not defined; node sets: ALL, TOP"), std::string::npos)
      << e.what();
  EXPECT_EQ(std::string(e.what()), e.where().str() + ": " + e.message());
}

TEST(ReadInp, UnknownParameterNamesTheAcceptedOnes) {
  const InputError e = read_error("unknown_param.inp",
                                  std::string(kMesh) + "*STEP, PERTURBATION\n*STATIC\n*END STEP\n");
  EXPECT_EQ(e.where().line, 16);
  EXPECT_NE(
      e.message().find("unknown parameter PERTURBATION on *STEP (accepted: NAME=, NLGEOM, INC=)"),
      std::string::npos)
      << e.what();
}

TEST(ReadInp, MissingDeckIsAnInputErrorAtLineZero) {
  const ElementRegistry registry = fake_registry();
  try {
    read_inp("/nonexistent/deck.inp", registry);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, "/nonexistent/deck.inp");
    EXPECT_EQ(e.where().line, 0);
    EXPECT_NE(e.message().find("no such file"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace styk
