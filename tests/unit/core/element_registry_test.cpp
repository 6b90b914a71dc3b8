// ElementRegistry: registration, case-insensitive lookup, duplicates.
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "styk/core/element_registry.hpp"
#include "test_tetrahedron.hpp"

namespace styk {
namespace {

// A second type name for the same test formulation.
class NamedTetrahedron : public test::Tetrahedron4 {
 public:
  explicit NamedTetrahedron(std::string name) : name_(std::move(name)) {}
  std::string name() const override { return name_; }

 private:
  std::string name_;
};

TEST(ElementRegistry, LookupIsCaseInsensitive) {
  ElementRegistry registry;
  registry.add(std::make_unique<test::Tetrahedron4>(), "built-in");
  const TElement* e = registry.find("tet4");
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(e->name(), "TET4");
  EXPECT_EQ(registry.find("Tet4"), e);
  ASSERT_NE(registry.entry("TET4"), nullptr);
  EXPECT_EQ(registry.entry("TET4")->source, "built-in");
  EXPECT_EQ(registry.find("C3D8"), nullptr);
  EXPECT_EQ(registry.entry("C3D8"), nullptr);
}

TEST(ElementRegistry, NamesAreSortedAndUpperCase) {
  ElementRegistry registry;
  registry.add(std::make_unique<NamedTetrahedron>("zeta4"), "a.so");
  registry.add(std::make_unique<NamedTetrahedron>("ALPHA4"), "b.so");
  EXPECT_EQ(registry.names(), (std::vector<std::string>{"ALPHA4", "ZETA4"}));
}

TEST(ElementRegistry, DuplicateThrowsNamingBothSources) {
  ElementRegistry registry;
  registry.add(std::make_unique<test::Tetrahedron4>(), "built-in");
  try {
    registry.add(std::make_unique<NamedTetrahedron>("tet4"), "/opt/plugins/libtet.so");
    FAIL() << "duplicate accepted";
  } catch (const std::invalid_argument& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("TET4"), std::string::npos) << message;
    EXPECT_NE(message.find("/opt/plugins/libtet.so"), std::string::npos) << message;
    EXPECT_NE(message.find("built-in"), std::string::npos) << message;
  }
  EXPECT_EQ(registry.entry("TET4")->source, "built-in");  // the first registration stays
  EXPECT_THROW(registry.add(nullptr, "x"), std::invalid_argument);
}

}  // namespace
}  // namespace styk
