#include "beam_warnings.hpp"

#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

#include "assembly.hpp"
#include "section_extent.hpp"
#include "styk/core/beam_section.hpp"
#include "warning_format.hpp"
#include "zero_energy_modes.hpp"

namespace styk::solver_detail {
namespace {

// Locking is warned of where it costs an estimated 10 % of the deflection or more, the error
// docs/stability.md counts as failing. A 2-node element's bending stiffens by 1 + f, so its
// deflection falls short by f / (1 + f): 10 % from f = 0.11. Measured (styk study stability,
// thin-beam: 8 B31/B21 with INTEGRATION=FULL under a uniform load; SPEC §7.3 Tab 7.1a): f 0.045
// -> 3.9 % error, 0.078 -> 7.2 % (Tab 7.1a thick, 8 elements), 0.31 -> 24 % (4 elements), 0.50
// -> 33 %. A 3-node element locks only the part of its bending that varies within it; fully
// locked, that part costs about (l / L)^2 / 3 of the deflection, L the extent of the member's
// section (section_extent.hpp): a cantilever of n elements with a linear moment loses 1 / (4 n^2)
// (each element keeps its mean curvature), and under a uniform load the 8 B32/B22 elements of
// the sweep level off at 0.52 % = (1/8)^2 / 3 (docs/stability.md). So a 3-node element is warned
// of only where it is a large part of its member: one or two elements per member.
constexpr double kLockingWarned = 0.10;
constexpr double kQuadraticLockedShare = 1.0 / 3.0;

bool is_beam(const TElement& element) { return element.section_measure() == SectionMeasure::Beam; }

// The section depth across which a bending about section axis `axis` (0: axis 1, 1: axis 2)
// acts: the extent of the section along the other axis.
double depth(const BeamSection& section, int axis) {
  const std::vector<double>& d = section.dimensions;
  switch (section.shape) {
    case BeamShape::Rect:
    case BeamShape::Box:
      return axis == 0 ? d[1] : d[0];
    case BeamShape::Circ:
      return axis == 0 ? (d.size() > 1 ? d[1] : d[0]) : d[0];
    case BeamShape::Pipe:
      return 2.0 * d[0];
  }
  return 1.0;
}

std::string locking_warning(const Model& model, const Section& section, const TElement& type,
                            int count, const BeamLocking& worst, int worst_element) {
  const bool linear = type.node_count() == 2;
  const std::string quadratic = type.name() == "B21" ? "B22" : "B32";
  return section.where.file + ":" + std::to_string(section.where.line) + ": " +
         std::to_string(count) + " " + type.name() + " elements of element set " + section.elset +
         " are fully integrated (INTEGRATION=FULL) and slender: element length " +
         "/ section depth up to " + format("%.3g", worst.slenderness) + " (element " +
         std::to_string(model.elements[worst_element].id) + "), so shear locking makes " +
         (linear ? "their bending" : "the varying part of their bending") + " about " +
         format("%.3g", 1.0 + worst.factor) + " times too stiff (k G A l^2 / (" +
         (linear ? "12" : "60") + " E I) = " + format("%.3g", worst.factor) + ")" +
         (linear ? std::string()
                 : ", which with elements " + format("%.2g", worst.share_of_member) +
                       " of their member's extent can cost (l / L)^2 / 3 of the deflection") +
         ": the deflection estimated " + format("%.0f", 100.0 * worst.error) +
         " % short; remedy: reduced integration (drop INTEGRATION=FULL, the Abaqus default)" +
         (linear ? ", the quadratic " + quadratic + " elements" : std::string()) +
         " or more elements (the error falls with the element length squared)";
}

}  // namespace

BeamLocking beam_locking(const Model& model, const PreparedModel& prepared, int e,
                         double member_extent) {
  BeamLocking out;
  const Section& section = model.sections[model.elements[e].section];
  const Material& material = *prepared.material[e];
  if (!section.beam || !check_beam_section(*section.beam).empty()) return out;
  const BeamSectionProperties p = beam_section_properties(*section.beam);
  const double E = *material.young, G = E / (2.0 * (1.0 + *material.poisson));
  const int* nodes = model.element_nodes(e);
  const Vec3& a = model.coords[nodes[0]];
  const Vec3& b = model.coords[nodes[model.elements[e].node_count - 1]];
  const double l = std::sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) +
                             (b[2] - a[2]) * (b[2] - a[2]));
  const bool two_node = prepared.formulation[e]->node_count() == 2;
  const double c = two_node ? 12.0 : 60.0;
  const bool planar = !prepared.formulation[e]->active_dofs()[2];
  // Bending about axis 1 is resisted with shear along axis 2, and about axis 2 with axis 1.
  const double about1 = G * p.shear_area2 * l * l / (c * E * p.I11);
  const double about2 = planar ? 0.0 : G * p.shear_area1 * l * l / (c * E * p.I22);
  const int axis = about1 >= about2 ? 0 : 1;
  out.factor = std::max(about1, about2);
  out.slenderness = l / depth(*section.beam, axis);
  out.share_of_member = member_extent > 0.0 ? std::min(1.0, l / member_extent) : 1.0;
  const double locked = out.factor / (1.0 + out.factor);
  out.error = two_node ? locked
                       : locked * kQuadraticLockedShare * out.share_of_member * out.share_of_member;
  return out;
}

