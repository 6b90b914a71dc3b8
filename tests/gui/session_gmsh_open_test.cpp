// The desktop program opens Gmsh meshes (File > Open, *.msh) as `styk import` reads them: the
// document's model is the imported mesh with its physical groups as sets; a bad mesh leaves the
// document as it was.
#include <gtest/gtest.h>

#include <string>

#include "session/document.hpp"
#include "styk/core/plugin_loader.hpp"
#include "styk/elements/element_setup.hpp"

namespace styk::gui {
namespace {

std::string fixture(const std::string& name) {
  return std::string(STYK_SOURCE_DIR) + "/tests/inputs/gmsh/" + name;
}

TEST(SessionGmshOpen, OpensAMeshWithItsPhysicalGroupsAsSets) {
  PluginLibraries libraries;
  ElementRegistry registry;
  setup_element_registry(registry, libraries, {});
  Document document(registry);
  document.open_msh(fixture("tet10_v41.msh"), {});
  EXPECT_EQ(document.path(), fixture("tet10_v41.msh"));
  ASSERT_EQ(document.model().element_count(), 1);
  EXPECT_EQ(document.model().elements[0].type, "C3D10");
  EXPECT_TRUE(document.model().find_nset("BASE"));
  EXPECT_TRUE(document.model().find_elset("BODY"));
  EXPECT_EQ(gmsh_mesh_dimension(fixture("surface_v41.msh")), 2);
  GmshImportOptions shells;
  shells.planar = PlanarElements::Shell;
  document.open_msh(fixture("surface_v41.msh"), shells);
  EXPECT_EQ(document.model().element_count(), 4);
  // A pyramid is refused at its line; the document keeps the shells.
  try {
    document.open_msh(fixture("pyramid_v22.msh"), {});
    FAIL() << "a pyramid opened";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 15);
  }
  EXPECT_EQ(document.model().element_count(), 4);
}

}  // namespace
}  // namespace styk::gui
