// The view styk-gui keeps with a deck (issue 7: user layers and the element filter survive a save
// and an open): which layers are user layers, each layer's visibility and colour, and the element
// filter. They travel as comment lines at the end of the deck, so the solver, CalculiX and Abaqus
// read the deck unchanged:
//
//   **STYK LAYER, NAME=SLEEVE, USER=YES, VISIBLE=NO, COLOR=CC3311
//   **STYK FILTER, IDS=1-500 700, TYPES=C3D20 C3D21
//
// A user layer is an element set of the deck (*ELSET) drawn before the part layers; NAME is that
// set. COLOR is 8-bit RGB in hex. A view line that cannot be applied (a layer or type the model
// lacks, a malformed value) never refuses the deck: it is dropped with a "file:line: ..." warning.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "session/element_filter.hpp"
#include "session/layers.hpp"
#include "styk/core/model.hpp"

namespace styk::gui {

struct LayerStyle {
  std::string name;  // upper-case
  bool user = false;
  bool visible = true;
  render::Rgb color;
  int line = 0;  // the deck line it was read from (0: not read)
};

struct ViewState {
  std::vector<LayerStyle> layers;
  // The filter's text as the dialog takes it (ranges "1-500 700", upper-case types); empty: none.
  std::string filter_ids;
  std::vector<std::string> filter_types;
  int filter_line = 0;
};

ViewState view_state_of(const LayerTable& layers, const ElementDisplayFilter& filter);
// The comment block (nothing when the state holds no layer and no filter).
void write_view_state(const ViewState& state, std::ostream& out);

struct ReadViewState {
  ViewState state;
  std::vector<std::string> warnings;  // "file:line: message"
};
// The **STYK lines of the deck at `path` (only that file: an *INCLUDEd file holds none). A line
// starting "**STYK" that is no LAYER or FILTER, or whose values are malformed, is a warning.
ReadViewState read_view_state(const std::string& path);

// Restores a read state onto the layers of `model` (user layers registered, the table rebuilt,
// visibility and colours set) and returns the filter. Entries the model cannot take are dropped
// with a warning appended to `warnings`.
ElementDisplayFilter apply_view_state(const ViewState& state, const std::string& path,
                                      const Model& model, LayerTable& layers,
                                      std::vector<std::string>& warnings);

}  // namespace styk::gui
