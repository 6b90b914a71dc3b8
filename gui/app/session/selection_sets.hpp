// A set made from the selection in the view (issue 7): picked nodes become a node set, picked
// elements an element set, picked faces an element-face surface, under a name the user gives,
// as one undoable edit, so boundary conditions, loads and contact pairs can use it. Defining a
// set changes neither the mesh nor the analysis, so results on display stay attached.
#pragma once

#include <memory>
#include <string>

#include "session/commands.hpp"
#include "session/selection.hpp"

namespace styk::gui {

// Throws InputError (for the dialog) when the selection is empty, the name is not a valid set
// name, or a node set, element set or surface of that name exists; the set gets the upper-case
// name. Indices the model does not hold are an InputError too (a selection older than an edit).
std::unique_ptr<Command> set_from_selection_command(const Model& model, const Selection& selection,
                                                    const std::string& name);

std::unique_ptr<Command> make_add_element_set(ElementSet set);
std::unique_ptr<Command> make_add_surface(Surface surface);

}  // namespace styk::gui
