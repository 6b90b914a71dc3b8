// Pieces of write_inp() kept in their own files so each stays about one group of keywords.
// Private to styk_inp.
#pragma once

#include <ostream>
#include <string>

#include "styk/core/model.hpp"

namespace styk::inp {

// Shortest text that reads back to exactly the same double. (CalculiX reads at most 20
// characters per field; the few doubles whose shortest exact form is longer, such as
// 1.2246467991473532e-16, are written exactly anyway: round trip comes first.)
std::string shortest_number(double value);

// *ORIENTATION, *SURFACE, *SURFACE INTERACTION (+ *SURFACE BEHAVIOR, *FRICTION), *CONTACT PAIR,
// *CLEARANCE, *TRANSFORM, *EQUATION and *INITIAL CONDITIONS of the model part.
void write_contact_and_constraints(const Model& model, std::ostream& out);

// The step's *TEMPERATURE block (nothing when the step has none and no OP=NEW).
void write_step_temperatures(const Model& model, const Step& step, std::ostream& out);

}  // namespace styk::inp
