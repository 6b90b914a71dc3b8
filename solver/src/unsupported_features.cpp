#include "unsupported_features.hpp"

namespace styk::solver_detail {

void reject_unsupported_features(const Model& model) {
  // The contact path (contact_analysis.cpp) does not apply *EQUATION, *TRANSFORM or step
  // temperatures yet; the linear path does (model_constraints.hpp, thermal_load.hpp).
  if (model.contact_pairs.empty()) return;
  if (!model.equations.empty())
    throw InputError(model.equations.front().where,
                     "*EQUATION together with *CONTACT PAIR is not available yet in this build");
  if (!model.transforms.empty())
    throw InputError(model.transforms.front().where,
                     "*TRANSFORM together with *CONTACT PAIR is not available yet in this build");
  for (const Step& step : model.steps)
    if (!step.temperatures.empty())
      throw InputError(step.temperatures.front().where,
                       "*TEMPERATURE together with *CONTACT PAIR is not available yet in this "
                       "build");
}

}  // namespace styk::solver_detail
