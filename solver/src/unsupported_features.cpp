#include "unsupported_features.hpp"

namespace styk::solver_detail {

void reject_unsupported_features(const Model& model) {
  if (!model.contact_pairs.empty())
    throw InputError(model.contact_pairs.front().where,
                     "*CONTACT PAIR: contact analysis is not available yet in this build");
  for (const Step& step : model.steps)
    for (const OutputRequest& output : step.outputs)
      if (output.kind == OutputRequest::Kind::ContactPrint)
        throw InputError(output.where,
                         "*CONTACT PRINT: contact output is not available yet in this build");
  if (!model.equations.empty())
    throw InputError(model.equations.front().where,
                     "*EQUATION: multi-point constraints are not available yet in this build");
  if (!model.transforms.empty())
    throw InputError(model.transforms.front().where,
                     "*TRANSFORM: local coordinate systems for boundary conditions and loads are "
                     "not available yet in this build");
  // Initial temperatures alone strain nothing (thermal strain follows T - T_initial); prescribed
  // step temperatures would.
  for (const Step& step : model.steps)
    if (!step.temperatures.empty())
      throw InputError(step.temperatures.front().where,
                       "*TEMPERATURE: thermal loading is not available yet in this build");
}

}  // namespace styk::solver_detail
