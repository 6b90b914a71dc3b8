#include "shell_warnings.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

#include <Eigen/Eigenvalues>

#include "assembly.hpp"
#include "warning_format.hpp"

namespace styk::solver_detail {
namespace {

// Element size / thickness from which a fully integrated S8 is warned of (about 3 % too stiff).
constexpr double kSlenderWarned = 10.0;

bool is_shell(const TElement& element) {
  return element.section_measure() == SectionMeasure::Shell;
}

// The fully integrated serendipity shell: 8 nodes, more points in its full rule than its reduced.
bool locks_in_shear(const TElement& element, RuleKind kind) {
  return is_shell(element) && element.node_count() == 8 && kind == RuleKind::Full &&
         element.rule(RuleKind::Full).size() > element.rule(RuleKind::Reduced).size();
}

// The longest distance between consecutive corners (edge chords) of element e.
double element_size(const Model& model, int e) {
  const int* nodes = model.element_nodes(e);
  double size = 0.0;
  for (int k = 0; k < 4; ++k) {
    const Vec3& a = model.coords[nodes[k]];
    const Vec3& b = model.coords[nodes[(k + 1) % 4]];
    size = std::max(size, std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]));
  }
  return size;
}

// Zero eigenvalues beyond the six rigid motions of a dense symmetric stiffness matrix.
int modes_beyond_rigid(const Eigen::MatrixXd& K) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(K, Eigen::EigenvaluesOnly);
  const Eigen::VectorXd& values = eigen.eigenvalues();
  const double largest = values.cwiseAbs().maxCoeff();
  int zero = 0;
  for (Eigen::Index k = 0; k < values.size(); ++k) zero += std::abs(values[k]) < 1e-9 * largest;
  return std::max(0, zero - 6);
}

// Meshes of reduced-integration shells up to this many elements are checked whole (their own
// geometry, free of supports): patterns the 2x2 patch does not show (a single S8R element, a
// strip one element wide) are found there. Larger meshes rely on the patch count.
constexpr int kWholeMeshLimit = 16;

// Zero-energy modes beyond the rigid motions of the model's shell elements whose type and rule
// has spurious modes as a single element (S8R, S9R), assembled alone with a unit material and a
// thickness of a tenth of their mean size (the count depends on the rule and the mesh, not on
// the section). -1 when there are none or more than kWholeMeshLimit.
int reduced_shell_mesh_modes(const Model& model, const PreparedModel& prepared) {
  std::map<std::pair<const TElement*, RuleKind>, bool> single_modes;
  std::vector<int> elements;
  for (int e = 0; e < model.element_count(); ++e) {
    if (!is_shell(*prepared.formulation[e])) continue;
    const auto key = std::make_pair(prepared.formulation[e], prepared.rule_kind[e]);
    const auto known = single_modes.find(key);
    const bool candidate =
        known != single_modes.end()
            ? known->second
            : (single_modes[key] = spurious_shell_modes(*key.first, key.second, 1) > 0);
    if (candidate) elements.push_back(e);
  }
  if (elements.empty() || static_cast<int>(elements.size()) > kWholeMeshLimit) return -1;
  std::map<int, int> slot;  // node -> its place in the small matrix
  double size = 0.0;
  for (const int e : elements) {
    const int* nodes = model.element_nodes(e);
    for (int k = 0; k < model.elements[e].node_count; ++k) slot.emplace(nodes[k], 0);
    size += element_size(model, e) / static_cast<double>(elements.size());
  }
  int next = 0;
  for (auto& [node, place] : slot) place = next++;
  Section section;
  section.elset = "MESH";
  section.thickness = 0.1 * size;
  section.shell = ShellSection{};
  Material unit;
  unit.name = "UNIT";
  unit.young = 1.0;
  unit.poisson = 0.3;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(6 * next, 6 * next);
  ElementGeometry g;
  for (const int e : elements) {
    element_geometry(model, prepared, e, g);
    g.section = &section;
    g.cross_section = *section.thickness;
    Eigen::MatrixXd Ke;
    prepared.formulation[e]->stiffness(g, unit, prepared.rule_kind[e], Ke);
    const int* nodes = model.element_nodes(e);
    const int n = model.elements[e].node_count;
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b)
        K.block<6, 6>(6 * slot[nodes[a]], 6 * slot[nodes[b]]) += Ke.block<6, 6>(6 * a, 6 * b);
  }
  return modes_beyond_rigid(K);
}

