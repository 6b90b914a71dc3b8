// Programmatic hexahedral models for the recovery tests (SPEC §2.4 single elements, §3.1.8 patch
// test, unit tests of the stress averaging): elements of any registered type placed on the
// trilinear map of eight corner points, nodes shared by position. The registry with the
// build-tree plug-ins (C3D14, C3D21, C3D28) comes from tests/support. Header-only.
#pragma once

#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "styk/core/element.hpp"
#include "styk/core/element_registry.hpp"
#include "support/element_registries.hpp"

namespace styk::test {

// Corners in Abaqus order: 1-4 counter-clockwise seen from the top (nodes 5-8), 5-8 above them.
using HexCorners = std::array<Vec3, 8>;

// The trilinear map of the corners at natural coordinates xi.
inline Vec3 trilinear(const HexCorners& corners, const Vec3& xi) {
  static const double sign[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                    {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  Vec3 x{0.0, 0.0, 0.0};
  for (int c = 0; c < 8; ++c) {
    double N = 0.125;
    for (int d = 0; d < 3; ++d) N *= 1.0 + sign[c][d] * xi[d];
    for (int d = 0; d < 3; ++d) x[d] += N * corners[c][d];
  }
  return x;
}

// Builds a Model element by element: every node of an element sits at the trilinear map of the
// element's natural node coordinates (straight edges, flat faces); nodes closer than 1e-10 are
// one node. One isotropic material and one section (element set EALL), node set NALL.
class HexModelBuilder {
 public:
  HexModelBuilder(const ElementRegistry& registry, double young, double poisson)
      : registry_(registry) {
    model_.source = "built.inp";
    Material material;
    material.name = "M";
    material.young = young;
    material.poisson = poisson;
    model_.materials.push_back(material);
    Section section;
    section.elset = "EALL";
    section.material = "M";
    section.material_index = 0;
    model_.sections.push_back(section);
  }

  // Adds an element of `type` (must be registered); returns its index.
  int add(const std::string& type, const HexCorners& corners) {
    const TElement* element = registry_.find(type);
    if (element == nullptr) throw std::invalid_argument("element type " + type + " not registered");
    std::vector<int> nodes;
    for (const Vec3& xi : element->natural_nodes())
      nodes.push_back(node_at(trilinear(corners, xi)));
    const int index = model_.add_element(model_.element_count() + 1, type, nodes, {});
    model_.elements[index].section = 0;
    return index;
  }

  Model finish() {
    ElementSet all{"EALL", {}, {}};
    for (int e = 0; e < model_.element_count(); ++e) all.elements.push_back(e);
    model_.elsets["EALL"] = all;
    NodeSet nodes{"NALL", {}, {}};
    for (int n = 0; n < model_.node_count(); ++n) nodes.nodes.push_back(n);
    model_.nsets["NALL"] = nodes;
    Step step;
    step.name = "STEP";
    step.has_procedure = true;
    model_.steps.push_back(step);
    return std::move(model_);
  }

 private:
  int node_at(const Vec3& x) {
    for (int n = 0; n < model_.node_count(); ++n) {
      const Vec3& y = model_.coords[n];
      if (std::abs(x[0] - y[0]) + std::abs(x[1] - y[1]) + std::abs(x[2] - y[2]) < 1e-10) return n;
    }
    return model_.add_node(model_.node_count() + 1, x, {});
  }

  const ElementRegistry& registry_;
  Model model_;
};

}  // namespace styk::test