int spurious_beam_modes(const TElement& element, RuleKind kind) {
  if (!is_beam(element)) return 0;
  Section section;
  section.elset = "PATCH";
  section.beam = BeamSection{};
  section.beam->dimensions = {1.0, 1.0};
  Material unit;
  unit.name = "UNIT";
  unit.young = 1.0;
  unit.poisson = 0.3;
  const int n = element.node_count();
  const int nodes = 2 * n - 1;  // two elements along x sharing one end node
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(6 * nodes, 6 * nodes);
  ElementGeometry g;
  g.X.setZero(n, 3);
  g.section = &section;
  for (int cell = 0; cell < 2; ++cell) {
    for (int k = 0; k < n; ++k) g.X(k, 0) = cell + (element.natural_nodes()[k][0] + 1.0) / 2.0;
    Eigen::MatrixXd Ke;
    element.stiffness(g, unit, kind, Ke);
    const int first = cell * (n - 1);
    K.block(6 * first, 6 * first, 6 * n, 6 * n) += Ke;
  }
  // Only the dofs the type stiffens (planar beams: ux, uy, rz).
  const DofSet active = element.active_dofs();
  std::vector<Eigen::Index> kept;
  for (int node = 0; node < nodes; ++node)
    for (int d = 0; d < 6; ++d)
      if (active[d]) kept.push_back(6 * node + d);
  const int rigid = active[2] ? 6 : 3;
  return std::max(0, zero_eigenvalue_count(K, kept) - rigid);
}

std::vector<std::string> beam_warnings(const Model& model, const PreparedModel& prepared) {
  std::vector<std::string> warnings;
  // Spurious modes, per type and rule (computed once each).
  std::map<std::pair<const TElement*, RuleKind>, int> count_of;
  for (int e = 0; e < model.element_count(); ++e)
    if (is_beam(*prepared.formulation[e]))
      ++count_of[{prepared.formulation[e], prepared.rule_kind[e]}];
  for (const auto& [key, count] : count_of) {
    const int modes = spurious_beam_modes(*key.first, key.second);
    if (modes > 0)
      warnings.push_back(std::to_string(count) + " elements of type " + key.first->name() + " (" +
                         key.first->rule(key.second).label + ") have " + std::to_string(modes) +
                         " zero-energy modes in a 2-element patch beyond the rigid motions: "
                         "their displacements and section forces can be garbage; integrate "
                         "them with more points or use another type");
  }
  // Shear locking, per section and type: the worst element and how many are warned of.
  struct Worst {
    int count = 0;
    int element = -1;
    BeamLocking locking;
  };
  std::map<std::pair<int, const TElement*>, Worst> locking;
  const std::vector<double> extent = section_extents(model);
  for (int e = 0; e < model.element_count(); ++e) {
    if (!is_beam(*prepared.formulation[e]) || prepared.rule_kind[e] != RuleKind::Full) continue;
    const TElement& type = *prepared.formulation[e];
    if (type.rule(RuleKind::Full).size() == type.rule(RuleKind::Reduced).size()) continue;
    const BeamLocking l = beam_locking(model, prepared, e, extent[model.elements[e].section]);
    if (l.error < kLockingWarned) continue;
    Worst& w = locking[{model.elements[e].section, &type}];
    ++w.count;
    if (w.element < 0 || l.error > w.locking.error) w.element = e, w.locking = l;
  }
  for (const auto& [key, w] : locking)
    warnings.push_back(locking_warning(model, model.sections[key.first], *key.second, w.count,
                                       w.locking, w.element));
  return warnings;
}

}  // namespace styk::solver_detail