// Folds (nodes whose shells keep their own normals) and given normals far from their element's.
void append_normal_warnings(const ShellNormals& normals, std::vector<std::string>& warnings) {
  if (!normals.fold_nodes.empty()) {
    std::string nodes;
    for (std::size_t k = 0; k < normals.fold_nodes.size() && k < 8; ++k)
      nodes += (k ? ", " : "") + std::to_string(normals.fold_nodes[k]);
    if (normals.fold_nodes.size() > 8)
      nodes += " and " + std::to_string(normals.fold_nodes.size() - 8) + " more";
    warnings.push_back(std::to_string(normals.fold_nodes.size()) +
                       " shell nodes are folds: the normals of the elements sharing them differ "
                       "by more than " +
                       format("%.0f", kNormalAveragingDegrees) +
                       " degrees, so each element keeps its own there (give *NORMAL where the "
                       "shell is smooth): nodes " +
                       nodes);
  }
  warnings.insert(warnings.end(), normals.warnings.begin(), normals.warnings.end());
}

}  // namespace

int spurious_shell_modes(const TElement& element, RuleKind kind, int cells) {
  if (!is_shell(element)) return 0;
  Section section;
  section.elset = "PATCH";
  section.thickness = 0.1;
  section.shell = ShellSection{};
  Material unit;
  unit.name = "UNIT";
  unit.young = 1.0;
  unit.poisson = 0.3;
  // A cells x cells patch (2x2 unless asked) of unit squares on a grid of
  // (cells order + 1)^2 points; node a of an element sits at
  // grid point (order (cell_x + (xi_a + 1) / 2), order (cell_y + (eta_a + 1) / 2)). Triangles
  // (natural corners (0, 0), (1, 0), (0, 1)) cut each square into two along its diagonal.
  const bool triangle = element.node_count() == 3;
  const int order = element.node_count() <= 4 ? 1 : 2, side = cells * order + 1;
  const int dofs = 6 * side * side;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(dofs, dofs);
  std::vector<char> used(side * side, 0);
  ElementGeometry g;
  g.X.setZero(element.node_count(), 3);
  g.section = &section;
  g.cross_section = 0.1;
  const auto add_element = [&](const std::vector<std::array<int, 2>>& points) {
    std::vector<int> grid;
    for (const auto& [i, j] : points) {
      g.X.row(static_cast<Eigen::Index>(grid.size())) << static_cast<double>(i) / order,
          static_cast<double>(j) / order, 0.0;
      grid.push_back(j * side + i);
      used[j * side + i] = 1;
    }
    Eigen::MatrixXd Ke;
    element.stiffness(g, unit, kind, Ke);
    for (std::size_t a = 0; a < grid.size(); ++a)
      for (std::size_t b = 0; b < grid.size(); ++b)
        K.block<6, 6>(6 * grid[a], 6 * grid[b]) += Ke.block<6, 6>(6 * a, 6 * b);
  };
  for (int cell = 0; cell < cells * cells; ++cell) {
    const int x0 = cell % cells, y0 = cell / cells;
    if (triangle) {
      add_element({{x0, y0}, {x0 + 1, y0}, {x0 + 1, y0 + 1}});
      add_element({{x0, y0}, {x0 + 1, y0 + 1}, {x0, y0 + 1}});
      continue;
    }
    std::vector<std::array<int, 2>> points;
    for (const Vec3& xi : element.natural_nodes())
      points.push_back({order * x0 + static_cast<int>(std::lround(order * (xi[0] + 1.0) / 2.0)),
                        order * y0 + static_cast<int>(std::lround(order * (xi[1] + 1.0) / 2.0))});
    add_element(points);
  }
  std::vector<int> kept;  // the grid points the type has (no centre nodes for 8-node elements)
  for (int p = 0; p < side * side; ++p)
    if (used[p])
      for (int d = 0; d < 6; ++d) kept.push_back(6 * p + d);
  Eigen::MatrixXd Kr(kept.size(), kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i)
    for (std::size_t j = 0; j < kept.size(); ++j) Kr(i, j) = K(kept[i], kept[j]);
  return modes_beyond_rigid(Kr);
}

