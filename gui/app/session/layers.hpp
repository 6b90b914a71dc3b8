// Layer bookkeeping of the model tree: which element groups the view draws, each shown or hidden
// with its own colour. Layers follow the model's parts: the element sets its sections name (in
// section order), or, without sections (a results file holds only the mesh), the element sets
// that do not overlap one another; elements in no layer form "OTHER"; a model without usable sets
// is one layer "ALL". Rebuilding after an edit keeps the user's visibility and colour by name.
// User layers (New layer from filter / selection, layer_edits.hpp) come first: each is the element
// set of its name and claims its elements, which the part layers then leave out (an element is
// drawn once). A user layer whose set does not exist (its creation undone) is not shown; it comes
// back with its set on redo.
#pragma once

#include <string>
#include <vector>

#include "styk/core/model.hpp"
#include "styk/render/layers.hpp"

namespace styk::gui {

class LayerTable {
 public:
  // Recomputes the layers of `model`, keeping visibility and colour of layers that keep their name.
  void rebuild(const Model& model);

  const std::vector<render::Layer>& layers() const { return layers_; }
  // Throw std::out_of_range for an unknown name.
  void set_visible(const std::string& name, bool visible);
  void set_color(const std::string& name, const render::Rgb& color);
  // Makes the element set `name` (upper-case) a user layer from the next rebuild() on.
  void add_user_layer(const std::string& name);
  const std::vector<std::string>& user_layers() const { return user_layers_; }
  const render::Layer& layer(const std::string& name) const;
  bool any_visible() const;

 private:
  render::Layer& find(const std::string& name);
  bool is_user_layer(const std::string& name) const;
  std::vector<render::Layer> layers_;
  std::vector<std::string> user_layers_;  // in creation order
};

}  // namespace styk::gui
