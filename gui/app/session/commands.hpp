// Edit commands with undo/redo for every change the GUI makes to a Model (issue "Desktop
// pre/postprocessor", priority 2). A command knows how to apply and revert itself; UndoStack
// keeps the history. Small edits (materials, sections, loads, steps) store only what they change;
// mesh edits store the model before and after, because Model's id maps cannot shrink.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "styk/core/model.hpp"

namespace styk::gui {

class Command {
 public:
  virtual ~Command() = default;
  virtual std::string text() const = 0;  // "Add material STEEL", for the Edit menu
  virtual void redo(Model& model) = 0;
  virtual void undo(Model& model) = 0;
  // Whether results of the model stay valid across this edit (defining a set changes neither the
  // mesh nor the analysis); most edits make them stale.
  virtual bool keeps_results() const { return false; }
};

class UndoStack {
 public:
  // Applies the command and records it; drops whatever had been undone.
  void push(Model& model, std::unique_ptr<Command> command);
  bool can_undo() const { return index_ > 0; }
  bool can_redo() const { return index_ < commands_.size(); }
  void undo(Model& model);
  void redo(Model& model);
  std::string undo_text() const;  // empty when nothing to undo
  std::string redo_text() const;
  // keeps_results() of the command undo() / redo() would apply next (false when there is none).
  bool undo_keeps_results() const { return can_undo() && commands_[index_ - 1]->keeps_results(); }
  bool redo_keeps_results() const { return can_redo() && commands_[index_]->keeps_results(); }
  void clear();
  void set_clean() { clean_ = index_; }
  // No state of the stack is the saved one (a model recovered from an autosave).
  void set_unsaved() { clean_ = static_cast<std::size_t>(-1); }
  bool is_clean() const { return clean_ == index_; }
  std::size_t size() const { return commands_.size(); }

 private:
  std::vector<std::unique_ptr<Command>> commands_;
  std::size_t index_ = 0;  // commands_[0 .. index_) are applied
  std::size_t clean_ = 0;  // index_ at the last save; npos when that state is gone
};

// The model before and after (mesh edits, builders, block meshing).
std::unique_ptr<Command> make_replace_model(std::string text, Model before, Model after);

std::unique_ptr<Command> make_add_material(Material material);
// Adds the section and assigns it to every element of its set (which must exist and hold no
// element with a section already: validate first, see validation.hpp).
std::unique_ptr<Command> make_add_section(Section section);
std::unique_ptr<Command> make_add_step(Step step);
// step < 0: model-level boundary conditions (held in every step); otherwise into steps[step].
std::unique_ptr<Command> make_add_boundaries(int step, std::vector<Boundary> boundaries,
                                             std::string text);
std::unique_ptr<Command> make_add_cloads(int step, std::vector<ConcentratedLoad> loads,
                                         std::string text);
std::unique_ptr<Command> make_add_dloads(int step, std::vector<DistributedLoad> loads,
                                         std::string text);
std::unique_ptr<Command> make_add_node_set(NodeSet set);

// Any other small edit: `redo` applies it, `undo` reverts it exactly (each captures the values it
// needs, e.g. the entry it removes and where it was). `keeps_results`: see Command (set edits).
using ModelChange = std::function<void(Model&)>;
std::unique_ptr<Command> make_model_edit(std::string text, ModelChange redo, ModelChange undo,
                                         bool keeps_results = false);

}  // namespace styk::gui
