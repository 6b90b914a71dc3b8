// STRI3, the flat discrete-Kirchhoff (DKT) thin shell triangle (docs/elements.md, "STRI3"), one
// element and one patch at a time: its zero-energy modes (exactly the six rigid motions, flat and
// tilted in space; issue 14: eigenvalue counts for every new element), the membrane and the
// constant-curvature bending patch tests on MacNeal and Harder's patch (1985: 0.24 x 0.12,
// E = 1e6, nu = 0.25, t = 0.001; its five quadrilaterals split into ten triangles) in the x-y
// plane and tilted in space, with their stresses and section forces, and the pressure load.
// Exact states are asserted to round-off (1e-9 relative unless stated).
#include <array>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "styk/elements/stri3.hpp"

namespace styk {
namespace {

constexpr double kE = 1e6, kNu = 0.25, kT = 0.001;

Material material() {
  Material m;
  m.name = "M";
  m.young = kE;
  m.poisson = kNu;
  m.where = SourceLoc{"stri3.inp", 5};
  return m;
}

Section shell_section(double thickness) {
  Section s;
  s.elset = "PLATE";
  s.material = "M";
  s.where = SourceLoc{"stri3.inp", 9};
  s.thickness = thickness;
  s.shell = ShellSection{};
  return s;
}

ElementGeometry geometry(const Section& section, const std::array<Eigen::Vector3d, 3>& x) {
  ElementGeometry g;
  g.X.resize(3, 3);
  for (int a = 0; a < 3; ++a) g.X.row(a) = x[a].transpose();
  g.id = 7;
  g.where = SourceLoc{"stri3.inp", 20};
  g.section = &section;
  g.cross_section = *section.thickness;
  return g;
}

// A rotation that tilts the x-y plane in space (no axis of it stays global).
Eigen::Matrix3d tilt() {
  return Eigen::AngleAxisd(0.4, Eigen::Vector3d(1.0, 2.0, 0.5).normalized()).toRotationMatrix();
}

int zero_modes(const Eigen::MatrixXd& K) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(K);
  const double largest = eig.eigenvalues().cwiseAbs().maxCoeff();
  int zeros = 0;
  for (Eigen::Index k = 0; k < eig.eigenvalues().size(); ++k)
    zeros += std::abs(eig.eigenvalues()(k)) < 1e-9 * largest ? 1 : 0;
  return zeros;
}

TEST(Stri3, ZeroEnergyModesAreTheSixRigidMotions) {
  const Stri3 element;
  const Section section = shell_section(0.05);
  for (const bool tilted : {false, true}) {
    const Eigen::Matrix3d R = tilted ? tilt() : Eigen::Matrix3d::Identity();
    const ElementGeometry g =
        geometry(section, {R * Eigen::Vector3d(0.1, 0.2, 0.0), R * Eigen::Vector3d(1.3, 0.1, 0.0),
                           R * Eigen::Vector3d(0.5, 0.9, 0.0)});
    for (const RuleKind kind : {RuleKind::Full, RuleKind::Reduced}) {
      Eigen::MatrixXd K;
      element.stiffness(g, material(), kind, K);
      ASSERT_EQ(K.rows(), 18);
      EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
      EXPECT_EQ(zero_modes(K), 6) << (tilted ? "tilted" : "flat");
      Eigen::MatrixXd modes = Eigen::MatrixXd::Zero(18, 6);
      for (int a = 0; a < 3; ++a)
        for (int k = 0; k < 3; ++k) {
          modes(6 * a + k, k) = 1.0;
          const Eigen::Vector3d omega = Eigen::Vector3d::Unit(k);
          modes.block<3, 1>(6 * a, 3 + k) = omega.cross(Eigen::Vector3d(g.X.row(a).transpose()));
          modes.block<3, 1>(6 * a + 3, 3 + k) = omega;
        }
      EXPECT_LT((K * modes).norm(), 1e-9 * K.norm() * modes.norm());
    }
  }
}

// MacNeal and Harder's patch, each quadrilateral split along its diagonal from its first corner.
struct Patch {
  std::vector<Eigen::Vector3d> x;
  std::vector<std::array<int, 3>> elements;
  std::vector<bool> boundary;
};

Patch patch(const Eigen::Matrix3d& R) {
  Patch p;
  p.x = {{0, 0, 0},       {0.24, 0, 0},    {0.24, 0.12, 0}, {0, 0.12, 0},
         {0.04, 0.02, 0}, {0.18, 0.03, 0}, {0.16, 0.08, 0}, {0.08, 0.08, 0}};
  const int quads[5][4] = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}, {4, 5, 6, 7}};
  for (const auto& q : quads) {
    p.elements.push_back({q[0], q[1], q[2]});
    p.elements.push_back({q[0], q[2], q[3]});
  }
  for (Eigen::Vector3d& x : p.x) {
    p.boundary.push_back(p.boundary.size() < 4);
    x = R * x;
  }
  return p;
}

