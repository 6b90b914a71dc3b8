#include "session/commands.hpp"

#include <limits>
#include <stdexcept>
#include <utility>

namespace styk::gui {

void UndoStack::push(Model& model, std::unique_ptr<Command> command) {
  command->redo(model);
  commands_.resize(index_);
  if (clean_ > index_) clean_ = std::numeric_limits<std::size_t>::max();
  commands_.push_back(std::move(command));
  ++index_;
}

void UndoStack::undo(Model& model) {
  if (!can_undo()) return;
  commands_[--index_]->undo(model);
}

void UndoStack::redo(Model& model) {
  if (!can_redo()) return;
  commands_[index_++]->redo(model);
}

std::string UndoStack::undo_text() const {
  return can_undo() ? commands_[index_ - 1]->text() : std::string();
}

std::string UndoStack::redo_text() const {
  return can_redo() ? commands_[index_]->text() : std::string();
}

void UndoStack::clear() {
  commands_.clear();
  index_ = 0;
  clean_ = 0;
}

namespace {

class ReplaceModel : public Command {
 public:
  ReplaceModel(std::string text, Model before, Model after)
      : text_(std::move(text)), before_(std::move(before)), after_(std::move(after)) {}
  std::string text() const override { return text_; }
  void redo(Model& model) override { model = after_; }
  void undo(Model& model) override { model = before_; }

 private:
  std::string text_;
  Model before_, after_;
};

class AddMaterial : public Command {
 public:
  explicit AddMaterial(Material m) : material_(std::move(m)) {}
  std::string text() const override { return "Add material " + material_.name; }
  void redo(Model& model) override { model.materials.push_back(material_); }
  void undo(Model& model) override { model.materials.pop_back(); }

 private:
  Material material_;
};

class AddSection : public Command {
 public:
  explicit AddSection(Section s) : section_(std::move(s)) {}
  std::string text() const override { return "Add section on " + section_.elset; }
  void redo(Model& model) override {
    const ElementSet* set = model.find_elset(section_.elset);
    if (!set) throw std::logic_error("section on a missing element set " + section_.elset);
    Section section = section_;
    section.material_index = model.material_index(section.material);
    const int index = static_cast<int>(model.sections.size());
    model.sections.push_back(section);
    for (int e : set->elements) model.elements[e].section = index;
  }
  void undo(Model& model) override {
    const int index = static_cast<int>(model.sections.size()) - 1;
    for (Element& e : model.elements)
      if (e.section == index) e.section = -1;
    model.sections.pop_back();
  }

 private:
  Section section_;
};

class AddStep : public Command {
 public:
  explicit AddStep(Step s) : step_(std::move(s)) {}
  std::string text() const override { return "Add step " + step_.name; }
  void redo(Model& model) override { model.steps.push_back(step_); }
  void undo(Model& model) override { model.steps.pop_back(); }

 private:
  Step step_;
};

// Appends entries to one vector of the model (model-level or a step's) and removes them again.
template <typename T>
class AppendEntries : public Command {
 public:
  using Target = std::vector<T>& (*)(Model&, int step);
  AppendEntries(std::string text, int step, std::vector<T> entries, Target target)
      : text_(std::move(text)), step_(step), entries_(std::move(entries)), target_(target) {}
  std::string text() const override { return text_; }
  void redo(Model& model) override {
    std::vector<T>& v = target_(model, step_);
    v.insert(v.end(), entries_.begin(), entries_.end());
  }
  void undo(Model& model) override {
    std::vector<T>& v = target_(model, step_);
    v.resize(v.size() - entries_.size());
  }

 private:
  std::string text_;
  int step_;
  std::vector<T> entries_;
  Target target_;
};

std::vector<Boundary>& boundaries_of(Model& model, int step) {
  return step < 0 ? model.boundaries : model.steps.at(step).boundaries;
}
std::vector<ConcentratedLoad>& cloads_of(Model& model, int step) {
  return model.steps.at(step).cloads;
}
std::vector<DistributedLoad>& dloads_of(Model& model, int step) {
  return model.steps.at(step).dloads;
}

class AddNodeSet : public Command {
 public:
  explicit AddNodeSet(NodeSet s) : set_(std::move(s)) {}
  std::string text() const override { return "Add node set " + set_.name; }
  void redo(Model& model) override { model.nsets[set_.name] = set_; }
  void undo(Model& model) override { model.nsets.erase(set_.name); }

 private:
  NodeSet set_;
};

class ModelEdit : public Command {
 public:
  ModelEdit(std::string text, ModelChange redo, ModelChange undo, bool keeps_results)
      : text_(std::move(text)),
        redo_(std::move(redo)),
        undo_(std::move(undo)),
        keeps_results_(keeps_results) {}
  std::string text() const override { return text_; }
  bool keeps_results() const override { return keeps_results_; }
  void redo(Model& model) override { redo_(model); }
  void undo(Model& model) override { undo_(model); }

 private:
  std::string text_;
  ModelChange redo_, undo_;
  bool keeps_results_;
};

}  // namespace

std::unique_ptr<Command> make_model_edit(std::string text, ModelChange redo, ModelChange undo,
                                         bool keeps_results) {
  return std::make_unique<ModelEdit>(std::move(text), std::move(redo), std::move(undo),
                                     keeps_results);
}
std::unique_ptr<Command> make_replace_model(std::string text, Model before, Model after) {
  return std::make_unique<ReplaceModel>(std::move(text), std::move(before), std::move(after));
}
std::unique_ptr<Command> make_add_material(Material material) {
  return std::make_unique<AddMaterial>(std::move(material));
}
std::unique_ptr<Command> make_add_section(Section section) {
  return std::make_unique<AddSection>(std::move(section));
}
std::unique_ptr<Command> make_add_step(Step step) {
  return std::make_unique<AddStep>(std::move(step));
}
std::unique_ptr<Command> make_add_boundaries(int step, std::vector<Boundary> boundaries,
                                             std::string text) {
  return std::make_unique<AppendEntries<Boundary>>(std::move(text), step, std::move(boundaries),
                                                   &boundaries_of);
}
std::unique_ptr<Command> make_add_cloads(int step, std::vector<ConcentratedLoad> loads,
                                         std::string text) {
  return std::make_unique<AppendEntries<ConcentratedLoad>>(std::move(text), step, std::move(loads),
                                                           &cloads_of);
}
std::unique_ptr<Command> make_add_dloads(int step, std::vector<DistributedLoad> loads,
                                         std::string text) {
  return std::make_unique<AppendEntries<DistributedLoad>>(std::move(text), step, std::move(loads),
                                                          &dloads_of);
}
std::unique_ptr<Command> make_add_node_set(NodeSet set) {
  return std::make_unique<AddNodeSet>(std::move(set));
}

}  // namespace styk::gui
