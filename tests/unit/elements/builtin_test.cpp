// register_builtin_elements: what it provides, and that it goes through the registry rules.
#include <gtest/gtest.h>

#include "styk/elements/builtin.hpp"

namespace styk {
namespace {

TEST(BuiltinElements, RegistersTheSolidPlaneTrussBeamAndShellFamiliesAsBuiltIn) {
  ElementRegistry registry;
  register_builtin_elements(registry);
  EXPECT_EQ(registry.names(),
            (std::vector<std::string>{
                "B21",    "B22",   "B31",   "B31R", "B32",  "B32R",  "C3D10", "C3D15",  "C3D20",
                "C3D20R", "C3D27", "C3D4",  "C3D6", "C3D8", "C3D8I", "C3D8R", "C3D8R0", "CAX4",
                "CAX4R",  "CAX8",  "CAX8R", "CPE4", "CPE8", "CPE8R", "CPS4",  "CPS8",   "CPS8R",
                "S4",     "S4R",   "S8",    "S8R",  "S9",   "S9R",   "STRI3", "T3D2"}));
  const ElementRegistry::Entry* entry = registry.entry("c3d20");
  ASSERT_NE(entry, nullptr);
  EXPECT_EQ(entry->source, "built-in");
  EXPECT_EQ(entry->element->node_count(), 20);
  EXPECT_EQ(entry->element->rule(RuleKind::Full).size(), 27);
  EXPECT_EQ(entry->element->rule(RuleKind::Reduced).size(), 8);
  const TElement* c3d8 = registry.find("C3d8");
  ASSERT_NE(c3d8, nullptr);
  EXPECT_EQ(c3d8->rule(RuleKind::Full).size(), 8);
  EXPECT_EQ(c3d8->face_rule_order(), 2);
  EXPECT_FALSE(c3d8->description().empty());
  for (const std::string& name : registry.names()) {
    const ElementRegistry::Entry* e = registry.entry(name);
    ASSERT_NE(e, nullptr);
    EXPECT_EQ(e->source, "built-in");
    EXPECT_EQ(e->element->name(), name);
    EXPECT_FALSE(e->element->description().empty()) << name;
  }
  EXPECT_EQ(registry.find("C3D8R")->rule(RuleKind::Full).size(), 1);
  EXPECT_EQ(registry.find("C3D20R")->rule(RuleKind::Full).size(), 8);
  EXPECT_EQ(registry.find("C3D27")->node_count(), 27);
  EXPECT_EQ(registry.find("C3D8I")->incompatible_mode_count(), 9);
}

TEST(BuiltinElements, RegisteringTwiceThrowsNamingTheSources) {
  ElementRegistry registry;
  register_builtin_elements(registry);
  try {
    register_builtin_elements(registry);
    FAIL() << "duplicate registration accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("C3D8"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("built-in"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace styk
