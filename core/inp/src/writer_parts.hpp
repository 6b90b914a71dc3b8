// Pieces of write_inp() kept in their own files so each stays about one group of keywords.
// Private to styk_inp.
#pragma once

#include <ostream>
#include <string>

#include "styk/core/model.hpp"

namespace styk::inp {

// The longest number CalculiX reads in one field of a data line (it refuses the card otherwise).
constexpr int kMaxFieldChars = 20;
// The shortest text that reads back as exactly `value`. The few doubles whose shortest exact form
// is longer than kMaxFieldChars, such as 1.2246467991473532e-16 or -0.0070710678118654755, are
// written with as many significant digits as fit (13 or more: a relative rounding below 5e-13),
// so that CalculiX reads every deck Styk writes; those values round-trip to that rounding only.
std::string shortest_number(double value);

// *ELASTIC (type and table over temperature), *DENSITY and *EXPANSION of a material.
void write_material_law(const Material& m, std::ostream& out);

// *ORIENTATION, *SURFACE, *SURFACE INTERACTION (+ *SURFACE BEHAVIOR, *FRICTION), *CONTACT PAIR,
// *CLEARANCE, *TRANSFORM, *EQUATION and *INITIAL CONDITIONS of the model part.
void write_contact_and_constraints(const Model& model, std::ostream& out);

// *TIE, *COUPLING (+ *KINEMATIC / *DISTRIBUTING), *MPC, *PRE-TENSION SECTION and *INITIAL
// CONDITIONS, TYPE=STRESS of the model part (constraint_writer.cpp).
void write_ties_and_couplings(const Model& model, std::ostream& out);
// A step's *CHANGE SOLID SECTION and *BOUNDARY, FIXED lines (before its other boundaries).
void write_step_changes(const Model& model, const Step& step, std::ostream& out);
// A step's *DLOAD GRAV / CENTRIF lines.
void write_body_loads(const Model& model, const Step& step, std::ostream& out);
// The step's *PRESSURE PENETRATION definitions (Styk extension: a deck meant for CalculiX must
// not carry them, docs/input.md).
void write_step_penetrations(const Model& model, const Step& step, std::ostream& out);

// The step's *TEMPERATURE block (nothing when the step has none and no OP=NEW).
void write_step_temperatures(const Model& model, const Step& step, std::ostream& out);

}  // namespace styk::inp
