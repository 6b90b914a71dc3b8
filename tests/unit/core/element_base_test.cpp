// TElement defaults (BEE, DEE) and template methods, on a test tetrahedron.
#include <string>

#include <gtest/gtest.h>

#include "test_tetrahedron.hpp"

namespace styk {
namespace {

Material steel() {
  Material m;
  m.name = "STEEL";
  m.young = 210000.0;
  m.poisson = 0.3;
  m.where = SourceLoc{"deck.inp", 12};
  return m;
}

// Isotropic Hooke's law with engineering shear: D11 = E(1-nu)/((1+nu)(1-2nu)),
// D12 = E nu/((1+nu)(1-2nu)), D44 = E/(2(1+nu)); relative tolerance 1e-14.
TEST(ElementDee, IsotropicElasticity) {
  test::Tetrahedron4 e;
  Matrix6d D;
  e.dee(material_point(steel()), D);
  const double E = 210000.0, nu = 0.3, c = E / ((1 + nu) * (1 - 2 * nu));
  EXPECT_NEAR(D(0, 0), c * (1 - nu), 1e-14 * E);
  EXPECT_NEAR(D(1, 2), c * nu, 1e-14 * E);
  EXPECT_NEAR(D(3, 3), E / (2 * (1 + nu)), 1e-14 * E);
  EXPECT_NEAR(D(5, 5), E / (2 * (1 + nu)), 1e-14 * E);
  EXPECT_EQ(D(0, 3), 0.0);
  EXPECT_EQ(D(3, 4), 0.0);
  EXPECT_EQ((D - D.transpose()).cwiseAbs().maxCoeff(), 0.0);
}

TEST(ElementDee, BadMaterialIsAnInputErrorAtTheMaterial) {
  test::Tetrahedron4 e;
  Matrix6d D;
  Material m = steel();
  m.young.reset();
  try {
    e.dee(material_point(m), D);
    FAIL() << "missing Young's modulus accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()).rfind("deck.inp:12: material STEEL", 0), 0u)
        << error.what();
  }
  for (double nu : {0.5, -1.0, 0.7}) {
    m = steel();
    m.poisson = nu;
    EXPECT_THROW(e.dee(material_point(m), D), InputError) << nu;
  }
  m = steel();
  m.young = 0.0;
  EXPECT_THROW(e.dee(material_point(m), D), InputError);
}

// B for one node with dN/dx = (a, b, c): rows 11, 22, 33, 12, 13, 23 with engineering shear.
TEST(ElementBee, StandardSmallStrainOperator) {
  test::Tetrahedron4 e;
  Eigen::MatrixXd dNdx = Eigen::MatrixXd::Zero(4, 3);
  dNdx.row(1) << 2.0, 3.0, 5.0;
  Eigen::MatrixXd B = Eigen::MatrixXd::Constant(6, 12, 99.0);
  e.bee(dNdx, B);
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(6, 12);
  expected.block<6, 3>(0, 3) << 2, 0, 0,  //
      0, 3, 0,                            //
      0, 0, 5,                            //
      3, 2, 0,                            //
      5, 0, 2,                            //
      0, 5, 3;
  EXPECT_EQ(B, expected);
}

// A tetrahedron stretched by 2 in x: det J = 2 and strains from u = (0.01 x, 0, 0) are
// eps_11 = 0.01, stress = D eps (tolerance 1e-15 relative).
TEST(ElementTemplate, JacobianAndStrainsOfAScaledTetrahedron) {
  test::Tetrahedron4 e;
  ElementGeometry g;
  g.X.resize(4, 3);
  g.X << 0, 0, 0, 2, 0, 0, 0, 1, 0, 0, 0, 1;
  g.id = 3;
  Eigen::VectorXd N(4);
  Eigen::MatrixXd dN(4, 3), dNdx(4, 3);
  e.der(Vec3{0.25, 0.25, 0.25}, N, dN);
  EXPECT_NEAR(e.jacobian(g, dN, dNdx, 1), 2.0, 1e-15);
  EXPECT_NEAR(dNdx(1, 0), 0.5, 1e-15);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(12);
  for (int i = 0; i < 4; ++i) u(3 * i) = 0.01 * g.X(i, 0);
  u(3 * 3 + 1) = 0.004;  // u_y = 0.004 z: gamma_23 = 0.004, tensor eps_23 = 0.002
  Eigen::MatrixXd strain, stress;
  e.strains_stresses(g, steel(), RuleKind::Full, u, strain, stress);
  ASSERT_EQ(strain.rows(), 1);
  EXPECT_NEAR(strain(0, 0), 0.01, 1e-15);
  EXPECT_NEAR(strain(0, 5), 0.002, 1e-15);
  Matrix6d D;
  e.dee(material_point(steel()), D);
  EXPECT_NEAR(stress(0, 0), D(0, 0) * 0.01, 1e-12);
  EXPECT_NEAR(stress(0, 1), D(1, 0) * 0.01, 1e-12);
  EXPECT_NEAR(stress(0, 5), D(5, 5) * 0.004, 1e-12);
  // Volume of the element times D: K = V B^T D B; trace check against a direct formula.
  Eigen::MatrixXd K, B(6, 12);
  e.stiffness(g, steel(), RuleKind::Full, K);
  e.bee(dNdx, B);
  const Eigen::MatrixXd expected = (2.0 / 6.0) * B.transpose() * D * B;
  EXPECT_LT((K - expected).cwiseAbs().maxCoeff(), 1e-10 * expected.cwiseAbs().maxCoeff());
}

TEST(ElementTemplate, InvertedTetrahedronNamesElementAndPoint) {
  test::Tetrahedron4 e;
  ElementGeometry g;
  g.X.resize(4, 3);
  g.X << 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1;  // nodes 2 and 3 swapped
  g.id = 77;
  g.where = SourceLoc{"deck.inp", 40};
  Eigen::MatrixXd K;
  try {
    e.stiffness(g, steel(), RuleKind::Full, K);
    FAIL() << "inverted element accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "deck.inp:40: element 77 (TET4): Jacobian determinant -1 at integration point 1 is "
              "not positive: the element is inverted or degenerate");
  }
}

}  // namespace
}  // namespace styk
