// The Timoshenko beams B21, B22, B31, B31R, B32, B32R one element at a time (docs/elements.md,
// "Beams"): zero-energy modes of every type with both rules (issue 14: eigenvalue counts for every
// new element), rigid-body motions, the constant-state patch tests (stretch, bending, shear,
// torsion) with their section forces and strain energy, consistent line loads, the fibre
// stresses, and the section constants against closed forms (Roark). Expected values are exact;
// the tolerance is round-off (1e-10 relative unless stated).
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "element_fixtures.hpp"
#include "styk/core/beam_section.hpp"
#include "styk/elements/beam.hpp"

namespace styk {
namespace {

constexpr double kPi = 3.14159265358979323846;

const BeamType kTypes[] = {BeamType::B21,  BeamType::B22, BeamType::B31,
                           BeamType::B31R, BeamType::B32, BeamType::B32R};

Material material(double young = 1000.0, double poisson = 0.25) {
  Material m;
  m.name = "STEEL";
  m.young = young;
  m.poisson = poisson;
  m.where = SourceLoc{"beam.inp", 5};
  return m;
}

Section rect_section(double a, double b, const Vec3* direction = nullptr) {
  Section s;
  s.elset = "BEAMS";
  s.material = "STEEL";
  s.where = SourceLoc{"beam.inp", 9};
  s.beam = BeamSection{};
  s.beam->dimensions = {a, b};
  if (direction) {
    s.beam->direction = *direction;
    s.beam->direction_given = true;
  }
  return s;
}

// A straight element from `a` along unit `t` of length L (planar types: in the x-y plane), its
// nodes at equal spacing; `bow` moves a 3-node element's middle node sideways (curved axis).
ElementGeometry geometry(const Beam& beam, const Section& section, const Eigen::Vector3d& a,
                         const Eigen::Vector3d& t, double L,
                         const Eigen::Vector3d& bow = Eigen::Vector3d::Zero()) {
  ElementGeometry g;
  const int n = beam.node_count();
  g.X.resize(n, 3);
  for (int k = 0; k < n; ++k) {
    const double s = (beam.natural_nodes()[k][0] + 1.0) / 2.0 * L;
    g.X.row(k) = (a + s * t).transpose();
  }
  if (n == 3) g.X.row(1) += bow.transpose();
  g.id = 7;
  g.where = SourceLoc{"beam.inp", 20};
  g.section = &section;
  return g;
}

// The element's axis direction for the tests: planar types along x-y, others skew in space.
Eigen::Vector3d axis_of(const Beam& beam) {
  return beam.planar() ? Eigen::Vector3d(3.0, 4.0, 0.0).normalized()
                       : Eigen::Vector3d(2.0, -1.0, 2.0).normalized();
}

std::vector<RuleKind> rules() { return {RuleKind::Full, RuleKind::Reduced}; }

// K restricted to the dofs the type stiffens.
Eigen::MatrixXd active_part(const Beam& beam, const Eigen::MatrixXd& K) {
  std::vector<int> kept;
  for (int k = 0; k < beam.node_count(); ++k)
    for (int d = 0; d < 6; ++d)
      if (beam.active_dofs()[d]) kept.push_back(6 * k + d);
  Eigen::MatrixXd out(kept.size(), kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i)
    for (std::size_t j = 0; j < kept.size(); ++j) out(i, j) = K(kept[i], kept[j]);
  return out;
}

// Nodal dofs of the field (u(x), theta(x)) at the element's nodes.
template <class U, class Theta>
Eigen::VectorXd nodal(const ElementGeometry& g, U u, Theta theta) {
  Eigen::VectorXd out(6 * g.X.rows());
  for (Eigen::Index k = 0; k < g.X.rows(); ++k) {
    const Eigen::Vector3d x = g.X.row(k).transpose();
    out.segment<3>(6 * k) = u(x);
    out.segment<3>(6 * k + 3) = theta(x);
  }
  return out;
}

// Eigenvalue counts: every type with both rules has exactly the rigid motions as zero-energy
// modes (6 in space; 3 in the plane: ux, uy, rz), straight or (3-node) curved: no spurious mode.
TEST(BeamElements, ZeroEnergyModesAreTheRigidMotionsOnly) {
  const Section section = rect_section(0.3, 0.5);
  for (const BeamType type : kTypes) {
    const Beam beam(type);
    for (const RuleKind kind : rules())
      for (const double bow : {0.0, 0.15}) {
        if (bow != 0.0 && beam.node_count() == 2) continue;
        const Eigen::Vector3d side = beam.planar() ? Eigen::Vector3d(-0.8, 0.6, 0.0)
                                                   : Eigen::Vector3d(1.0, 2.0, 0.0).normalized();
        const ElementGeometry g =
            geometry(beam, section, {0.1, 0.2, 0.0}, axis_of(beam), 1.7, bow * side);
        Eigen::MatrixXd K;
        beam.stiffness(g, material(), kind, K);
        ASSERT_EQ(K.rows(), 6 * beam.node_count());
        EXPECT_LT((K - K.transpose()).cwiseAbs().maxCoeff(), 1e-12 * K.cwiseAbs().maxCoeff());
        EXPECT_EQ(test::zero_eigenvalue_count(active_part(beam, K)), beam.planar() ? 3 : 6)
            << beam.name() << (kind == RuleKind::Full ? " full" : " reduced") << " bow " << bow;
      }
  }
}

// Rigid motions u = c + w x x, theta = w give no force on straight and curved elements.
TEST(BeamElements, RigidMotionsAreStressFree) {
  const Section section = rect_section(0.3, 0.5);
  for (const BeamType type : kTypes) {
    const Beam beam(type);
    const Eigen::Vector3d c(0.3, -0.2, beam.planar() ? 0.0 : 0.5);
    const Eigen::Vector3d w =
        beam.planar() ? Eigen::Vector3d(0, 0, 0.7) : Eigen::Vector3d(0.4, -0.3, 0.7);
    for (const RuleKind kind : rules()) {
      const ElementGeometry g = geometry(
          beam, section, {0.1, 0.2, 0.0}, axis_of(beam), 1.7,
          beam.planar() ? Eigen::Vector3d(-0.1, 0.07, 0) : Eigen::Vector3d(0.05, 0.1, -0.02));
      Eigen::MatrixXd K;
      beam.stiffness(g, material(), kind, K);
      const Eigen::VectorXd u = nodal(
          g, [&](const Eigen::Vector3d& x) { return Eigen::Vector3d(c + w.cross(x)); },
          [&](const Eigen::Vector3d&) { return w; });
      EXPECT_LT((K * u).cwiseAbs().maxCoeff(), 1e-10 * K.cwiseAbs().maxCoeff() * u.norm())
          << beam.name();
    }
  }
}

struct State {
  const char* name;
  int resultant;  // 0..5: SF1, SF2, SF3, SM1, SM2, SM3
  double strain;  // the generalised strain imposed
};

// Constant generalised-strain states on a straight skew element: the section force of each state
// is its stiffness times the strain at every station, the others are zero, and the strain energy
// 1/2 u^T K u is 1/2 D e^2 L. Bending is the exact Euler-Bernoulli field u = -k s^2 / 2 n2,
// theta = k s n1, which linear elements with one point (reduced) and every quadratic element
// represent without shear; B21/B31 with full integration show the parasitic shear that locks
// them (SPEC §7.3), asserted separately below.
TEST(BeamElements, ConstantStatesGiveExactSectionForcesAndEnergy) {
  const Section section = rect_section(0.3, 0.5);
  const BeamSectionProperties p = beam_section_properties(*section.beam);
  const double E = 1000.0, G = E / 2.5, L = 1.7;
  const double stiffness[6] = {E * p.area, G * p.shear_area2, G * p.shear_area1,
                               E * p.I11,  E * p.I22,         G * p.J};
  for (const BeamType type : kTypes) {
    const Beam beam(type);
    const Eigen::Vector3d a(0.1, 0.2, 0.0), t = axis_of(beam);
    for (const RuleKind kind : rules()) {
      const ElementGeometry g = geometry(beam, section, a, t, L);
      Eigen::MatrixXd K, forces, moments;
      beam.stiffness(g, material(), kind, K);
      // The element's own section axes (the default first axis (0, 0, -1)).
      Vec3 n1v, n2v;
      ASSERT_TRUE(beam_section_axes({t.x(), t.y(), t.z()}, {0, 0, -1}, n1v, n2v));
      const Eigen::Vector3d n1(n1v[0], n1v[1], n1v[2]), n2(n2v[0], n2v[1], n2v[2]);
      const auto s = [&](const Eigen::Vector3d& x) { return (x - a).dot(t); };
      const double k = 0.02;
      struct Field {
        State state;
        Eigen::VectorXd u;
      };
      std::vector<Field> fields = {
          {{"stretch", 0, k},
           nodal(
               g, [&](auto x) { return Eigen::Vector3d(k * s(x) * t); },
               [&](auto) { return Eigen::Vector3d::Zero().eval(); })},
          {{"shear 2", 1, k},
           nodal(
               g, [&](auto x) { return Eigen::Vector3d(k * s(x) * n2); },
               [&](auto) { return Eigen::Vector3d::Zero().eval(); })},
          {{"bending about 1", 3, k},
           nodal(
               g, [&](auto x) { return Eigen::Vector3d(-0.5 * k * s(x) * s(x) * n2); },
               [&](auto x) { return Eigen::Vector3d(k * s(x) * n1); })}};
      if (!beam.planar()) {
        fields.push_back({{"shear 1", 2, k},
                          nodal(
                              g, [&](auto x) { return Eigen::Vector3d(k * s(x) * n1); },
                              [&](auto) { return Eigen::Vector3d::Zero().eval(); })});
        fields.push_back(
            {{"bending about 2", 4, k},
             nodal(
                 g, [&](auto x) { return Eigen::Vector3d(0.5 * k * s(x) * s(x) * n1); },
                 [&](auto x) { return Eigen::Vector3d(k * s(x) * n2); })});
        fields.push_back({{"torsion", 5, k},
                          nodal(
                              g, [&](auto) { return Eigen::Vector3d::Zero().eval(); },
                              [&](auto x) { return Eigen::Vector3d(k * s(x) * t); })});
      }
      for (const Field& f : fields) {
        const bool bending = f.state.resultant == 3 || f.state.resultant == 4;
        const bool locks =
            bending && beam.node_count() == 2 && kind == RuleKind::Full && type != BeamType::B31R;
        if (locks) continue;  // parasitic shear: see LinearFullIntegrationShowsParasiticShear
        beam.section_resultants(g, material(), kind, f.u, forces, moments);
        ASSERT_EQ(forces.rows(), beam.section_stations(kind));
        for (Eigen::Index st = 0; st < forces.rows(); ++st)
          for (int r = 0; r < 6; ++r) {
            const double value = r < 3 ? forces(st, r) : moments(st, r - 3);
            const double expected = r == f.state.resultant ? stiffness[r] * f.state.strain : 0.0;
            EXPECT_NEAR(value, expected, 1e-9 * stiffness[f.state.resultant] * k)
                << beam.name() << " " << f.state.name << " station " << st << " resultant " << r;
          }
        const double energy = 0.5 * f.u.dot(K * f.u);
        const double exact = 0.5 * stiffness[f.state.resultant] * k * k * L;
        EXPECT_NEAR(energy, exact, 1e-9 * exact) << beam.name() << " " << f.state.name;
      }
    }
  }
}

// The linear elements with full (2-point) integration bend with a shear force they should not
// have: in the exact bending field the shear strain is k (s - L/2) at the Gauss points
// (+-L / (2 sqrt 3) from the middle), the locking SPEC §7.3 Tab 7.1a shows.
TEST(BeamElements, LinearFullIntegrationShowsParasiticShear) {
  const Section section = rect_section(0.3, 0.5);
  const BeamSectionProperties p = beam_section_properties(*section.beam);
  const double G = 400.0, L = 1.7, k = 0.02;
  for (const BeamType type : {BeamType::B21, BeamType::B31}) {
    const Beam beam(type);
    const Eigen::Vector3d a(0.1, 0.2, 0.0), t = axis_of(beam);
    const ElementGeometry g = geometry(beam, section, a, t, L);
    Vec3 n1v, n2v;
    ASSERT_TRUE(beam_section_axes({t.x(), t.y(), t.z()}, {0, 0, -1}, n1v, n2v));
    const Eigen::Vector3d n1(n1v[0], n1v[1], n1v[2]), n2(n2v[0], n2v[1], n2v[2]);
    const auto s = [&](const Eigen::Vector3d& x) { return (x - a).dot(t); };
    const Eigen::VectorXd u = nodal(
        g, [&](auto x) { return Eigen::Vector3d(-0.5 * k * s(x) * s(x) * n2); },
        [&](auto x) { return Eigen::Vector3d(k * s(x) * n1); });
    Eigen::MatrixXd forces, moments;
    beam.section_resultants(g, material(), RuleKind::Full, u, forces, moments);
    ASSERT_EQ(forces.rows(), 2);
    const double offset = L / (2.0 * std::sqrt(3.0));
    EXPECT_NEAR(forces(0, 1), -G * p.shear_area2 * k * offset, 1e-10);
    EXPECT_NEAR(forces(1, 1), G * p.shear_area2 * k * offset, 1e-10);
    EXPECT_NEAR(moments(0, 0), 1000.0 * p.I11 * k, 1e-12);  // the curvature itself is exact
  }
}

// P2 (force per length q along n2) is the consistent load: q L / 2 per node for 2-node elements,
// q L (1/6, 2/3, 1/6) for 3-node elements, no nodal moments; P1 acts along n1. Planar beams refuse
// P1 (their axis 1 is out of plane), naming the remedy.
TEST(BeamElements, LineLoadsAreConsistent) {
  const Section section = rect_section(0.3, 0.5);
  for (const BeamType type : kTypes) {
    const Beam beam(type);
    const Eigen::Vector3d t = axis_of(beam);
    const ElementGeometry g = geometry(beam, section, {0.1, 0.2, 0.0}, t, 1.7);
    Vec3 n1v, n2v;
    ASSERT_TRUE(beam_section_axes({t.x(), t.y(), t.z()}, {0, 0, -1}, n1v, n2v));
    const std::vector<double> share = beam.node_count() == 2
                                          ? std::vector<double>{0.5, 0.5}
                                          : std::vector<double>{1.0 / 6.0, 2.0 / 3.0, 1.0 / 6.0};
    for (const int label : {0, 1}) {
      if (beam.planar() && label == 0) {
        Eigen::VectorXd f;
        EXPECT_THROW(beam.pressure_load(g, 0, 2.0, f), InputError);
        continue;
      }
      const Vec3& n = label == 0 ? n1v : n2v;
      Eigen::VectorXd f;
      beam.pressure_load(g, label, 2.0, f);
      for (int k = 0; k < beam.node_count(); ++k)
        for (int d = 0; d < 3; ++d) {
          EXPECT_NEAR(f(6 * k + d), 2.0 * 1.7 * share[k] * n[d], 1e-12) << beam.name();
          EXPECT_NEAR(f(6 * k + 3 + d), 0.0, 1e-15);
        }
    }
  }
}

// Fibre stresses: pure bending about axis 1 gives S11 = M1 x2 / I11 along the axis at the four
// corners of a RECT section; a torque on a PIPE gives the shear T r / J on the outer fibres, and
// Mises sqrt(3) T r / J there.
TEST(BeamElements, FibreStressesFollowTheSectionForces) {
  const Section rect = rect_section(0.3, 0.5);
  const Beam b31(BeamType::B31);
  const Eigen::Vector3d a(0, 0, 0), t(1, 0, 0);  // n1 = (0, 0, -1), n2 = (0, 1, 0)
  const ElementGeometry g = geometry(b31, rect, a, t, 2.0);
  const double k = 0.01;
  const Eigen::VectorXd bend = nodal(
      g, [&](auto x) { return Eigen::Vector3d(0, -0.5 * k * x.x() * x.x(), 0); },
      [&](auto x) { return Eigen::Vector3d(0, 0, -k * x.x()); });  // theta = k s n1
  Eigen::MatrixXd strain, stress;
  b31.strains_stresses(g, material(), RuleKind::Reduced, bend, strain, stress);
  ASSERT_EQ(stress.rows(), 4);
  const BeamSectionProperties p = beam_section_properties(*rect.beam);
  const double M1 = 1000.0 * p.I11 * k;
  for (int fibre = 0; fibre < 4; ++fibre) {
    const double x2 = p.fibres[fibre][1];
    EXPECT_NEAR(stress(fibre, 0), M1 * x2 / p.I11, 1e-12);  // along t = x
    for (int c = 1; c < 6; ++c) EXPECT_NEAR(stress(fibre, c), 0.0, 1e-12);
    EXPECT_NEAR(strain(fibre, 0), M1 * x2 / p.I11 / 1000.0, 1e-14);
    EXPECT_NEAR(strain(fibre, 1), -0.25 * M1 * x2 / p.I11 / 1000.0, 1e-14);  // -nu eps
  }

  Section pipe = rect;
  pipe.beam->shape = BeamShape::Pipe;
  pipe.beam->dimensions = {0.2, 0.05};
  const ElementGeometry gp = geometry(b31, pipe, a, t, 2.0);
  const double twist = 0.01;
  const Eigen::VectorXd torsion = nodal(
      gp, [&](auto) { return Eigen::Vector3d::Zero().eval(); },
      [&](auto x) { return Eigen::Vector3d(twist * x.x(), 0, 0); });
  b31.strains_stresses(gp, material(), RuleKind::Reduced, torsion, strain, stress);
  const BeamSectionProperties pp = beam_section_properties(*pipe.beam);
  const double tau = 400.0 * pp.J * twist * 0.2 / pp.J;
  for (int fibre = 0; fibre < 4; ++fibre) {
    const Eigen::Vector3d shear(0, stress(fibre, 3), stress(fibre, 4));  // S12, S13
    EXPECT_NEAR(shear.norm(), tau, 1e-12);
    EXPECT_NEAR(stress(fibre, 0), 0.0, 1e-12);
  }
}

// Section constants against closed forms (Roark, Formulas for Stress and Strain, tables of
// section properties and torsion constants): areas and moments of inertia exact; the rectangle's
// torsion constant J = beta a b^3 with beta = 0.1406 (square), 0.229 (2:1), 0.263 (3:1) to the
// table's 3 digits; the ellipse's J = pi a^3 b^3 / (a^2 + b^2) (semi-axes); the thin box by Bredt.
TEST(BeamSections, ConstantsMatchClosedForms) {
  BeamSection s;
  s.dimensions = {2.0, 1.0};  // a = 2 along n1, b = 1 along n2
  BeamSectionProperties p = beam_section_properties(s);
  EXPECT_NEAR(p.area, 2.0, 1e-15);
  EXPECT_NEAR(p.I11, 2.0 / 12.0, 1e-15);
  EXPECT_NEAR(p.I22, 8.0 / 12.0, 1e-15);
  EXPECT_NEAR(p.J / (2.0 * 1.0), 0.229, 0.0005);
  EXPECT_NEAR(p.shear_area2, 5.0 / 3.0, 1e-15);
  s.dimensions = {1.0, 1.0};
  EXPECT_NEAR(beam_section_properties(s).J, 0.1406, 0.00005);
  s.dimensions = {1.0, 3.0};
  EXPECT_NEAR(beam_section_properties(s).J / 3.0, 0.263, 0.0005);

  s.shape = BeamShape::Circ;
  s.dimensions = {2.0};  // a circle of diameter 2
  p = beam_section_properties(s);
  EXPECT_NEAR(p.area, kPi, 1e-14);
  EXPECT_NEAR(p.I11, kPi / 4.0, 1e-14);
  EXPECT_NEAR(p.J, kPi / 2.0, 1e-14);
  s.dimensions = {4.0, 2.0};  // ellipse, semi-axes 2 along n1 and 1 along n2
  p = beam_section_properties(s);
  EXPECT_NEAR(p.area, 2.0 * kPi, 1e-14);
  EXPECT_NEAR(p.I11, kPi * 2.0 / 4.0, 1e-14);
  EXPECT_NEAR(p.I22, kPi * 8.0 / 4.0, 1e-14);
  EXPECT_NEAR(p.J, kPi * 8.0 / 5.0, 1e-14);

  s.shape = BeamShape::Pipe;
  s.dimensions = {1.0, 0.1};
  p = beam_section_properties(s);
  EXPECT_NEAR(p.area, kPi * (1.0 - 0.81), 1e-14);
  EXPECT_NEAR(p.I11, kPi / 4.0 * (1.0 - 0.6561), 1e-14);
  EXPECT_NEAR(p.J, kPi / 2.0 * (1.0 - 0.6561), 1e-14);
  // Cowper at nu = 0: 6 (1 + m^2)^2 / (7 (1 + m^2)^2 + 20 m^2) = 0.50231 at m = r_i / r_o = 0.9
  // (thin-wall limit 1/2).
  EXPECT_NEAR(p.shear_area1 / p.area, 0.50231, 0.00001);

  s.shape = BeamShape::Box;
  s.dimensions = {2.0, 1.0, 0.1, 0.05, 0.1, 0.05};
  p = beam_section_properties(s);
  EXPECT_NEAR(p.area, 2.0 - 1.8 * 0.9, 1e-14);
  EXPECT_NEAR(p.I11, (2.0 - 1.8 * 0.729) / 12.0, 1e-14);
  // Bredt: mid-line box 1.9 x 0.95, J = 4 A_m^2 / (2 (0.95 / 0.1 + 1.9 / 0.05)).
  EXPECT_NEAR(p.J, 4.0 * std::pow(1.9 * 0.95, 2) / (2.0 * (9.5 + 38.0)), 1e-12);
}

// Dimensions are checked with the reason: count, sign, walls that fill the box, unequal walls.
TEST(BeamSections, BadDimensionsAreExplained) {
  BeamSection s;
  s.dimensions = {1.0};
  EXPECT_NE(check_beam_section(s).find("takes 2 dimensions, read 1"), std::string::npos);
  s.dimensions = {1.0, -1.0};
  EXPECT_NE(check_beam_section(s).find("must be positive"), std::string::npos);
  s.shape = BeamShape::Pipe;
  s.dimensions = {1.0, 1.5};
  EXPECT_NE(check_beam_section(s).find("exceeds the outer radius"), std::string::npos);
  s.shape = BeamShape::Box;
  s.dimensions = {1.0, 1.0, 0.6, 0.1, 0.6, 0.1};
  EXPECT_NE(check_beam_section(s).find("leave no hollow"), std::string::npos);
  s.dimensions = {1.0, 1.0, 0.1, 0.1, 0.2, 0.1};
  EXPECT_NE(check_beam_section(s).find("give t1 = t3 and t2 = t4"), std::string::npos);
}

// The default first section axis (0, 0, -1) cannot orient a vertical beam: an error at the section
// line that says how to fix it; planar beams must lie in one z plane.
TEST(BeamElements, UndefinedSectionAxesAreInputErrors) {
  const Section section = rect_section(0.3, 0.5);
  const Beam b31(BeamType::B31);
  const ElementGeometry vertical = geometry(b31, section, {0, 0, 0}, {0, 0, 1}, 2.0);
  Eigen::MatrixXd K;
  try {
    b31.stiffness(vertical, material(), RuleKind::Reduced, K);
    FAIL() << "a vertical beam with the default first axis was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 9);
    EXPECT_NE(e.message().find("is parallel to the axis of element 7"), std::string::npos)
        << e.message();
  }
  const Beam b21(BeamType::B21);
  ElementGeometry tilted = geometry(b21, section, {0, 0, 0}, {1, 0, 0}, 2.0);
  tilted.X(1, 2) = 0.1;
  EXPECT_THROW(b21.stiffness(tilted, material(), RuleKind::Reduced, K), InputError);
}

// Rules: full = nodes Gauss points along the axis, reduced = one fewer; R types reduced always;
// four fibre output points per station.
TEST(BeamElements, StationsAndOutputPoints) {
  for (const BeamType type : kTypes) {
    const Beam beam(type);
    const int n = beam.node_count();
    const bool r_type = beam.name().back() == 'R';
    EXPECT_EQ(beam.section_stations(RuleKind::Full), r_type ? n - 1 : n) << beam.name();
    EXPECT_EQ(beam.section_stations(RuleKind::Reduced), n - 1) << beam.name();
    EXPECT_EQ(beam.rule(RuleKind::Full).size(), 4 * beam.section_stations(RuleKind::Full));
    EXPECT_EQ(beam.node_dofs(), 6);
    EXPECT_EQ(beam.distributed_load_labels(), 2);
    EXPECT_EQ(beam.section_measure(), SectionMeasure::Beam);
  }
  EXPECT_EQ(Beam(BeamType::B21).active_dofs(), (DofSet{true, true, false, false, false, true}));
}

}  // namespace
}  // namespace styk
