#include "session/selection_sets.hpp"

#include "session/input_checks.hpp"

namespace styk::gui {
namespace {

class AddElementSet : public Command {
 public:
  explicit AddElementSet(ElementSet s) : set_(std::move(s)) {}
  std::string text() const override { return "Add element set " + set_.name; }
  bool keeps_results() const override { return true; }
  void redo(Model& model) override { model.elsets[set_.name] = set_; }
  void undo(Model& model) override { model.elsets.erase(set_.name); }

 private:
  ElementSet set_;
};

class AddSurface : public Command {
 public:
  explicit AddSurface(Surface s) : surface_(std::move(s)) {}
  std::string text() const override { return "Add surface " + surface_.name; }
  bool keeps_results() const override { return true; }
  void redo(Model& model) override { model.surfaces[surface_.name] = surface_; }
  void undo(Model& model) override { model.surfaces.erase(surface_.name); }

 private:
  Surface surface_;
};

// A node set defined from the view: the shared node-set command, marked as keeping results.
class AddPickedNodeSet : public Command {
 public:
  explicit AddPickedNodeSet(NodeSet s) : inner_(make_add_node_set(std::move(s))) {}
  std::string text() const override { return inner_->text(); }
  bool keeps_results() const override { return true; }
  void redo(Model& model) override { inner_->redo(model); }
  void undo(Model& model) override { inner_->undo(model); }

 private:
  std::unique_ptr<Command> inner_;
};

void check_indices(const Model& model, const Selection& selection) {
  for (int n : selection.nodes())
    if (n < 0 || n >= model.node_count())
      refuse("the selection is older than the model: pick again");
  for (int e : selection.elements())
    if (e < 0 || e >= model.element_count())
      refuse("the selection is older than the model: pick again");
  for (const SurfaceFace& f : selection.faces())
    if (f.element < 0 || f.element >= model.element_count() || f.face < 1)
      refuse("the selection is older than the model: pick again");
}

}  // namespace

std::unique_ptr<Command> set_from_selection_command(const Model& model, const Selection& selection,
                                                    const std::string& name) {
  const std::string what = selection.kind() == PickKind::Node      ? "the node set"
                           : selection.kind() == PickKind::Element ? "the element set"
                                                                   : "the surface";
  if (selection.empty())
    refuse("nothing is selected: pick " + pick_kind_name(selection.kind()) + "s in the view first");
  check_name(name, what);
  const std::string upper = to_upper(name);
  check_set_names_free(model, upper);
  check_indices(model, selection);
  switch (selection.kind()) {
    case PickKind::Node: {
      NodeSet set;
      set.name = upper;
      set.nodes = selection.nodes();
      return std::make_unique<AddPickedNodeSet>(std::move(set));
    }
    case PickKind::Element: {
      ElementSet set;
      set.name = upper;
      set.elements = selection.elements();
      return make_add_element_set(std::move(set));
    }
    case PickKind::Face:
      break;
  }
  Surface surface;
  surface.name = upper;
  surface.kind = Surface::Kind::ElementFaces;
  surface.faces = selection.faces();
  return make_add_surface(std::move(surface));
}

std::unique_ptr<Command> make_add_element_set(ElementSet set) {
  return std::make_unique<AddElementSet>(std::move(set));
}

std::unique_ptr<Command> make_add_surface(Surface surface) {
  return std::make_unique<AddSurface>(std::move(surface));
}

}  // namespace styk::gui
