// SourceLoc / InputError formatting and the Model's id bookkeeping.
#include <string>

#include <gtest/gtest.h>

#include "styk/core/diagnostics.hpp"
#include "styk/core/model.hpp"

namespace styk {
namespace {

TEST(Diagnostics, SourceLocFormats) {
  EXPECT_EQ((SourceLoc{"a.inp", 12}).str(), "a.inp:12");
  EXPECT_EQ((SourceLoc{"a.inp", 0}).str(), "a.inp");
  EXPECT_EQ((SourceLoc{"", 3}).str(), "line 3");
  EXPECT_EQ(SourceLoc{}.str(), "");
}

TEST(Diagnostics, InputErrorReadsFileLineMessage) {
  const InputError located(SourceLoc{"a.inp", 12}, "bad card");
  EXPECT_EQ(std::string(located.what()), "a.inp:12: bad card");
  EXPECT_EQ(located.message(), "bad card");
  EXPECT_EQ(located.where().line, 12);
  const InputError unlocated(SourceLoc{}, "no deck");
  EXPECT_EQ(std::string(unlocated.what()), "no deck");
}

TEST(Model, NodeAndElementIdsMapToIndices) {
  Model m;
  EXPECT_EQ(m.add_node(10, Vec3{0, 0, 0}, SourceLoc{"a.inp", 2}), 0);
  EXPECT_EQ(m.add_node(3, Vec3{1, 0, 0}, SourceLoc{"a.inp", 3}), 1);
  EXPECT_EQ(m.node_index(3), 1);
  EXPECT_EQ(m.node_index(4), -1);
  EXPECT_EQ(m.add_element(7, "C3D8", {0, 1}, SourceLoc{"a.inp", 5}), 0);
  EXPECT_EQ(m.element_index(7), 0);
  EXPECT_EQ(m.element_nodes(0)[1], 1);
  EXPECT_EQ(m.elements[0].node_count, 2);
}

TEST(Model, DuplicateIdsAreInputErrorsAtTheRepeatedLine) {
  Model m;
  m.add_node(1, Vec3{0, 0, 0}, SourceLoc{"a.inp", 2});
  try {
    m.add_node(1, Vec3{1, 1, 1}, SourceLoc{"a.inp", 9});
    FAIL() << "duplicate node accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()).rfind("a.inp:9: node 1", 0), 0u) << error.what();
  }
  m.add_element(5, "C3D8", {0}, SourceLoc{"a.inp", 4});
  try {
    m.add_element(5, "C3D8", {0}, SourceLoc{"a.inp", 11});
    FAIL() << "duplicate element accepted";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.rfind("a.inp:11: element 5", 0), 0u) << message;
    EXPECT_NE(message.find("a.inp:4"), std::string::npos) << message;  // where it was first
  }
}

TEST(Model, NamesAreCaseInsensitive) {
  EXPECT_EQ(to_upper("Steel_1x"), "STEEL_1X");
  Model m;
  Material steel;
  steel.name = "STEEL";
  m.materials.push_back(steel);
  EXPECT_EQ(m.material_index("steel"), 0);
  EXPECT_EQ(m.material_index("alu"), -1);
  m.nsets["FIX"] = NodeSet{"FIX", {0}, {}};
  EXPECT_NE(m.find_nset("fix"), nullptr);
  EXPECT_EQ(m.find_elset("fix"), nullptr);
}

}  // namespace
}  // namespace styk
