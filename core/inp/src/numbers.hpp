// Strict conversion of data-line fields to numbers: the whole field must be consumed, nan and inf
// are rejected, and every failure names the field, what it should hold and what was read.
#pragma once

#include <string>

#include "card.hpp"
#include "styk/core/model.hpp"

namespace styk::inp {

// Field `index` (0-based) of `line`; `what` names it in messages ("x coordinate", "node id").
double real_field(const DataLine& line, std::size_t index, const std::string& what);
std::int64_t integer_field(const DataLine& line, std::size_t index, const std::string& what);
// A mechanical degree of freedom 1..6 (displacements, rotations); 11 (temperature) is named as
// not supported. Whether the node carries it (rotations: beam nodes) is the solver's check.
int displacement_dof(const DataLine& line, std::size_t index, const std::string& what);
// A *BOUNDARY dof: 1..6 (displacement, rotation), 11 (temperature) or 9 (electric potential);
// whether it fits the step is checked when the deck is complete.
int boundary_dof(const DataLine& line, std::size_t index, const std::string& what);
// The largest id a deck may give a node or element: CalculiX's 32-bit ids, which also fill the
// 10-digit id columns of the .dat and .frd files exactly (docs/input.md "Ids").
inline constexpr Id kLargestId = 2147483647;

// A user id: an integer from 1 to kLargestId.
Id id_field(const DataLine& line, std::size_t index, const std::string& what);

// Conversions of parameter values; `what` is e.g. "INC= of *STEP".
double real_value(const std::string& text, const std::string& what, const SourceLoc& where);
std::int64_t integer_value(const std::string& text, const std::string& what,
                           const SourceLoc& where);

// True when the text is an optionally signed run of digits (an id rather than a set name).
bool looks_like_integer(const std::string& text);
// True when the text reads as a (finite or not) number: "12", "-1.5", "2e3".
bool looks_like_number(const std::string& text);
// A data field that names a set rather than giving an id: anything that does not read as a
// number. CalculiX set names may start with a digit ("1E"), so the first character decides
// nothing; a name that reads as a number ("12", "1E5") cannot be told from an id.
bool names_a_set(const std::string& text);

}  // namespace styk::inp
