#include "shell_mesh_modes.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include <Eigen/Geometry>
#include <Eigen/QR>

#include "assembly.hpp"
#include "shell_locking.hpp"
#include "shell_warnings.hpp"
#include "zero_energy_modes.hpp"

namespace styk::solver_detail {
namespace {

bool is_shell(const TElement& element) {
  return element.section_measure() == SectionMeasure::Shell;
}

// The shell elements whose type and rule has spurious modes alone or in the 2x2 patch.
std::vector<int> candidate_elements(const Model& model, const PreparedModel& prepared) {
  std::map<std::pair<const TElement*, RuleKind>, bool> has_modes;
  std::vector<int> elements;
  for (int e = 0; e < model.element_count(); ++e) {
    if (!is_shell(*prepared.formulation[e])) continue;
    const auto key = std::make_pair(prepared.formulation[e], prepared.rule_kind[e]);
    auto known = has_modes.find(key);
    if (known == has_modes.end())
      known = has_modes
                  .emplace(key, spurious_shell_modes(*key.first, key.second, 1) > 0 ||
                                    spurious_shell_modes(*key.first, key.second) > 0)
                  .first;
    if (known->second) elements.push_back(e);
  }
  return elements;
}

// Dofs (node index * 6 + dof - 1) that *BOUNDARY holds outside any step or in the first step,
// on nodes without a *TRANSFORM (a support in local axes holds a mix of global dofs).
std::set<long> supported_dofs(const Model& model) {
  std::set<int> transformed;
  for (const Transform& t : model.transforms) {
    const auto set = model.nsets.find(t.nset);
    if (set != model.nsets.end())
      transformed.insert(set->second.nodes.begin(), set->second.nodes.end());
  }
  std::set<long> dofs;
  const auto add = [&](const std::vector<Boundary>& boundaries) {
    for (const Boundary& b : boundaries)
      if (b.dof >= 1 && b.dof <= 6 && !transformed.count(b.node))
        dofs.insert(6L * b.node + b.dof - 1);
  };
  add(model.boundaries);
  if (!model.steps.empty()) add(model.steps.front().boundaries);
  return dofs;
}

// The six rigid motions (translations, rotations about the nodes' centroid) at the nodes, one
// column each, 6 rows per node in `slot` order.
Eigen::MatrixXd rigid_motions(const Model& model, const std::map<int, int>& slot) {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& [node, place] : slot)
    centre += Eigen::Vector3d(model.coords[node][0], model.coords[node][1], model.coords[node][2]);
  centre /= static_cast<double>(slot.size());
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(6 * static_cast<Eigen::Index>(slot.size()), 6);
  for (const auto& [node, place] : slot) {
    const Eigen::Vector3d x =
        Eigen::Vector3d(model.coords[node][0], model.coords[node][1], model.coords[node][2]) -
        centre;
    for (int k = 0; k < 3; ++k) {
      R(6 * place + k, k) = 1.0;
      const Eigen::Vector3d axis = Eigen::Vector3d::Unit(k);
      R.block<3, 1>(6 * place, 3 + k) = axis.cross(x);
      R(6 * place + 3 + k, 3 + k) = 1.0;
    }
  }
  return R;
}

// The assembled unit-material stiffness of `elements` over the 6 dofs of each node in `slot`.
Eigen::MatrixXd unit_stiffness(const Model& model, const PreparedModel& prepared,
                               const std::vector<int>& elements, const std::map<int, int>& slot) {
  double size = 0.0;
  for (const int e : elements)
    size += shell_element_size(model, e) / static_cast<double>(elements.size());
  Section section;
  section.elset = "MESH";
  section.thickness = 0.1 * size;
  section.shell = ShellSection{};
  Material unit;
  unit.name = "UNIT";
  unit.young = 1.0;
  unit.poisson = 0.3;
  const Eigen::Index n = 6 * static_cast<Eigen::Index>(slot.size());
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  ElementGeometry g;
  for (const int e : elements) {
    element_geometry(model, prepared, e, g);
    g.section = &section;
    g.cross_section = *section.thickness;
    Eigen::MatrixXd Ke;
    prepared.formulation[e]->stiffness(g, unit, prepared.rule_kind[e], Ke);
    const int* nodes = model.element_nodes(e);
    const int count = model.elements[e].node_count;
    for (int a = 0; a < count; ++a)
      for (int b = 0; b < count; ++b)
        K.block<6, 6>(6 * slot.at(nodes[a]), 6 * slot.at(nodes[b])) += Ke.block<6, 6>(6 * a, 6 * b);
  }
  return K;
}

}  // namespace

int supported_shell_mesh_modes(const Model& model, const PreparedModel& prepared) {
  const std::vector<int> elements = candidate_elements(model, prepared);
  if (elements.empty() || static_cast<int>(elements.size()) > kWholeShellMeshLimit) return -1;
  std::map<int, int> slot;  // node -> its place in the small matrix
  for (const int e : elements) {
    const int* nodes = model.element_nodes(e);
    for (int k = 0; k < model.elements[e].node_count; ++k) slot.emplace(nodes[k], 0);
  }
  int next = 0;
  for (auto& [node, place] : slot) place = next++;
  const Eigen::MatrixXd K = unit_stiffness(model, prepared, elements, slot);
  const Eigen::MatrixXd R = rigid_motions(model, slot);
  // Split the small matrix's dofs into held and free.
  const std::set<long> held_dofs = supported_dofs(model);
  std::vector<Eigen::Index> free, held;
  for (const auto& [node, place] : slot)
    for (int d = 0; d < 6; ++d)
      (held_dofs.count(6L * node + d) ? held : free).push_back(6 * place + d);
  const int zero = zero_eigenvalue_count(K, free);
  // The rigid motions the supports leave free: 6 minus the rank of their held rows.
  int held_rank = 0;
  if (!held.empty()) {
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(R(held, Eigen::all));
    qr.setThreshold(1e-9);
    held_rank = static_cast<int>(qr.rank());
  }
  return std::max(0, zero - (6 - held_rank));
}

}  // namespace styk::solver_detail
