#include "shell_warnings.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

#include "assembly.hpp"
#include "shell_locking.hpp"
#include "shell_mesh_modes.hpp"
#include "warning_format.hpp"
#include "zero_energy_modes.hpp"

namespace styk::solver_detail {
namespace {

bool is_shell(const TElement& element) {
  return element.section_measure() == SectionMeasure::Shell;
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
  std::vector<Eigen::Index> kept;  // the grid points the type has (no centre node in S8)
  for (int p = 0; p < side * side; ++p)
    if (used[p])
      for (int d = 0; d < 6; ++d) kept.push_back(6 * p + d);
  return std::max(0, zero_eigenvalue_count(K, kept) - 6);
}

std::vector<std::string> shell_warnings(const Model& model, const PreparedModel& prepared) {
  std::vector<std::string> warnings;
  const int modes = supported_shell_mesh_modes(model, prepared);
  if (modes > 0)
    warnings.push_back(
        "the mesh of reduced-integration shell elements has " + std::to_string(modes) +
        " zero-energy modes that its supports leave free (checked whole with its *BOUNDARY "
        "conditions, as it has at most " +
        std::to_string(kWholeShellMeshLimit) +
        " elements): unless other elements or constraints hold them the model is singular, "
        "and coarse meshes show them; use more elements or the fully integrated types (S8, "
        "S9)");
  for (std::string& warning : shell_locking_warnings(model, prepared))
    warnings.push_back(std::move(warning));
  for (std::string& warning : thick_kirchhoff_shell_warnings(model, prepared))
    warnings.push_back(std::move(warning));
  append_normal_warnings(prepared.shell_normals, warnings);
  return warnings;
}

}  // namespace styk::solver_detail
