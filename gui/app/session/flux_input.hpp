// *DFLUX as the "Face flux" dialog asks for it: a uniform heat flux (per area, positive into the
// body) on the faces of an element-face surface, or on face S1..S6 of every element of an element
// set — the faces a pressure takes (validation.hpp), one *DFLUX entry per face. Face fluxes belong
// to steady heat transfer steps: the deck reader refuses *DFLUX in static and electric steps.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "session/commands.hpp"
#include "session/validation.hpp"
#include "styk/core/model.hpp"

namespace styk::gui {

// The same fields as a pressure; `magnitude` is the flux per area.
using FluxInput = PressureInput;

struct NamedFaces {
  std::vector<SurfaceFace> faces;
  std::string name;  // "SURF", or "ELSET S3"
};
// The faces of surface `surface`, or (surface empty) face `face` of every element of `elset`.
// Refused: unknown or empty surface / element set, a node surface, face outside 1..6.
NamedFaces faces_of(const Model& model, const std::string& surface, const std::string& elset,
                    int face);

// Step `step` must be a heat transfer step; a model without one, a static or electric step are
// refused with what to do.
void check_flux_step(const Model& model, int step);

std::unique_ptr<Command> flux_command(const Model& model, const FluxInput& input);

}  // namespace styk::gui
