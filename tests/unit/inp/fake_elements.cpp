#include "fake_elements.hpp"

#include <memory>
#include <stdexcept>

namespace styk::test {

namespace {

// Corner-node faces in the Abaqus order (the reader only counts them: S1..Sn must exist).
std::vector<FaceDef> hexahedron_faces() {
  return {{{0, 1, 2, 3}, 2, -1.0}, {{4, 7, 6, 5}, 2, 1.0}, {{0, 4, 5, 1}, 1, -1.0},
          {{1, 5, 6, 2}, 0, 1.0},  {{2, 6, 7, 3}, 1, 1.0}, {{3, 7, 4, 0}, 0, -1.0}};
}
std::vector<FaceDef> wedge_faces() {
  return {{{0, 1, 2}, 2, -1.0},
          {{3, 5, 4}, 2, 1.0},
          {{0, 3, 4, 1}, 1, -1.0},
          {{1, 4, 5, 2}, 0, 1.0},
          {{2, 5, 3, 0}, 0, -1.0}};
}

// A 2-node beam for the *BEAM SECTION checks: takes a beam section; `reduced_only` as CalculiX's
// R types (the same rule for both kinds).
class FakeBeam : public TElement {
 public:
  FakeBeam(std::string name, bool reduced_only)
      : name_(std::move(name)), reduced_only_(reduced_only) {}
  std::string name() const override { return name_; }
  std::string description() const override { return "fake beam " + name_ + " for reader tests"; }
  int node_count() const override { return 2; }
  const std::vector<Vec3>& natural_nodes() const override { throw std::logic_error("fake"); }
  const std::vector<FaceDef>& faces() const override { return faces_; }
  int node_dofs() const override { return 6; }
  SectionMeasure section_measure() const override { return SectionMeasure::Beam; }
  int distributed_load_labels() const override { return 2; }
  void der(const Vec3&, Eigen::Ref<Eigen::VectorXd>, Eigen::Ref<Eigen::MatrixXd>) const override {
    throw std::logic_error("fake");
  }
  IntegrationRule rule(RuleKind kind) const override {
    const int points = kind == RuleKind::Full && !reduced_only_ ? 2 : 1;
    return IntegrationRule{"fake", std::vector<Vec3>(points), std::vector<double>(points, 1.0)};
  }
  int face_rule_order() const override { throw std::logic_error("fake"); }

 private:
  std::string name_;
  bool reduced_only_;
  std::vector<FaceDef> faces_;
};

// A 4-node shell for the *SHELL SECTION checks: takes a shell section and the pressure P.
class FakeShell : public TElement {
 public:
  std::string name() const override { return "S4"; }
  std::string description() const override { return "fake shell S4 for reader tests"; }
  int node_count() const override { return 4; }
  const std::vector<Vec3>& natural_nodes() const override { throw std::logic_error("fake"); }
  const std::vector<FaceDef>& faces() const override { return faces_; }
  int node_dofs() const override { return 6; }
  SectionMeasure section_measure() const override { return SectionMeasure::Shell; }
  int distributed_load_labels() const override { return 1; }
  void der(const Vec3&, Eigen::Ref<Eigen::VectorXd>, Eigen::Ref<Eigen::MatrixXd>) const override {
    throw std::logic_error("fake");
  }
  IntegrationRule rule(RuleKind) const override {
    return IntegrationRule{"fake", std::vector<Vec3>(4), std::vector<double>(4, 1.0)};
  }
  int face_rule_order() const override { throw std::logic_error("fake"); }

 private:
  std::vector<FaceDef> faces_;
};

class FakeElement : public TElement {
 public:
  FakeElement(std::string name, int nodes, std::vector<FaceDef> faces)
      : name_(std::move(name)), nodes_(nodes), faces_(std::move(faces)) {}
  std::string name() const override { return name_; }
  std::string description() const override { return "fake " + name_ + " for reader tests"; }
  int node_count() const override { return nodes_; }
  const std::vector<Vec3>& natural_nodes() const override { throw std::logic_error("fake"); }
  const std::vector<FaceDef>& faces() const override { return faces_; }
  void der(const Vec3&, Eigen::Ref<Eigen::VectorXd>, Eigen::Ref<Eigen::MatrixXd>) const override {
    throw std::logic_error("fake");
  }
  IntegrationRule rule(RuleKind) const override { throw std::logic_error("fake"); }
  int face_rule_order() const override { throw std::logic_error("fake"); }

 private:
  std::string name_;
  int nodes_;
  std::vector<FaceDef> faces_;
};

}  // namespace

ElementRegistry fake_registry() {
  ElementRegistry registry;
  registry.add(std::make_unique<FakeElement>("C3D8", 8, hexahedron_faces()), "test");
  registry.add(std::make_unique<FakeElement>("C3D20", 20, hexahedron_faces()), "test");
  registry.add(std::make_unique<FakeBeam>("B21", false), "test");
  registry.add(std::make_unique<FakeBeam>("B31", false), "test");
  registry.add(std::make_unique<FakeBeam>("B31R", true), "test");
  registry.add(std::make_unique<FakeShell>(), "test");
  return registry;
}

ElementRegistry fake_registry_with_wedge() {
  ElementRegistry registry = fake_registry();
  registry.add(std::make_unique<FakeElement>("C3D6", 6, wedge_faces()), "test");
  return registry;
}

}  // namespace styk::test
