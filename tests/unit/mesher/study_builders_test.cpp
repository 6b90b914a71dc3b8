// What `styk study` asks of the builders (docs/mesher.md, "Options for the studies"): the other
// hexahedron families (C3D8R, C3D8I, C3D20R, C3D27) wherever the studies mesh, the C3D21/C3D28
// layer on a face that holds every element of a one-element-thick model (--layer), the curved
// beam's radial divisions, the cantilever's distorted meshes, and the shrink fit's thin sector
// (model C). Each mesh: positive Jacobians, conforming faces, no free nodes, the analytic volume.
#include <cmath>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "mesher_checks.hpp"
#include "styk/mesher/builders.hpp"
#include "styk/mesher/quality.hpp"

namespace styk {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Built {
  Model model;
  int of_type = 0;  // elements of the requested family
};

Built build(const ElementRegistry& registry, const std::string& builder,
            std::map<std::string, std::string> args) {
  Built b{mesher::run_builder(builder, args, registry).model};
  for (const Element& e : b.model.elements) b.of_type += e.type == args.at("element");
  return b;
}

void expect_valid(const Built& b, const ElementRegistry& registry, double volume,
                  double tolerance) {
  SCOPED_TRACE(test::type_counts(b.model));
  EXPECT_GT(mesher::assess_quality(b.model, registry).min_jacobian_ratio, 0.0);
  EXPECT_NEAR(test::volume(b.model, registry), volume, tolerance * volume);
  EXPECT_EQ(test::conformity_problem(b.model, registry), "");
  EXPECT_EQ(test::free_nodes(b.model), 0);
}

class StudyBuilders : public ::testing::Test {
 protected:
  test::Elements elements_;
  const ElementRegistry& registry_ = elements_.registry;
};

// Every family, whole mesh: the refinement series' builders (linear families facet the curved
// ones: chord error of 15 deg arcs <= 1.2 %; quadratic ones follow them to 1e-5).
TEST_F(StudyBuilders, EveryHexFamilyMeshesTheStudyModels) {
  const double ring = kPi / 4 * (81 - 9), wall = kPi * (9 - 4),
               curved = kPi / 4 * (4.32 * 4.32 - 4.12 * 4.12) * 0.1;
  for (const char* family : {"C3D8R", "C3D8I", "C3D20R", "C3D27", "C3D21", "C3D28"}) {
    SCOPED_TRACE(family);
    const bool linear = family[3] == '8';
    const double tol = linear ? 0.012 : 1e-5;
    Built b =
        build(registry_, "cantilever", {{"element", family}, {"mesh", "12x2"}, {"layer", "side"}});
    EXPECT_EQ(b.of_type, 24);  // every element, the C3D21/C3D28 layers included
    expect_valid(b, registry_, 150 * 2.5 * 5, 1e-9);
    b = build(registry_, "thick-cylinder",
              {{"element", family}, {"nr", "2"}, {"ntheta", "3"}, {"layer", "bottom"}});
    EXPECT_EQ(b.of_type, 6);
    expect_valid(b, registry_, ring, linear ? 0.05 : 5e-4);  // 30 deg arcs: 4.5 % chords
    b = build(registry_, "curved-beam", {{"element", family}, {"nr", "3"}, {"n", "6"}});
    EXPECT_EQ(b.model.element_count(), 18);
    EXPECT_EQ(b.of_type, 18);
    expect_valid(b, registry_, curved, tol);
    b = build(
        registry_, "cylinder-wall",
        {{"element", family}, {"nr", "2"}, {"ntheta", "24"}, {"nz", "1"}, {"layer", "bottom"}});
    EXPECT_EQ(b.of_type, 48);
    expect_valid(b, registry_, wall, tol);
  }
  for (const char* family : {"C3D8R", "C3D8I", "C3D20R", "C3D27"}) {
    const Built b =
        build(registry_, "cylinders", {{"element", family}, {"nr", "2"}, {"ntheta", "4"}});
    EXPECT_EQ(b.of_type, 16) << family;
    expect_valid(b, registry_, kPi / 4 * (9 - 1), family[3] == '8' ? 0.03 : 5e-4);
  }
}

// C3D27: the face centres are shared (one node per face between two elements) and lie on the
// C3D20 geometry; element centres are their own.
TEST_F(StudyBuilders, C3D27SharesFaceCentres) {
  const Built c20 = build(registry_, "cantilever", {{"element", "C3D20"}, {"mesh", "4x2"}});
  const Built c27 = build(registry_, "cantilever", {{"element", "C3D27"}, {"mesh", "4x2"}});
  // 4 x 1 x 2 elements: faces 5*1*2 + 4*2*2 + 4*1*3 = 38, centres 8.
  EXPECT_EQ(c27.model.node_count(), c20.model.node_count() + 38 + 8);
}

// The cantilever's distortions keep the beam's volume (every grid line turns about mid-height);
// a trapezoid that would close is refused naming the largest angle.
TEST_F(StudyBuilders, DistortedCantileversKeepTheirVolume) {
  for (const char* shape : {"parallelogram", "trapezoid"})
    for (const char* family : {"C3D8", "C3D20", "C3D28"}) {
      SCOPED_TRACE(std::string(shape) + " " + family);
      const Built b = build(registry_, "cantilever",
                            {{"element", family},
                             {"mesh", "10x2"},
                             {"length", "10"},
                             {"height", "1"},
                             {"width", "1"},
                             {"distortion", shape},
                             {"angle", "30"},
                             {"layer", "side"}});
      expect_valid(b, registry_, 10.0, 1e-9);
    }
  try {
    build(registry_, "cantilever",
          {{"element", "C3D8"},
           {"mesh", "10x2"},
           {"length", "10"},
           {"height", "1"},
           {"distortion", "trapezoid"},
           {"angle", "50"}});
    FAIL() << "a closed trapezoid was built";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the angle must stay below 45 degrees"), std::string::npos)
        << e.what();
  }
}

// SPEC §4.2 model C: a sector of --sector elements around, its oblique plane in a node set with a
// cylindrical *TRANSFORM held tangentially, the axis held in x and y; no torque.
TEST_F(StudyBuilders, ShrinkFitSectorHasItsSymmetryPlanes) {
  const std::map<std::string, std::string> coarse = {
      {"element", "C3D21"},  {"model", "C"},         {"load-case", "fit"},
      {"around", "4"},       {"sector-around", "2"}, {"shaft-rings", "2"},
      {"sleeve-rings", "2"}, {"fit-rows", "4"},      {"end-rows", "2"}};
  const Built b = build(registry_, "shrink-fit", coarse);
  // Shaft per row: core 1 + two rings of 2 x 1 = 5, x (2 + 4 + 2) rows; sleeve 2 x 2 x 4.
  EXPECT_EQ(b.model.element_count(), 5 * 8 + 16);
  const double shaft = kPi * 100 * 60 / 8, sleeve = kPi * (225 - 100) * 20 / 8;
  expect_valid(b, registry_, shaft + sleeve, 1e-4);
  ASSERT_EQ(b.model.transforms.size(), 1u);
  EXPECT_EQ(b.model.transforms[0].nset, "SECTOR_PLANE");
  const NodeSet* plane = b.model.find_nset("SECTOR_PLANE");
  ASSERT_NE(plane, nullptr);
  for (int n : plane->nodes) {
    const Vec3& x = b.model.coords[n];
    EXPECT_NEAR(std::atan2(x[1], x[0]), kPi / 4, 1e-9);
  }
  ASSERT_EQ(b.model.steps.size(), 1u);  // --load-case fit: the heating step alone
  std::map<std::string, std::string> torque = coarse;
  torque["load-case"] = "torque";
  EXPECT_THROW(build(registry_, "shrink-fit", torque), InputError);
  std::map<std::string, std::string> odd = coarse;
  odd["sector"] = "3";
  EXPECT_THROW(build(registry_, "shrink-fit", odd), InputError);
}

// The notched variants' settings that cannot be meshed are refused by name: a groove as wide as
// the wall, grooves that meet in the middle (coarse: 4 fit rows of 5, a 10 deep groove takes 2
// at each end), a relief deeper than the wall, and variant II with a load on the outer circle
// its turned-down end no longer has.
TEST_F(StudyBuilders, ShrinkFitNotchBadValuesAreNamed) {
  const std::map<std::string, std::string> coarse = {
      {"element", "C3D21"}, {"model", "A"},        {"load-case", "fit"}, {"around", "4"},
      {"shaft-rings", "2"}, {"sleeve-rings", "2"}, {"fit-rows", "4"},    {"end-rows", "2"}};
  auto fails = [&](std::map<std::string, std::string> extra, const std::string& needle) {
    std::map<std::string, std::string> args = coarse;
    for (const auto& [k, v] : extra) args[k] = v;
    try {
      build(registry_, "shrink-fit", args);
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
      return;
    }
    ADD_FAILURE() << "no error for " << needle;
  };
  fails({{"notch", "III"}}, "--notch");
  fails({{"notch", "I"}, {"groove-width", "4"}}, "--groove-lip + --groove-width");
  fails({{"notch", "I"}, {"groove-depth", "10"}}, "--groove-depth 10 takes 2 of the 4 fit rows");
  fails({{"notch", "II"}, {"relief-depth", "5"}}, "--relief-depth");
  fails({{"notch", "II"}, {"model", "B"}, {"load-case", "rotation"}}, "--notch II");
  std::map<std::string, std::string> one = coarse;
  one["notch"] = "I";
  // Shaft: core 2 x 2 + two rings of 2 x 2 = 12 per row, 2 + 4 + 2 rows; sleeve (groove 1 of the
  // 4 rows at each end): lip 4 x 4, groove 4 x 2, outer ring (at least 1) 4 x 4.
  EXPECT_EQ(build(registry_, "shrink-fit", one).model.element_count(), 12 * 8 + 16 + 8 + 16);
}

}  // namespace
}  // namespace styk
