// The template plug-in: the smallest complete element plug-in, meant to be copied. It registers
// the 8-node trilinear brick once more under the name "TMPL8"; docs/plugins.md walks through it
// and builds it outside the Styk tree with the CMakeLists.txt next to this file.
// Everything a new element needs is here: node layout, faces, DER, integration rules, the
// face-load rule, and the entry point (the last line).

// The SDK: TElement, ElementRegistry and the STYK_PLUGIN entry macro.
#include "styk/plugin/sdk.hpp"

// The SDK's hexahedral shape-function library (node tables, Abaqus faces, DER of the 8-, 20- and
// 27-node bricks; quad_shapes.hpp, tet_shapes.hpp and wedge_shapes.hpp hold the other families);
// a new element may use it or compute everything itself.
#include "styk/elements/hex_shapes.hpp"

#include <memory>
#include <string>
#include <vector>

// A plug-in's own code lives in an anonymous namespace: nothing but the entry point is exported.
namespace {

// An element type is a class derived from styk::TElement that overrides the pure virtual hooks.
class Tmpl8 : public styk::TElement {
 public:
  // The node table and the faces never change: build them once.
  Tmpl8() : nodes_(styk::hex8_natural_nodes()), faces_(styk::hex_faces(false)) {}

  // The type name used in *ELEMENT, TYPE=TMPL8 (upper case; must be unique in the registry).
  std::string name() const override { return "TMPL8"; }

  // One line for `styk elements`.
  std::string description() const override {
    return "template plug-in: 8-node trilinear brick (copy of C3D8), 2x2x2 Gauss";
  }

  // Nodes per element, and their natural coordinates in the element's local order.
  int node_count() const override { return 8; }
  const std::vector<styk::Vec3>& natural_nodes() const override { return nodes_; }

  // Faces S1..S6: the local nodes on each (corners first) and the plane xi_axis = value.
  const std::vector<styk::FaceDef>& faces() const override { return faces_; }

  // DER: shape functions N and their natural derivatives dN/dxi at the point xi.
  void der(const styk::Vec3& xi, Eigen::Ref<Eigen::VectorXd> N,
           Eigen::Ref<Eigen::MatrixXd> dN) const override {
    styk::hex8_shape(xi, N, dN);
  }

  // The volume rules: full (default) and reduced (chosen by the section's control).
  styk::IntegrationRule rule(styk::RuleKind kind) const override {
    return kind == styk::RuleKind::Reduced ? styk::gauss_rule(1, 1, 1) : styk::gauss_rule(2, 2, 2);
  }

  // Gauss points per direction on a face, for pressure loads and contact nodal areas.
  int face_rule_order() const override { return 2; }

  // bee() (strain-displacement) and dee() (material matrix) keep the TElement defaults: small
  // strain, isotropic elasticity. Override them for B-bar, incompatible modes, other materials.
  // An element whose nodes carry rotations (a beam, a shell) overrides node_dofs() (6) and
  // active_dofs() and computes its own stiffness(); tests/unit/rotations/plugin/ebframe.cpp is a
  // complete example (docs/plugins.md, "Declaring rotational degrees of freedom").

 private:
  std::vector<styk::Vec3> nodes_;
  std::vector<styk::FaceDef> faces_;
};

// The factory: one instance of every element type this plug-in provides.
styk::plugin::ElementList make_elements() {
  styk::plugin::ElementList elements;
  elements.push_back(std::make_unique<Tmpl8>());
  return elements;
}

}  // namespace

// Defines and exports `styk_plugin_register`: ABI check, then all-or-nothing registration.
STYK_PLUGIN(make_elements)
