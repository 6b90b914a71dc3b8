#include "styk/core/shell_normals.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include <Eigen/Geometry>

#include "styk/core/vec3.hpp"

namespace styk {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The unit normal of element e's own mid-surface interpolation at each of its nodes (zero where
// the tangents are parallel: the element reports that itself when it is set up).
std::vector<Eigen::Vector3d> own_normals(const Model& model, int e, const TElement& element) {
  const int n = element.node_count();
  const int* nodes = model.element_nodes(e);
  Eigen::MatrixXd X(n, 3);
  for (int a = 0; a < n; ++a) X.row(a) = as_eigen(model.coords[nodes[a]]).transpose();
  const double scale = std::max(X.cwiseAbs().maxCoeff(), 1e-300);
  Eigen::VectorXd N(n);
  Eigen::MatrixXd dN(n, 3);
  std::vector<Eigen::Vector3d> normals;
  for (int a = 0; a < n; ++a) {
    element.der(element.natural_nodes()[a], N, dN);
    const Eigen::Vector3d g1 = X.transpose() * dN.col(0), g2 = X.transpose() * dN.col(1);
    const Eigen::Vector3d normal = g1.cross(g2);
    normals.push_back(normal.norm() > 1e-12 * scale * scale ? normal.normalized()
                                                            : Eigen::Vector3d::Zero());
  }
  return normals;
}

double degrees_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.dot(b), -1.0, 1.0)) * 180.0 / kPi;
}

// Averages, per node, the own normals of the slots listed for it when they all lie within the
// averaging angle of each other; records the node as a fold otherwise.
void average_at_nodes(const Model& model, const std::map<int, std::vector<int>>& slots_of_node,
                      const std::vector<Eigen::Vector3d>& own, ShellNormals& out) {
  const double cos_limit = std::cos(kNormalAveragingDegrees * kPi / 180.0);
  for (const auto& [node, slots] : slots_of_node) {
    bool smooth = true;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < slots.size() && smooth; ++i) {
      sum += own[slots[i]];
      for (std::size_t j = i + 1; j < slots.size() && smooth; ++j)
        smooth = own[slots[i]].dot(own[slots[j]]) >= cos_limit;
    }
    if (!smooth) {
      out.fold_nodes.push_back(model.node_ids[node]);
      continue;
    }
    const Eigen::Vector3d mean = sum.normalized();
    for (const int slot : slots) out.at_slot[slot] = to_vec3(mean);
  }
  std::sort(out.fold_nodes.begin(), out.fold_nodes.end());
}

// The *NORMAL lines, in deck order, replace the resolved normal of their element and node.
void apply_given_normals(const Model& model, const std::vector<Eigen::Vector3d>& own,
                         ShellNormals& out) {
  for (const UserNormal& given : model.normals) {
    const Element& element = model.elements[given.element];
    const int* nodes = model.element_nodes(given.element);
    const int a =
        static_cast<int>(std::find(nodes, nodes + element.node_count, given.node) - nodes);
    if (a == element.node_count) continue;  // the reader only keeps nodes of the element
    const int slot = element.first_node + a;
    if (own[slot].isZero()) continue;  // a degenerate element refuses itself
    Eigen::Vector3d normal = as_eigen(given.direction).normalized();
    const double angle = degrees_between(normal, own[slot]);
    if (angle > 180.0 - 2.0 * kNormalAveragingDegrees) {
      normal = -normal;  // given the other way round: Abaqus reverses it silently
    } else if (angle > kNormalAveragingDegrees) {
      char text[64];
      std::snprintf(text, sizeof text, "%.1f", angle);
      out.warnings.push_back(given.where.str() + ": the *NORMAL of element " +
                             std::to_string(element.id) + " at node " +
                             std::to_string(model.node_ids[given.node]) + " is " + text +
                             " degrees from the element's own normal there (a strongly skewed "
                             "fibre direction)");
    }
    out.at_slot[slot] = to_vec3(normal);
  }
}

}  // namespace

bool takes_nodal_normals(const TElement& element) {
  return element.section_measure() == SectionMeasure::Shell && element.node_count() != 3;
}

ShellNormals resolve_shell_normals(const Model& model,
                                   const std::vector<const TElement*>& formulation) {
  ShellNormals out;
  std::vector<Eigen::Vector3d> own;  // per slot
  std::map<int, std::vector<int>> slots_of_node;
  for (int e = 0; e < model.element_count(); ++e) {
    const TElement* element = formulation[e];
    if (!element || !takes_nodal_normals(*element) ||
        element->node_count() != model.elements[e].node_count)
      continue;
    if (own.empty()) own.assign(model.connectivity.size(), Eigen::Vector3d::Zero());
    const std::vector<Eigen::Vector3d> normals = own_normals(model, e, *element);
    const int first = model.elements[e].first_node;
    for (int a = 0; a < element->node_count(); ++a) {
      own[first + a] = normals[a];
      if (!normals[a].isZero()) slots_of_node[model.element_nodes(e)[a]].push_back(first + a);
    }
  }
  if (own.empty()) return out;
  out.at_slot.assign(model.connectivity.size(), Vec3{0.0, 0.0, 0.0});
  average_at_nodes(model, slots_of_node, own, out);
  for (std::size_t slot = 0; slot < own.size(); ++slot)  // folds: each element its own
    if (out.at_slot[slot] == Vec3{0.0, 0.0, 0.0} && !own[slot].isZero())
      out.at_slot[slot] = to_vec3(own[slot]);
  apply_given_normals(model, own, out);
  return out;
}

}  // namespace styk