ElementGeometry element_geometry(const Section& section, const Patch& p, std::size_t e) {
  return geometry(section, {p.x[p.elements[e][0]], p.x[p.elements[e][1]], p.x[p.elements[e][2]]});
}

Eigen::VectorXd element_dofs(const Patch& p, std::size_t e, const Eigen::VectorXd& u) {
  Eigen::VectorXd ue(18);
  for (int a = 0; a < 3; ++a) ue.segment<6>(6 * a) = u.segment<6>(6 * p.elements[e][a]);
  return ue;
}

// A field given in the patch's plane coordinates (6 local dofs), turned into global dofs.
using Field = Eigen::Matrix<double, 6, 1> (*)(const Eigen::Vector3d&);
Eigen::Matrix<double, 6, 1> global_field(Field f, const Eigen::Matrix3d& R,
                                         const Eigen::Vector3d& x) {
  const Eigen::Matrix<double, 6, 1> local = f(R.transpose() * x);
  Eigen::Matrix<double, 6, 1> u;
  u << R * local.head<3>(), R * local.tail<3>();
  return u;
}

// Solves the patch with the exact field on the outer corners' boundary and returns the nodes'
// solution (6 per node).
Eigen::VectorXd solve_patch(const Section& section, const Patch& p, Field field,
                            const Eigen::Matrix3d& R) {
  const Stri3 element;
  const int dofs = 6 * static_cast<int>(p.x.size());
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(dofs, dofs);
  for (std::size_t e = 0; e < p.elements.size(); ++e) {
    Eigen::MatrixXd Ke;
    element.stiffness(element_geometry(section, p, e), material(), RuleKind::Full, Ke);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        K.block<6, 6>(6 * p.elements[e][a], 6 * p.elements[e][b]) += Ke.block<6, 6>(6 * a, 6 * b);
  }
  Eigen::VectorXd u = Eigen::VectorXd::Zero(dofs);
  std::vector<int> free;
  for (std::size_t n = 0; n < p.x.size(); ++n) {
    if (p.boundary[n])
      u.segment<6>(6 * n) = global_field(field, R, p.x[n]);
    else
      for (int k = 0; k < 6; ++k) free.push_back(6 * static_cast<int>(n) + k);
  }
  const Eigen::VectorXd f = -K * u;
  Eigen::MatrixXd Kff(free.size(), free.size());
  Eigen::VectorXd ff(free.size());
  for (std::size_t i = 0; i < free.size(); ++i) {
    ff(i) = f(free[i]);
    for (std::size_t j = 0; j < free.size(); ++j) Kff(i, j) = K(free[i], free[j]);
  }
  const Eigen::VectorXd uf = Kff.ldlt().solve(ff);
  for (std::size_t i = 0; i < free.size(); ++i) u(free[i]) = uf(i);
  return u;
}

// Membrane: u = 1e-3 (x + y / 2), v = 1e-3 (y + x / 2) (no in-plane rotation).
Eigen::Matrix<double, 6, 1> membrane_field(const Eigen::Vector3d& x) {
  Eigen::Matrix<double, 6, 1> u = Eigen::Matrix<double, 6, 1>::Zero();
  u(0) = 1e-3 * (x(0) + x(1) / 2.0);
  u(1) = 1e-3 * (x(1) + x(0) / 2.0);
  return u;
}

