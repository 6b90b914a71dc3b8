#include "session/flux_input.hpp"

#include <algorithm>

#include "session/input_checks.hpp"

namespace styk::gui {

NamedFaces faces_of(const Model& model, const std::string& surface, const std::string& elset,
                    int face) {
  NamedFaces out;
  if (!surface.empty()) {
    const Surface& s = existing_surface(model, surface);
    if (s.kind != Surface::Kind::ElementFaces)
      refuse("surface " + s.name + " holds nodes, not element faces");
    out.faces = s.faces;
    out.name = s.name;
    return out;
  }
  if (elset.empty()) refuse("choose a surface or an element set");
  const ElementSet* set = model.find_elset(elset);
  if (!set) refuse("no element set " + to_upper(elset) + " in the model");
  if (set->elements.empty()) refuse("element set " + set->name + " is empty");
  if (face < 1 || face > 6) refuse("face must be 1..6 (S1..S6)");
  for (int e : set->elements) out.faces.push_back({e, face});
  out.name = set->name + " S" + std::to_string(face);
  return out;
}

void check_flux_step(const Model& model, int step) {
  const bool heat = std::any_of(model.steps.begin(), model.steps.end(),
                                [](const Step& s) { return s.kind == StepKind::HeatTransfer; });
  if (!heat)
    refuse(
        "the model has no heat transfer step: a face flux (*DFLUX) belongs to one; add a step "
        "of kind heat transfer first");
  check_step(model, step, false);
  const Step& s = model.steps[step];
  if (s.kind != StepKind::HeatTransfer)
    refuse("step " + s.name + " is a " + step_kind_name(s.kind) +
           " step: a face flux (*DFLUX) belongs to a heat transfer step");
}

std::unique_ptr<Command> flux_command(const Model& model, const FluxInput& in) {
  check_flux_step(model, in.step);
  check_finite(in.magnitude, "flux");
  if (in.magnitude == 0.0) refuse("a flux of 0 does nothing; enter a value");
  const NamedFaces target = faces_of(model, in.surface, in.elset, in.face);
  std::vector<DistributedLoad> fluxes;
  for (const SurfaceFace& f : target.faces) fluxes.push_back({f.element, f.face, in.magnitude, {}});
  return make_model_edit(
      "Face flux into " + target.name,
      [step = in.step, fluxes](Model& m) {
        auto& v = m.steps.at(step).dfluxes;
        v.insert(v.end(), fluxes.begin(), fluxes.end());
      },
      [step = in.step, count = fluxes.size()](Model& m) {
        auto& v = m.steps.at(step).dfluxes;
        v.resize(v.size() - count);
      });
}

}  // namespace styk::gui
