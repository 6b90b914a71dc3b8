// Private: contact output (IncrementResult::contact) as scalar fields of the renderer, one value
// per slave node, undefined elsewhere.
#pragma once

#include <string>
#include <vector>

#include "styk/core/model.hpp"
#include "styk/core/results.hpp"
#include "styk/render/field.hpp"

namespace styk::render {

// True for the quantities this module draws: CPRESS, CSHEAR, CSLIP, CGAP, CSTATUS
// (upper-case, without the component suffix).
bool is_contact_quantity(const std::string& quantity);

// Canonical names of the contact fields, for field_names().
std::vector<std::string> contact_field_names();

// Evaluates contact field `quantity`.`suffix` (suffix lower-case, may be empty). `drawable` lists
// the other fields the increment holds, for the message when it holds no contact output. A
// non-empty `pair` (the slave surface of one *CONTACT PAIR line, case-insensitive) keeps that
// pair's output only; an unknown one is an InputError listing the pairs' slave surfaces. The
// field carries the faces of the slave surfaces (ScalarField::support).
ScalarField evaluate_contact_field(const Model& model, const IncrementResult& increment,
                                   const std::string& quantity, const std::string& suffix,
                                   const std::string& drawable, const std::string& pair = "");

}  // namespace styk::render
