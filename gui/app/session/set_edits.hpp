// Editing a node set, element set or surface from the model tree: a new name (what refers to the
// set by name follows: *TRANSFORM, contact pairs, sections, output requests) and its members from
// the selection in the view (replace, add, remove: picked nodes for a node set, elements for an
// element set, faces for a surface), as one undoable command. Boundary conditions and loads hold
// node and face indices, not set names, so they stay as they are.
#pragma once

#include <memory>
#include <string>

#include "session/commands.hpp"
#include "session/entry_edits.hpp"
#include "session/selection.hpp"

namespace styk::gui {

enum class Membership { Keep, Replace, Add, Remove };

struct SetEditInput {
  std::string name;  // the new name (the same name: no rename)
  Membership membership = Membership::Keep;
};

// "keep", "replace with the selection", "add the selection", "remove the selection".
std::string membership_name(Membership membership);
Membership membership_of(const std::string& name);  // InputError for another text

// `entry` is a NodeSet, ElementSet or Surface entry. Refused (InputError): an invalid or used
// name, a selection of another kind than the set holds (or empty, or older than the model),
// a set that would become empty, an element set with a section gaining an element of another
// section. Results stay attached unless an element set with a section changes its members.
std::unique_ptr<Command> set_edit_command(const Model& model, const Entry& entry,
                                          const SetEditInput& input, const Selection& selection);

}  // namespace styk::gui
