// "Contact pair": a *SURFACE INTERACTION with its *FRICTION and one *CONTACT PAIR (slave nodes
// against master faces) with an optional *CLEARANCE, as the dialog asks for them, checked, and
// the undoable commands that add or replace them.
#pragma once

#include <memory>
#include <string>

#include "session/commands.hpp"
#include "styk/core/model.hpp"

namespace styk::gui {

struct ContactInput {
  std::string slave;        // surface names (Model::surfaces)
  std::string master;       // an element-face surface
  std::string interaction;  // *SURFACE INTERACTION name (new, or the pair's own when editing)
  // "frictionless", "isotropic" (mu), "anisotropic" (mu, mu2 along the axes of `orientation`),
  // "rough" (no slip)
  std::string friction = "isotropic";
  double mu = 0.2;
  double mu2 = 0.0;
  std::string orientation;  // anisotropic: an *ORIENTATION of the model
  // NODE TO SURFACE, SURFACE TO SURFACE or MORTAR (the last two need element faces on the slave).
  ContactPair::Type type = ContactPair::Type::NodeToSurface;
  bool has_clearance = false;
  double clearance = 0.0;  // > 0 open gap, < 0 interference (replaces the geometric gap)
};

// Throws InputError for an unknown or empty surface, the same surface twice, a master without
// element faces, mu < 0, an unknown orientation, an interaction name in use.
// `replacing` >= 0: the pair being edited (its own interaction name is not "in use").
std::unique_ptr<Command> contact_command(const Model& model, const ContactInput& input,
                                         int replacing = -1);
// The dialog's fields of an existing pair (for editing).
ContactInput contact_input_of(const Model& model, int pair);

}  // namespace styk::gui
