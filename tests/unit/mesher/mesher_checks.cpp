#include "mesher_checks.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <stdexcept>
#include <vector>

namespace styk::test {

double volume(const Model& model, const ElementRegistry& registry) {
  double v = 0.0;
  for (int e = 0; e < model.element_count(); ++e) {
    const TElement& t = *registry.find(model.elements[e].type);
    const int n = t.node_count();
    ElementGeometry g;
    g.X.resize(n, 3);
    g.id = model.elements[e].id;
    for (int i = 0; i < n; ++i)
      for (int d = 0; d < 3; ++d) g.X(i, d) = model.coords[model.element_nodes(e)[i]][d];
    Eigen::VectorXd N(n);
    Eigen::MatrixXd dN(n, 3), dNdx(n, 3);
    const IntegrationRule rule = t.rule(RuleKind::Full);
    for (int p = 0; p < rule.size(); ++p) {
      t.der(rule.points[p], N, dN);
      v += t.jacobian(g, dN, dNdx, p + 1) * rule.weights[p];
    }
  }
  return v;
}

std::string conformity_problem(const Model& model, const ElementRegistry& registry) {
  struct Use {
    int element;
    std::vector<int> nodes;
  };
  // Faces keyed by their corner nodes (those of the element's corners on the face: 4 on a brick
  // face, 3 on a triangle).
  std::map<std::vector<int>, std::vector<Use>> faces;
  for (int e = 0; e < model.element_count(); ++e) {
    const TElement& t = *registry.find(model.elements[e].type);
    const std::vector<int> element_corners = corner_nodes(t);
    for (const FaceDef& f : t.faces()) {
      std::vector<int> nodes, corners;
      for (int local : f.nodes) {
        nodes.push_back(model.element_nodes(e)[local]);
        if (std::binary_search(element_corners.begin(), element_corners.end(), local))
          corners.push_back(model.element_nodes(e)[local]);
      }
      std::sort(corners.begin(), corners.end());
      std::sort(nodes.begin(), nodes.end());
      faces[corners].push_back({e, nodes});
    }
  }
  for (const auto& [corners, uses] : faces) {
    const std::string name = "elements " + std::to_string(model.elements[uses[0].element].id);
    if (uses.size() > 2)
      return name + ": a face shared by " + std::to_string(uses.size()) + " elements";
    if (uses.size() == 2 && uses[0].nodes != uses[1].nodes)
      return name + " and " + std::to_string(model.elements[uses[1].element].id) +
             ": shared face with different node sets (" + model.elements[uses[0].element].type +
             " / " + model.elements[uses[1].element].type + ")";
  }
  return {};
}

int free_nodes(const Model& model) {
  std::vector<char> used(model.node_count(), 0);
  for (int n : model.connectivity) used[n] = 1;
  return static_cast<int>(std::count(used.begin(), used.end(), 0));
}

std::string type_counts(const Model& model) {
  std::map<std::string, int> counts;
  for (const Element& e : model.elements) ++counts[e.type];
  std::string out;
  for (const auto& [type, n] : counts)
    out += (out.empty() ? "" : " ") + type + ":" + std::to_string(n);
  return out;
}

}  // namespace styk::test