// Constant curvature: w = 1e-3 (x^2 + x y + y^2) / 2, rx = w,y, ry = -w,x.
Eigen::Matrix<double, 6, 1> bending_field(const Eigen::Vector3d& x) {
  Eigen::Matrix<double, 6, 1> u = Eigen::Matrix<double, 6, 1>::Zero();
  u(2) = 1e-3 * (x(0) * x(0) + x(0) * x(1) + x(1) * x(1)) / 2.0;
  u(3) = 1e-3 * (x(0) / 2.0 + x(1));
  u(4) = -1e-3 * (x(0) + x(1) / 2.0);
  return u;
}

void expect_exact(const Patch& p, const Eigen::VectorXd& u, Field field, const Eigen::Matrix3d& R,
                  double tolerance) {
  for (std::size_t n = 0; n < p.x.size(); ++n) {
    const Eigen::Matrix<double, 6, 1> e = global_field(field, R, p.x[n]);
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(u(6 * n + k), e(k), tolerance) << n << " dof " << k;
  }
}

TEST(Stri3, MembranePatchTestIsExact) {
  const Stri3 element;
  const Section section = shell_section(kT);
  const double c = kE / (1.0 - kNu * kNu), G = kE / (2.0 * (1.0 + kNu));
  const Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  const Patch p = patch(R);
  const Eigen::VectorXd u = solve_patch(section, p, membrane_field, R);
  expect_exact(p, u, membrane_field, R, 1e-15);
  for (std::size_t e = 0; e < p.elements.size(); ++e) {
    Eigen::MatrixXd strain, stress, forces, moments;
    element.strains_stresses(element_geometry(section, p, e), material(), RuleKind::Full,
                             element_dofs(p, e, u), strain, stress);
    ASSERT_EQ(stress.rows(), 9);
    for (Eigen::Index k = 0; k < stress.rows(); ++k) {
      EXPECT_NEAR(stress(k, 0), c * (1.0 + kNu) * 1e-3, 1e-6);
      EXPECT_NEAR(stress(k, 1), c * (1.0 + kNu) * 1e-3, 1e-6);
      EXPECT_NEAR(stress(k, 3), G * 1e-3, 1e-6);
    }
    element.section_resultants(element_geometry(section, p, e), material(), RuleKind::Full,
                               element_dofs(p, e, u), forces, moments);
    for (Eigen::Index k = 0; k < forces.rows(); ++k) {
      EXPECT_NEAR(forces(k, 0), kT * c * (1.0 + kNu) * 1e-3, 1e-9);
      EXPECT_NEAR(forces(k, 2), kT * G * 1e-3, 1e-9);
      EXPECT_NEAR(moments.row(k).norm(), 0.0, 1e-12);
    }
  }
}

