// The shaft-hub joint builders spline-joint (SPEC §4.4) and p3g-joint (SPEC §4.5), every element
// family on coarse meshes (the spline's C3D28 also on a finer one): positive Jacobians, conforming
// interior faces (C3D21/C3D28 layers and their C3D20 neighbours included) and C3D28 GLL edges, no
// free nodes, the analytic volume of each body, non-empty sets, the zero-thickness contact
// interface (one-to-one coincident nodes, none shared), the contact face as S1, the torque of the
// rim forces and a deck that reads back; then the SPEC element counts of the default meshes
// (counted, not written), the default C3D28 spline and the parameter errors.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "mesher_checks.hpp"
#include "styk/inp/reader.hpp"
#include "styk/inp/writer.hpp"
#include "styk/mesher/builders.hpp"
#include "styk/mesher/quality.hpp"

namespace styk {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Area of the disc of radius R inside the band |x| <= h, y >= 0: one spline's share of a circle.
double band(double R, double h) { return h * std::sqrt(R * R - h * h) + R * R * std::asin(h / R); }

// SPEC §4.4 straight-sided spline outline (6 splines of width w between the root circle d and the
// tip circle D): the root disc plus six teeth.
double spline_area(double D, double d, double w) {
  return kPi * d * d / 4 + 6 * (band(D / 2, w / 2) - band(d / 2, w / 2));
}

// SPEC §4.5 P3G: the profile is P(v) = r e_r + r' e_theta with r = D/2 - e cos nv, so
// P x P' = r (r + r'') and A = 1/2 int r (r + r'') dv = pi (D^2/4 - (n^2 - 1) e^2 / 2).
double p3g_area(double D, int n, double e) { return kPi * (D * D / 4 - (n * n - 1) * e * e / 2); }

// A boundary curve of a section, by its parameter, and the parameters of its element nodes.
struct Boundary {
  std::function<Vec3(double)> point;
  std::vector<double> nodes;  // element ends, increasing
  double length;              // axial extent
};

// Area 1/2 int (x dy - y dx) along a path, by a fine polygon.
double swept_area(const std::function<Vec3(double)>& path) {
  const int m = 20000;
  double area = 0.0;
  Vec3 a = path(0.0);
  for (int i = 1; i <= m; ++i) {
    const Vec3 b = path(static_cast<double>(i) / m);
    area += 0.5 * (a[0] * b[1] - a[1] * b[0]);
    a = b;
  }
  return area;
}

// Discretisation error of a mesh whose elements are prisms along z: the section's area is what
// the element edges enclose (the full Gauss rule integrates det J exactly), so a body's volume
// differs from the analytic one by the area between each curved boundary and its interpolant
// (linear: the chord; quadratic: the parabola through the end nodes and the mid-edge node at the
// middle parameter) times the axial length. Summed in absolute value: a bound.
double discretisation_bound(const std::vector<Boundary>& boundaries, bool quadratic) {
  double bound = 0.0;
  for (const Boundary& b : boundaries)
    for (std::size_t e = 0; e + 1 < b.nodes.size(); ++e) {
      const double t0 = b.nodes[e], t1 = b.nodes[e + 1];
      const Vec3 p0 = b.point(t0), pm = b.point(0.5 * (t0 + t1)), p1 = b.point(t1);
      const double exact = swept_area([&](double s) { return b.point(t0 + s * (t1 - t0)); });
      const double interpolated = swept_area([&](double s) {
        const double x = 2 * s - 1;
        const double n0 = quadratic ? 0.5 * x * (x - 1) : 0.5 * (1 - x);
        const double nm = quadratic ? 1 - x * x : 0.0;
        const double n1 = quadratic ? 0.5 * x * (x + 1) : 0.5 * (1 + x);
        return Vec3{n0 * p0[0] + nm * pm[0] + n1 * p1[0], n0 * p0[1] + nm * pm[1] + n1 * p1[1], 0};
      });
      bound += std::abs(exact - interpolated) * b.length;
    }
  return bound;
}

Boundary arc(double R, std::vector<double> angles, double length) {
  return {[R](double a) {
            return Vec3{R * std::cos(a), R * std::sin(a), 0};
          },
          std::move(angles), length};
}

// Angles of k equal elements from a0 to a1, continuing `angles` (its last entry is a0).
void add_equal(std::vector<double>& angles, double a0, double a1, int k) {
  if (angles.empty()) angles.push_back(a0);
  for (int i = 1; i <= k; ++i) angles.push_back(a0 + (a1 - a0) * i / k);
}

struct JointCase {
  std::string builder;
  std::string family;
  std::map<std::string, std::string> args;  // coarse mesh
  int contact_faces;                        // per side
  double shaft_volume, hub_volume;          // analytic
  std::vector<Boundary> shaft_curves, hub_curves;
};

std::ostream& operator<<(std::ostream& os, const JointCase& c) {
  os << c.builder << " " << c.family;
  for (const auto& [k, v] : c.args) os << " --" << k << " " << v;
  return os;
}

constexpr double kDeg = kPi / 180;

std::vector<JointCase> cases() {
  std::vector<JointCase> out;
  // Spline, 2 + 2 elements per pitch; the builder's arcs (docs/mesher.md): the root circle in
  // the round part (half grooves, spline roots), the groove bottoms and spline tips over the hub,
  // the hub's tooth tips and groove bottoms, Ø80 (arm) and Ø155 (flange) at equal angles.
  const double D = 67, d = 61.18, w = 12.48, c = 0.1;
  const int tooth = 2, groove = 2;
  const auto flank = [w](double rho) { return std::asin(w / 2 / rho); };
  std::vector<double> root, grooves, tips, hub_tips, hub_grooves, even;
  for (int k = 0; k < 6; ++k) {
    const double m = 60 * k * kDeg, half = 30 * kDeg;
    add_equal(root, m - half, m - flank(d / 2), groove / 2);
    add_equal(root, m - flank(d / 2), m + flank(d / 2), tooth);
    add_equal(root, m + flank(d / 2), m + half, groove / 2);
  }
  std::vector<Boundary> spline_shaft{arc(d / 2, root, 80)}, spline_hub;
  for (int k = 0; k < 6; ++k) {
    const double m = 60 * k * kDeg;
    std::vector<double> g, t, ht, hg;
    add_equal(g, m + flank(d / 2), m + 60 * kDeg - flank(d / 2), groove);
    add_equal(t, m - flank(D / 2), m + flank(D / 2), tooth);
    add_equal(ht, m + flank(d / 2 + c), m + 60 * kDeg - flank(d / 2 + c), groove);
    add_equal(hg, m - flank(D / 2 + c), m + flank(D / 2 + c), tooth);
    spline_shaft.push_back(arc(d / 2, g, 40));
    spline_shaft.push_back(arc(D / 2, t, 40));
    spline_hub.push_back(arc(d / 2 + c, ht, 40));
    spline_hub.push_back(arc(D / 2 + c, hg, 40));
  }
  add_equal(even, 0, 2 * kPi, 6 * (tooth + groove));
  spline_hub.push_back(arc(40, even, 20));
  spline_hub.push_back(arc(77.5, even, 20));
  const double spline_shaft_volume = kPi * d * d / 4 * 80 + spline_area(D, d, w) * 40;
  const double spline_hub_volume =
      kPi * (40 * 40 + 77.5 * 77.5) * 20 - spline_area(D + 2 * c, d + 2 * c, w) * 40;
  // C3D28 (docs/mesher.md): the 0.1 root strip of each spline runs on over the round part to
  // the shaft's end (a ridge of root + c between the flank lines), so the round part's outline is
  // the groove bottoms (120 long) and the ridge tops (80 long).
  std::vector<Boundary> ridged_shaft;
  for (int k = 0; k < 6; ++k) {
    const double m = 60 * k * kDeg;
    std::vector<double> g, r, t;
    add_equal(g, m + flank(d / 2), m + 60 * kDeg - flank(d / 2), groove);
    add_equal(r, m - flank(d / 2 + c), m + flank(d / 2 + c), tooth);
    add_equal(t, m - flank(D / 2), m + flank(D / 2), tooth);
    ridged_shaft.push_back(arc(d / 2, g, 120));
    ridged_shaft.push_back(arc(d / 2 + c, r, 80));
    ridged_shaft.push_back(arc(D / 2, t, 40));
  }
  const double ridges = 6 * (band(d / 2 + c, w / 2) - band(d / 2, w / 2)) * 80;
  const std::map<std::string, std::string> coarse_spline = {
      {"tooth", "2"},       {"groove", "2"},     {"flank-rows", "1"}, {"arm-rows", "1"},
      {"flange-rows", "1"}, {"shaft-rows", "2"}, {"hub-rings", "1"},  {"flange-rings", "2"}};
  for (const char* fam : {"C3D8", "C3D20", "C3D14", "C3D21", "C3D28"}) {
    const bool ridged = std::string(fam) == "C3D28";
    out.push_back({"spline-joint", fam, coarse_spline,
                   12 * 1 * 2,  // 12 flanks x 1 radial row x 2 axial rows
                   spline_shaft_volume + (ridged ? ridges : 0.0), spline_hub_volume,
                   ridged ? ridged_shaft : spline_shaft, spline_hub});
  }
  // A finer C3D28 spline: 4 elements across a spline (the ring under it between the two
  // transitions), 2 core rings, 2 contact rows.
  {
    std::vector<Boundary> shaft4, hub4;
    for (int k = 0; k < 6; ++k) {
      const double m = 60 * k * kDeg;
      std::vector<double> g, r, t, ht, hg;
      add_equal(g, m + flank(d / 2), m + 60 * kDeg - flank(d / 2), 4);
      add_equal(r, m - flank(d / 2 + c), m + flank(d / 2 + c), 4);
      add_equal(t, m - flank(D / 2), m + flank(D / 2), 4);
      add_equal(ht, m + flank(d / 2 + c), m + 60 * kDeg - flank(d / 2 + c), 4);
      add_equal(hg, m - flank(D / 2 + c), m + flank(D / 2 + c), 4);
      shaft4.push_back(arc(d / 2, g, 120));
      shaft4.push_back(arc(d / 2 + c, r, 80));
      shaft4.push_back(arc(D / 2, t, 40));
      hub4.push_back(arc(d / 2 + c, ht, 40));
      hub4.push_back(arc(D / 2 + c, hg, 40));
    }
    std::vector<double> even8;
    add_equal(even8, 0, 2 * kPi, 6 * 8);
    hub4.push_back(arc(40, even8, 20));
    hub4.push_back(arc(77.5, even8, 20));
    out.push_back({"spline-joint",
                   "C3D28",
                   {{"tooth", "4"},
                    {"groove", "4"},
                    {"flank-rows", "2"},
                    {"core-rings", "2"},
                    {"arm-rows", "1"},
                    {"flange-rows", "1"},
                    {"shaft-rows", "2"},
                    {"hub-rings", "1"},
                    {"flange-rings", "2"}},
                   12 * 2 * 2,
                   spline_shaft_volume + ridges,
                   spline_hub_volume,
                   shaft4,
                   hub4});
  }

  // P3G, 24 elements around at equal steps of v; the Ø65 nodes on the rays through the polygon
  // nodes, Ø80 half-way to equal angles, Ø155 at equal angles (docs/mesher.md).
  const auto p3g = [](double v) {
    const double r = 30 - 2.25 * std::cos(3 * v), s = 3 * 2.25 * std::sin(3 * v);
    return Vec3{r * std::cos(v) - s * std::sin(v), r * std::sin(v) + s * std::cos(v), 0};
  };
  const auto polar = [&](double v) {
    const Vec3 q = p3g(v);
    return v + std::atan2(q[1] * std::cos(v) - q[0] * std::sin(v),
                          q[0] * std::cos(v) + q[1] * std::sin(v));
  };
  std::vector<double> v, rays, half_rays;
  add_equal(v, -30 * kDeg, 330 * kDeg, 24);
  for (double x : v) {
    rays.push_back(polar(x));
    half_rays.push_back(x + 0.5 * (polar(x) - x));
  }
  const Boundary polygon{p3g, v, 40};
  const std::vector<Boundary> p3g_shaft{polygon, arc(32.5, rays, 80)};
  const std::vector<Boundary> p3g_hub{polygon, arc(40, half_rays, 20), arc(77.5, v, 20)};
  const double A = p3g_area(60, 3, 2.25);
  const double p3g_shaft_volume = kPi * 32.5 * 32.5 * 80 + A * 40;
  const double p3g_hub_volume = (kPi * 40 * 40 - A) * 20 + (kPi * 77.5 * 77.5 - A) * 20;
  for (const char* fam : {"C3D8", "C3D20", "C3D14", "C3D21", "C3D28"})
    out.push_back({"p3g-joint",
                   fam,
                   {{"around", "24"},
                    {"arm-rows", "1"},
                    {"flange-rows", "1"},
                    {"shaft-rows", "2"},
                    {"hub-rings", "2"},
                    {"flange-rings", "3"}},
                   24 * 2,
                   p3g_shaft_volume,
                   p3g_hub_volume,
                   p3g_shaft,
                   p3g_hub});
  return out;
}

double set_volume(const Model& model, const ElementRegistry& registry, const std::string& elset) {
  Model part = model;
  std::vector<Element> kept;
  for (int e : model.elsets.at(elset).elements) kept.push_back(model.elements[e]);
  part.elements = kept;
  return test::volume(part, registry);
}

// The nodes of a surface's faces (all face nodes of each element's TElement::faces()).
std::set<int> surface_nodes(const Model& model, const ElementRegistry& registry,
                            const Surface& surface) {
  std::set<int> nodes;
  for (const SurfaceFace& f : surface.faces) {
    const TElement& t = *registry.find(model.elements[f.element].type);
    for (int local : t.faces().at(f.face - 1).nodes)
      nodes.insert(model.element_nodes(f.element)[local]);
  }
  return nodes;
}

// Edge conformity of the C3D28 elements, which the face check does not see: an element that
// shares only an edge with a C3D28 (no face) must carry that edge's two GLL nodes too when the
// edge is a bottom edge (C3D28 nodes 17-24, 1-based, on the edges 1-2, 2-3, 3-4, 4-1). Returns the
// number of element pairs that do not.
int gll_edge_mismatches(const Model& model) {
  std::map<std::pair<int, int>, std::vector<int>> by_edge;  // corner pair -> elements with it
  for (int e = 0; e < model.element_count(); ++e) {
    const int* n = model.element_nodes(e);
    for (int i = 0; i < 8; ++i)
      for (int j = i + 1; j < 8; ++j)
        by_edge[{std::min(n[i], n[j]), std::max(n[i], n[j])}].push_back(e);
  }
  static constexpr int kEdge[4][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  int bad = 0;
  for (int e = 0; e < model.element_count(); ++e) {
    if (model.elements[e].type != "C3D28") continue;
    const int* n = model.element_nodes(e);
    for (int k = 0; k < 4; ++k) {
      const int a = n[kEdge[k][0]], b = n[kEdge[k][1]];
      for (int other : by_edge[{std::min(a, b), std::max(a, b)}]) {
        const int* o = model.element_nodes(other);
        const int* end = o + model.elements[other].node_count;
        const bool has =
            std::find(o, end, n[16 + 2 * k]) != end && std::find(o, end, n[17 + 2 * k]) != end;
        bad += has ? 0 : 1;
      }
    }
  }
  return bad;
}

double torque_about_z(const Model& model, const std::vector<ConcentratedLoad>& loads, Vec3* force) {
  double m = 0.0;
  *force = {0, 0, 0};
  for (const ConcentratedLoad& l : loads) {
    const Vec3& x = model.coords[l.node];
    (*force)[l.dof - 1] += l.value;
    if (l.dof == 1) m -= x[1] * l.value;
    if (l.dof == 2) m += x[0] * l.value;
  }
  return m;
}

class JointBuilderTest : public ::testing::TestWithParam<JointCase> {
 protected:
  test::Elements elements_;
};

TEST_P(JointBuilderTest, MeshInterfaceTorqueAndDeck) {
  const JointCase& c = GetParam();
  const ElementRegistry& registry = elements_.registry;
  auto args = c.args;
  args["element"] = c.family;
  const mesher::BuildResult r = mesher::run_builder(c.builder, args, registry);
  const Model& model = r.model;
  SCOPED_TRACE(test::type_counts(model));

  // Jacobians (assess_quality throws naming the element for det J <= 0 at a Gauss point).
  EXPECT_GT(mesher::assess_quality(model, registry).min_jacobian_ratio, 0.0);
  EXPECT_EQ(test::conformity_problem(model, registry), "");
  EXPECT_EQ(gll_edge_mismatches(model), 0);
  EXPECT_EQ(test::free_nodes(model), 0);
  const double shaft = set_volume(model, registry, "SHAFT");
  const double hub = set_volume(model, registry, "HUB");
  const bool quadratic = c.family != "C3D8" && c.family != "C3D14";
  const double shaft_tol = discretisation_bound(c.shaft_curves, quadratic) + 1e-9 * c.shaft_volume;
  const double hub_tol = discretisation_bound(c.hub_curves, quadratic) + 1e-9 * c.hub_volume;
  EXPECT_NEAR(shaft, c.shaft_volume, shaft_tol);
  EXPECT_NEAR(hub, c.hub_volume, hub_tol);
  EXPECT_EQ(model.elsets.at("SHAFT").elements.size() + model.elsets.at("HUB").elements.size(),
            static_cast<std::size_t>(model.element_count()));
  for (const auto& [name, set] : model.nsets) EXPECT_FALSE(set.nodes.empty()) << name;
  for (const auto& [name, set] : model.elsets) EXPECT_FALSE(set.elements.empty()) << name;
  for (const auto& [name, s] : model.surfaces) EXPECT_FALSE(s.faces.empty()) << name;

  // One frictionless pair: hub (slave) on shaft (master), same face count, coincident nodes.
  ASSERT_EQ(model.contact_pairs.size(), 1u);
  const ContactPair& pair = model.contact_pairs[0];
  EXPECT_FALSE(model.surface_interactions.at(pair.interaction).friction.has_value());
  const Surface& slave = model.surfaces.at(pair.slave);
  const Surface& master = model.surfaces.at(pair.master);
  EXPECT_EQ(static_cast<int>(slave.faces.size()), c.contact_faces);
  EXPECT_EQ(static_cast<int>(master.faces.size()), c.contact_faces);
  const std::set<int> a = surface_nodes(model, registry, slave);
  const std::set<int> b = surface_nodes(model, registry, master);
  ASSERT_EQ(a.size(), b.size());
  std::set<int> matched;
  for (int i : a) {
    EXPECT_EQ(b.count(i), 0u) << "node shared by both sides";
    int best = -1;
    double best_distance = 1e300;
    for (int j : b) {
      const Vec3 &p = model.coords[i], &q = model.coords[j];
      const double dist = std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
      if (dist < best_distance) {
        best_distance = dist;
        best = j;
      }
    }
    ASSERT_LT(best_distance, 1e-9 * 155) << "slave node " << model.node_ids[i];
    EXPECT_TRUE(matched.insert(best).second) << "master node matched twice";
  }
  for (const Surface* s : {&slave, &master})
    for (const SurfaceFace& f : s->faces) {
      EXPECT_EQ(model.elements[f.element].type, c.family);
      if (c.family == "C3D21" || c.family == "C3D28") {
        EXPECT_EQ(f.face, 1);
      }
    }

  // Torque 1000 N m = 1e6 N mm about the axis, to 1e-9; no net force (equal to round-off).
  ASSERT_EQ(model.steps.size(), 1u);
  const Step& step = model.steps[0];
  Vec3 force;
  EXPECT_NEAR(torque_about_z(model, step.cloads, &force), 1e6, 1e-9 * 1e6);
  double magnitude = 0.0;
  for (const ConcentratedLoad& l : step.cloads) magnitude += std::abs(l.value);
  for (int dof = 0; dof < 3; ++dof) EXPECT_NEAR(force[dof], 0.0, 1e-12 * magnitude);
  const std::vector<int>& rim = model.nsets.at("FLANGE_RIM").nodes;
  for (const ConcentratedLoad& l : step.cloads)
    EXPECT_TRUE(std::binary_search(rim.begin(), rim.end(), l.node)) << "load off the rim";
  const bool has_contact_print = std::any_of(
      step.outputs.begin(), step.outputs.end(),
      [](const OutputRequest& o) { return o.kind == OutputRequest::Kind::ContactPrint; });
  EXPECT_TRUE(has_contact_print);
  // The fixed shaft end: every node at z = 0 in x, y and z; the hub held axially at one node.
  EXPECT_EQ(model.boundaries.size(), 3 * model.nsets.at("SHAFT_END").nodes.size() + 1);

  const std::string path = ::testing::TempDir() + "joint_" + c.builder + "_" + c.family + ".inp";
  {
    std::ofstream out(path);
    write_inp(model, out);
  }
  const Model back = read_inp(path, registry);
  EXPECT_EQ(back.node_count(), model.node_count());
  EXPECT_EQ(back.element_count(), model.element_count());
  EXPECT_EQ(back.surfaces.size(), model.surfaces.size());
  EXPECT_EQ(back.contact_pairs.size(), 1u);
  EXPECT_EQ(back.boundaries.size(), model.boundaries.size());
  ASSERT_EQ(back.steps.size(), 1u);
  Vec3 back_force;
  EXPECT_NEAR(torque_about_z(back, back.steps[0].cloads, &back_force), 1e6, 1e-9 * 1e6);
  std::remove(path.c_str());
}

INSTANTIATE_TEST_SUITE_P(Spec, JointBuilderTest, ::testing::ValuesIn(cases()));

class JointDefaults : public ::testing::Test {
 protected:
  test::Elements elements_;
};

// SPEC §4.4: 12 000 elements (hub 3500, shaft 8500), 384 C3D21 in contact = 16 per flank side.
// A structured 6-fold mesh has hub and shaft counts divisible by 6: hub 3504, shaft 8496
// (docs/mesher.md); the total and the contact count are exact.
TEST_F(JointDefaults, SplineCountsOfSpec) {
  const auto r = mesher::run_builder("spline-joint", {}, elements_.registry);
  EXPECT_EQ(r.model.element_count(), 12000);
  EXPECT_EQ(r.model.elsets.at("HUB").elements.size(), 3504u);
  EXPECT_EQ(r.model.elsets.at("SHAFT").elements.size(), 8496u);
  EXPECT_EQ(r.model.surfaces.at("HUB_FLANKS").faces.size(), 192u);    // 12 flanks x 16
  EXPECT_EQ(r.model.surfaces.at("SHAFT_FLANKS").faces.size(), 192u);  // 384 in all
  EXPECT_EQ(test::type_counts(r.model), "C3D20:11616 C3D21:384");
}

// SPEC §4.5: 9500 elements (shaft 2587, hub 6913), 576 in contact (288 + 288). Counts of a
// 3-fold structured mesh are multiples of 6: shaft 2592, hub 6912, 9504 (docs/mesher.md).
TEST_F(JointDefaults, P3gCountsOfSpec) {
  const auto r = mesher::run_builder("p3g-joint", {}, elements_.registry);
  EXPECT_EQ(r.model.element_count(), 9504);
  EXPECT_EQ(r.model.elsets.at("SHAFT").elements.size(), 2592u);
  EXPECT_EQ(r.model.elsets.at("HUB").elements.size(), 6912u);
  EXPECT_EQ(r.model.surfaces.at("HUB_BORE").faces.size(), 288u);
  EXPECT_EQ(r.model.surfaces.at("SHAFT_POLYGON").faces.size(), 288u);
}

// Bad densities are input errors naming the parameter.
TEST_F(JointDefaults, BadParametersAreNamed) {
  const auto message = [&](const std::string& builder, std::map<std::string, std::string> args) {
    try {
      mesher::run_builder(builder, args, elements_.registry);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("spline-joint", {{"groove", "5"}}).find("--groove must be even"),
            std::string::npos);
  EXPECT_NE(message("spline-joint", {{"tooth", "1"}}).find("--tooth"), std::string::npos);
  EXPECT_NE(message("spline-joint", {{"clearance", "3"}}).find("--clearance"), std::string::npos);
  EXPECT_NE(message("p3g-joint", {{"around", "40"}}).find("--around must be a multiple of 6"),
            std::string::npos);
  EXPECT_NE(message("p3g-joint", {{"core", "28"}}).find("--core"), std::string::npos);
}

// SPEC §4.4 with C3D28 at the default density: the layers close (conforming, no free nodes,
// positive Jacobians) with SPEC's 384 contact faces, all C3D28 with the contact face as S1. The hub
// keeps its 3504 elements; the shaft's C3D28 section (docs/mesher.md) has 2 elements fewer per
// hexagon side (core 3 x 8 x 8) and per pitch the groove rings 2 x (2 x 3), the ring under the
// spline 1 x 2 and the strip 4: 300 per axial row, plus 6 x 2 x 4 contact-row elements per hub row:
// 22 x 300 + 8 x 48 = 6984 (the C3D21 shaft: 8496).
TEST_F(JointDefaults, SplineC3d28LayersClose) {
  const auto r = mesher::run_builder("spline-joint", {{"element", "C3D28"}}, elements_.registry);
  const Model& model = r.model;
  EXPECT_EQ(test::conformity_problem(model, elements_.registry), "");
  EXPECT_EQ(gll_edge_mismatches(model), 0);
  EXPECT_EQ(test::free_nodes(model), 0);
  EXPECT_GT(mesher::assess_quality(model, elements_.registry).min_jacobian_ratio, 0.0);
  EXPECT_EQ(model.elsets.at("HUB").elements.size(), 3504u);
  EXPECT_EQ(model.elsets.at("SHAFT").elements.size(), 6984u);
  for (const char* name : {"HUB_FLANKS", "SHAFT_FLANKS"}) {
    const Surface& s = model.surfaces.at(name);
    EXPECT_EQ(s.faces.size(), 192u) << name;
    for (const SurfaceFace& f : s.faces) {
      EXPECT_EQ(model.elements[f.element].type, "C3D28");
      EXPECT_EQ(f.face, 1);
    }
  }
}

}  // namespace
}  // namespace styk
