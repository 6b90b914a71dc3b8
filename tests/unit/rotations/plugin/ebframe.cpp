// A test plug-in that declares rotational dofs through the SDK: EBF2, a 2-node Euler-Bernoulli
// space frame (6 dofs per node: ux, uy, uz, rx, ry, rz) of a square cross-section whose area A is
// the first data line of its *SOLID SECTION. Section constants: I = A^2 / 12 about both section
// axes, torsion constant J = 2 I (the polar moment, a stand-in: exact for round sections only).
// Its closed-form stiffness (cubic deflection, linear twist and stretch) is exact for end loads,
// so the rotation dof layer of the solver can be checked against beam formulas to round-off:
// tip force P -> w = P L^3 / (3 E I), slope P L^2 / (2 E I); tip moment M -> M L / (E I);
// torque T -> T L / (G J).
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "styk/plugin/sdk.hpp"

namespace {

class EulerBernoulliFrame : public styk::TElement {
 public:
  EulerBernoulliFrame() : nodes_{{-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}} {}

  std::string name() const override { return "EBF2"; }
  std::string description() const override {
    return "test plug-in: 2-node Euler-Bernoulli space frame, 6 dofs per node";
  }
  int node_count() const override { return 2; }
  const std::vector<styk::Vec3>& natural_nodes() const override { return nodes_; }
  const std::vector<styk::FaceDef>& faces() const override { return faces_; }
  int node_dofs() const override { return 6; }
  styk::DofSet active_dofs() const override { return {true, true, true, true, true, true}; }
  styk::SectionMeasure section_measure() const override { return styk::SectionMeasure::Area; }

  void der(const styk::Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
           Eigen::Ref<Eigen::MatrixXd> dN) const override {
    N << 0.5 * (1.0 - xi[0]), 0.5 * (1.0 + xi[0]);
    dN.setZero();
    dN(0, 0) = -0.5;
    dN(1, 0) = 0.5;
  }
  styk::IntegrationRule rule(styk::RuleKind) const override {
    return styk::IntegrationRule{"1-point", {{0.0, 0.0, 0.0}}, {2.0}};
  }
  int face_rule_order() const override { return 1; }

  void stiffness(const styk::ElementGeometry& g, const styk::ElementMaterial& material,
                 styk::RuleKind, Eigen::MatrixXd& K, const styk::ElementOptions&) const override {
    Eigen::Matrix3d R;
    double L = 0.0;
    axes(g, R, L);
    const Constants c = constants(g, material.material(), L);
    Eigen::Matrix<double, 12, 12> k = Eigen::Matrix<double, 12, 12>::Zero();
    auto pair = [&](int i, int j, double value) {
      k(i, j) += value;
      if (i != j) k(j, i) += value;
    };
    // Local dofs: node 0 = 0..5, node 1 = 6..11 (u, v, w, rx, ry, rz along the element axes).
    pair(0, 0, c.EA / L), pair(6, 6, c.EA / L), pair(0, 6, -c.EA / L);
    pair(3, 3, c.GJ / L), pair(9, 9, c.GJ / L), pair(3, 9, -c.GJ / L);
    // Bending in the local x-y plane (v, rz) and x-z plane (w, ry, opposite slope sign).
    for (const int plane : {0, 1}) {
      const int v = plane == 0 ? 1 : 2, r = plane == 0 ? 5 : 4;
      const double s = plane == 0 ? 1.0 : -1.0;
      const double a = 12.0 * c.EI / (L * L * L), b = 6.0 * c.EI / (L * L);
      pair(v, v, a), pair(v + 6, v + 6, a), pair(v, v + 6, -a);
      pair(v, r, s * b), pair(v, r + 6, s * b), pair(v + 6, r, -s * b), pair(v + 6, r + 6, -s * b);
      pair(r, r, 4.0 * c.EI / L), pair(r + 6, r + 6, 4.0 * c.EI / L),
          pair(r, r + 6, 2.0 * c.EI / L);
    }
    Eigen::Matrix<double, 12, 12> T = Eigen::Matrix<double, 12, 12>::Zero();
    for (int block = 0; block < 4; ++block) T.block<3, 3>(3 * block, 3 * block) = R.transpose();
    K = T.transpose() * k * T;
  }

  void eigenstrain_load(const styk::ElementGeometry& g, const styk::ElementMaterial& material,
                        styk::RuleKind, Eigen::VectorXd& f, const styk::ElementOptions&,
                        const Eigen::MatrixXd* initial_stress) const override {
    if (material.has_thermal_strain() || initial_stress != nullptr)
      throw styk::InputError(g.where,
                             "EBF2 (test element) takes no temperature change or initial stress");
    f.setZero(12);
  }

  // One point: the axial stress N / A along the bar, as a global tensor t t^T sigma.
  void strains_stresses(const styk::ElementGeometry& g, const styk::ElementMaterial& law,
                        styk::RuleKind, const Eigen::Ref<const Eigen::VectorXd>& u,
                        Eigen::MatrixXd& strain, Eigen::MatrixXd& stress,
                        const styk::ElementOptions&, const Eigen::MatrixXd*) const override {
    const styk::Material& material = law.material();
    Eigen::Matrix3d R;
    double L = 0.0;
    axes(g, R, L);
    const Eigen::Vector3d t = R.col(0);
    const double eps = t.dot(u.segment<3>(6) - u.segment<3>(0)) / L;
    const double sigma = *material.young * eps;
    strain.setZero(1, 6);
    stress.setZero(1, 6);
    const int pairs[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
    for (int c = 0; c < 6; ++c) {
      stress(0, c) = sigma * t[pairs[c][0]] * t[pairs[c][1]];
      strain(0, c) = eps * t[pairs[c][0]] * t[pairs[c][1]];
    }
  }

 private:
  struct Constants {
    double EA, EI, GJ;
  };

  static Constants constants(const styk::ElementGeometry& g, const styk::Material& m, double L) {
    (void)L;
    const double E = *m.young, G = E / (2.0 * (1.0 + *m.poisson));
    const double A = g.cross_section, I = A * A / 12.0;
    return {E * A, E * I, G * 2.0 * I};
  }

  // Columns: the element axis and two perpendicular section axes; L the length.
  static void axes(const styk::ElementGeometry& g, Eigen::Matrix3d& R, double& L) {
    const Eigen::Vector3d d = (g.X.row(1) - g.X.row(0)).transpose();
    L = d.norm();
    if (!(L > 0.0)) throw styk::InputError(g.where, "EBF2 element of zero length");
    const Eigen::Vector3d t = d / L;
    const Eigen::Vector3d helper =
        std::abs(t.z()) < 0.9 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
    const Eigen::Vector3d n2 = t.cross(helper).normalized();
    R.col(0) = t;
    R.col(1) = n2.cross(t);  // completes a right-handed frame with t
    R.col(2) = t.cross(R.col(1));
  }

  std::vector<styk::Vec3> nodes_;
  std::vector<styk::FaceDef> faces_;
};

styk::plugin::ElementList make_elements() {
  styk::plugin::ElementList elements;
  elements.push_back(std::make_unique<EulerBernoulliFrame>());
  return elements;
}

}  // namespace

STYK_PLUGIN(make_elements)