// kxx = kyy = -1e-3, 2 kxy = -1e-3 (beta1 = -w,x, beta2 = -w,y): M11 = M22 = -D (1 + nu) 1e-3,
// M12 = -D (1 - nu) / 2 1e-3; top fibre sxx = -(t / 2) E / (1 - nu^2) (1 + nu) 1e-3.
TEST(Stri3, ConstantCurvaturePatchTestIsExactFlatAndTilted) {
  const Stri3 element;
  const Section section = shell_section(kT);
  const double D = kE * kT * kT * kT / (12.0 * (1.0 - kNu * kNu));
  for (const bool tilted : {false, true}) {
    const Eigen::Matrix3d R = tilted ? tilt() : Eigen::Matrix3d::Identity();
    const Patch p = patch(R);
    const Eigen::VectorXd u = solve_patch(section, p, bending_field, R);
    expect_exact(p, u, bending_field, R, 1e-9 * 1e-3);
    for (std::size_t e = 0; e < p.elements.size(); ++e) {
      Eigen::MatrixXd strain, stress, forces, moments;
      element.section_resultants(element_geometry(section, p, e), material(), RuleKind::Full,
                                 element_dofs(p, e, u), forces, moments);
      if (!tilted)  // the lamina axes are x, y only for the untilted patch
        for (Eigen::Index k = 0; k < moments.rows(); ++k) {
          EXPECT_NEAR(moments(k, 0), -D * (1.0 + kNu) * 1e-3, 1e-9 * D * 1e-3);
          EXPECT_NEAR(moments(k, 1), -D * (1.0 + kNu) * 1e-3, 1e-9 * D * 1e-3);
          EXPECT_NEAR(moments(k, 2), -D * (1.0 - kNu) / 2.0 * 1e-3, 1e-9 * D * 1e-3);
          EXPECT_NEAR(forces.row(k).norm(), 0.0, 1e-12);
        }
      // Invariant of the axes: M11 + M22 = -2 D (1 + nu) 1e-3.
      for (Eigen::Index k = 0; k < moments.rows(); ++k)
        EXPECT_NEAR(moments(k, 0) + moments(k, 1), -2.0 * D * (1.0 + kNu) * 1e-3, 1e-9 * D * 1e-3);
      element.strains_stresses(element_geometry(section, p, e), material(), RuleKind::Full,
                               element_dofs(p, e, u), strain, stress);
      const double top = -(kT / 2.0) * kE / (1.0 - kNu * kNu) * (1.0 + kNu) * 1e-3;
      for (Eigen::Index k = 0; k < stress.rows(); k += 3) {
        // The trace of the fibre stress (sigma33 = 0): 2 top at the top fibre, -2 top at the
        // bottom.
        const double bottom_trace = stress(k, 0) + stress(k, 1) + stress(k, 2);
        const double top_trace = stress(k + 2, 0) + stress(k + 2, 1) + stress(k + 2, 2);
        EXPECT_NEAR(bottom_trace, -2.0 * top, 1e-9 * std::abs(top));
        EXPECT_NEAR(top_trace, 2.0 * top, 1e-9 * std::abs(top));
        EXPECT_NEAR(stress.row(k + 1).norm(), 0.0, 1e-9 * std::abs(top));
      }
    }
  }
}

TEST(Stri3, PressureLoadIsThePressureTimesTheAreaAlongTheNormal) {
  const Stri3 element;
  const Section section = shell_section(0.1);
  const Eigen::Matrix3d R = tilt();
  const ElementGeometry g =
      geometry(section, {R * Eigen::Vector3d(0.0, 0.0, 0.0), R * Eigen::Vector3d(2.0, 0.0, 0.0),
                         R * Eigen::Vector3d(0.5, 1.5, 0.0)});
  Eigen::VectorXd f;
  element.pressure_load(g, 0, 4.0, f);
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  for (int a = 0; a < 3; ++a) total += f.segment<3>(6 * a);
  const Eigen::Vector3d expected = 4.0 * 1.5 * R.col(2);  // p times the area 1.5 along +z'
  EXPECT_LT((total - expected).norm(), 1e-12 * expected.norm());
  EXPECT_THROW(element.pressure_load(g, 1, 4.0, f), InputError);
}

TEST(Stri3, RefusesASolidSectionADegenerateTriangleAndAnOrthotropicMaterial) {
  const Stri3 element;
  Section solid = shell_section(0.1);
  solid.shell.reset();
  Eigen::MatrixXd K;
  const std::array<Eigen::Vector3d, 3> corners = {
      Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)};
  EXPECT_THROW(element.stiffness(geometry(solid, corners), material(), RuleKind::Full, K),
               InputError);
  const Section section = shell_section(0.1);
  const ElementGeometry line = geometry(
      section, {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(2, 0, 0)});
  try {
    element.stiffness(line, material(), RuleKind::Full, K);
    ADD_FAILURE() << "a degenerate triangle was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("element 7 (STRI3)"), std::string::npos) << e.what();
  }
  Material orthotropic = material();
  orthotropic.elastic_type = ElasticType::Orthotropic;
  EXPECT_THROW(element.stiffness(geometry(section, corners), orthotropic, RuleKind::Full, K),
               InputError);
}

}  // namespace
}  // namespace styk
