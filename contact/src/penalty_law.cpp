// Penalty laws of *SURFACE BEHAVIOR: which laws the solver takes and the spring of one node.
#include "styk/contact/penalty_law.hpp"

#include <cmath>
#include <sstream>

#include "styk/core/diagnostics.hpp"

namespace styk::contact {

void check_penalty_law(const SurfaceInteraction& interaction) {
  const PressureOverclosure& behavior = interaction.behavior;
  if (behavior.law == PressureOverclosure::Law::Tied && interaction.friction)
    throw InputError(interaction.friction->where,
                     "surface interaction " + interaction.name +
                         ": PRESSURE-OVERCLOSURE=TIED ties the surfaces in every direction with "
                         "springs of slope K; *FRICTION does not apply to it (remove it)");
}

void apply_penalty_law(const SurfaceInteraction& interaction, const Surface& slave_surface,
                       const std::string& node_label, ContactConstraint& constraint) {
  const PressureOverclosure& behavior = interaction.behavior;
  if (!behavior.penalty()) return;
  const bool node_surface = slave_surface.kind == Surface::Kind::Nodes;
  const double area = node_surface ? 1.0 : constraint.area;
  if (!(area > 0.0)) {
    std::ostringstream message;
    message << "surface interaction " << interaction.name << ": slave node " << node_label
            << " of surface " << slave_surface.name << " has the nodal area " << area
            << " (the corner of a quadratic face); a penalty spring there would have a "
               "non-positive stiffness: give the slave a C3D21/C3D28 contact layer or linear "
               "elements, or use PRESSURE-OVERCLOSURE=HARD";
    throw InputError(behavior.where, message.str());
  }
  if (behavior.law == PressureOverclosure::Law::Exponential) {
    // CalculiX: p = p0 exp(-beta clearance), beta such that p drops to 1 % of p0 at c0.
    constraint.exponential_force0 = behavior.p0 * area;
    constraint.exponential_beta = std::log(100.0) / behavior.c0.value_or(0.0);
    return;
  }
  constraint.penalty_stiffness = behavior.slope * area;
  constraint.bonded = behavior.law == PressureOverclosure::Law::Tied;
}

std::string normal_law_label(const PressureOverclosure& behavior) {
  std::ostringstream out;
  switch (behavior.law) {
    case PressureOverclosure::Law::Hard:
      return "exact (hard)";
    case PressureOverclosure::Law::Linear:
      out << "penalty LINEAR K=" << behavior.slope;
      break;
    case PressureOverclosure::Law::Tied:
      out << "penalty TIED K=" << behavior.slope;
      break;
    case PressureOverclosure::Law::Exponential:
      out << "penalty EXPONENTIAL c0=" << behavior.c0.value_or(0.0) << " p0=" << behavior.p0;
      break;
  }
  return out.str();
}

}  // namespace styk::contact