std::vector<std::string> shell_warnings(const Model& model, const PreparedModel& prepared) {
  std::vector<std::string> warnings;
  std::map<std::pair<const TElement*, RuleKind>, int> count_of;
  for (int e = 0; e < model.element_count(); ++e)
    if (is_shell(*prepared.formulation[e]))
      ++count_of[{prepared.formulation[e], prepared.rule_kind[e]}];
  for (const auto& [key, count] : count_of) {
    const int modes = spurious_shell_modes(*key.first, key.second);
    if (modes > 0)
      warnings.push_back(
          std::to_string(count) + " elements of type " + key.first->name() + " (" +
          key.first->rule(key.second).label + ") have " + std::to_string(modes) +
          " zero-energy modes in a flat 2x2 patch beyond the rigid motions: where the supports "
          "do not restrain them the model is singular, and coarse meshes can show them; use "
          "more elements, " +
          (key.first->node_count() == 9 ? "S8R or the fully integrated S9"
                                        : "S9 (the fully integrated 9-node Lagrange shell)"));
  }
  // A small reduced-integration mesh, checked whole, where the patch count saw nothing.
  if (std::none_of(count_of.begin(), count_of.end(), [](const auto& entry) {
        return spurious_shell_modes(*entry.first.first, entry.first.second) > 0;
      })) {
    const int modes = reduced_shell_mesh_modes(model, prepared);
    if (modes > 0)
      warnings.push_back(
          "the mesh of reduced-integration shell elements (" + std::to_string(modes) +
          " zero-energy modes beyond the rigid motions when assembled without supports, "
          "checked whole as it has at most " +
          std::to_string(kWholeMeshLimit) +
          " elements): where the supports do not restrain them the model is singular; use "
          "more elements or the fully integrated types (S8, S9)");
  }
  // Shear locking of S8, per section: the most slender element and how many are warned of.
  struct Worst {
    int count = 0;
    int element = -1;
    double slenderness = 0.0;
  };
  std::map<int, Worst> locking;
  for (int e = 0; e < model.element_count(); ++e) {
    if (!locks_in_shear(*prepared.formulation[e], prepared.rule_kind[e])) continue;
    const Section& section = model.sections[model.elements[e].section];
    const double slenderness = element_size(model, e) / section.thickness.value_or(1.0);
    if (slenderness < kSlenderWarned) continue;
    Worst& w = locking[model.elements[e].section];
    ++w.count;
    if (w.element < 0 || slenderness > w.slenderness) w.element = e, w.slenderness = slenderness;
  }
  for (const auto& [s, w] : locking) {
    const Section& section = model.sections[s];
    warnings.push_back(
        section.where.file + ":" + std::to_string(section.where.line) + ": " +
        std::to_string(w.count) + " S8 elements of element set " + section.elset +
        " are thin: element size / thickness up to " + format("%.3g", w.slenderness) +
        " (element " + std::to_string(model.elements[w.element].id) +
        "), where the fully integrated 8-node serendipity shell locks in shear (SPEC §7.3 "
        "Tab 7.1b: 8 % too stiff at 25, 87 % at 250); remedy: reduced integration (S8R), the "
        "9-node Lagrange shell (S9 or S9R) or more elements");
  }
  append_normal_warnings(prepared.shell_normals, warnings);
  return warnings;
}

}  // namespace styk::solver_detail
