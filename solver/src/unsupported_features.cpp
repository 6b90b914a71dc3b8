#include "unsupported_features.hpp"

#include "styk/core/step_kind.hpp"

namespace styk::solver_detail {

void reject_unsupported_features(const Model& model) {
  // Both paths apply *EQUATION, *TRANSFORM and step temperatures (model_constraints.hpp,
  // thermal_load.hpp). Ties, couplings, MPCs and pre-tension sections act on displacements: a
  // steady heat or electric deck refuses them.
  bool scalar = false;
  for (const Step& step : model.steps) scalar = scalar || step.kind != StepKind::Static;
  if (!scalar) return;
  auto refuse = [](const SourceLoc& where, const std::string& what) {
    throw InputError(where, what +
                                " constrains displacements; a *HEAT TRANSFER or *COUPLED "
                                "THERMAL-ELECTRICAL deck cannot use it");
  };
  if (!model.ties.empty()) refuse(model.ties.front().where, "*TIE");
  if (!model.couplings.empty()) refuse(model.couplings.front().where, "*COUPLING");
  if (!model.mpcs.empty()) refuse(model.mpcs.front().where, "*MPC");
  if (!model.pretension_sections.empty())
    refuse(model.pretension_sections.front().where, "*PRE-TENSION SECTION");
}

}  // namespace styk::solver_detail
