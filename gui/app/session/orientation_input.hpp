// *ORIENTATION as the dialog asks for it: a named local system given, as for *TRANSFORM, by
// SYSTEM=R|C and two points a, b (anisotropic friction takes its slip directions 1, 2 from one).
// local_axes() is the one check of such a system, shared with the transform dialog
// (constraint_input.hpp), so both refuse degenerate data with the same words.
#pragma once

#include <memory>
#include <string>

#include "session/commands.hpp"
#include "styk/core/model.hpp"

namespace styk::gui {

// Rectangular: local x along a (from the origin), y in the plane of a and b. Cylindrical: a and b
// on the axis. InputError for a non-finite coordinate, a at the origin, b on the line of a, or
// coinciding axis points.
LocalAxes local_axes(bool cylindrical, const Vec3& a, const Vec3& b);

struct OrientationInput {
  std::string name;
  bool cylindrical = false;
  Vec3 a{1, 0, 0};
  Vec3 b{0, 1, 0};
};

// Refused: a bad or empty name, a name another orientation has (except `replacing`, the one being
// edited; empty for a new one), degenerate axes.
Orientation checked_orientation(const Model& model, const OrientationInput& input,
                                const std::string& replacing);
std::unique_ptr<Command> orientation_command(const Model& model, const OrientationInput& input);

// Editing orientation `name`: the dialog's fields, and the edit. A new name is followed by the
// anisotropic frictions that name it.
OrientationInput orientation_input_of(const Model& model, const std::string& name);
std::unique_ptr<Command> orientation_edit_command(const Model& model, const std::string& name,
                                                  const OrientationInput& input);

// The interaction whose friction takes its axes from orientation `name`, or empty.
std::string orientation_user(const Model& model, const std::string& name);

}  // namespace styk::gui
