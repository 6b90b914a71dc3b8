// A 4-node linear tetrahedron used as a test double of TElement in the core tests, so the
// base-class template methods are exercised without the elements module (core must not depend on
// it).
#pragma once

#include "styk/core/element.hpp"

namespace styk::test {

class Tetrahedron4 : public TElement {
 public:
  std::string name() const override { return "TET4"; }
  std::string description() const override { return "test tetrahedron"; }
  int node_count() const override { return 4; }
  const std::vector<Vec3>& natural_nodes() const override { return nodes_; }
  const std::vector<FaceDef>& faces() const override { return faces_; }
  void der(const Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
           Eigen::Ref<Eigen::MatrixXd> dN) const override {
    N << 1.0 - xi[0] - xi[1] - xi[2], xi[0], xi[1], xi[2];
    dN << -1, -1, -1, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  }
  // One point at the centroid, weight = volume of the unit tetrahedron.
  IntegrationRule rule(RuleKind) const override {
    return IntegrationRule{"1-point", {Vec3{0.25, 0.25, 0.25}}, {1.0 / 6.0}};
  }
  int face_rule_order() const override { return 1; }

 private:
  std::vector<Vec3> nodes_{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  std::vector<FaceDef> faces_;
};

}  // namespace styk::test
