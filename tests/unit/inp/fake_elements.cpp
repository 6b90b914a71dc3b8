#include "fake_elements.hpp"

#include <memory>
#include <stdexcept>

namespace styk::test {

namespace {

class FakeElement : public TElement {
 public:
  FakeElement(std::string name, int nodes) : name_(std::move(name)), nodes_(nodes) {}
  std::string name() const override { return name_; }
  std::string description() const override { return "fake " + name_ + " for reader tests"; }
  int node_count() const override { return nodes_; }
  const std::vector<Vec3>& natural_nodes() const override { throw std::logic_error("fake"); }
  const std::vector<FaceDef>& faces() const override { throw std::logic_error("fake"); }
  void der(const Vec3&, Eigen::Ref<Eigen::VectorXd>, Eigen::Ref<Eigen::MatrixXd>) const override {
    throw std::logic_error("fake");
  }
  IntegrationRule rule(RuleKind) const override { throw std::logic_error("fake"); }
  int face_rule_order() const override { throw std::logic_error("fake"); }

 private:
  std::string name_;
  int nodes_;
};

}  // namespace

ElementRegistry fake_registry() {
  ElementRegistry registry;
  registry.add(std::make_unique<FakeElement>("C3D8", 8), "test");
  registry.add(std::make_unique<FakeElement>("C3D20", 20), "test");
  return registry;
}

}  // namespace styk::test
