#include "session/document.hpp"

#include <cerrno>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "session/view_state.hpp"
#include "styk/inp/reader.hpp"
#include "styk/inp/writer.hpp"
#include "styk/io/results_file.hpp"
#include "styk/io/temp_file.hpp"

namespace styk::gui {

Document::Document(const ElementRegistry& registry) : registry_(registry) { new_model(); }

void Document::new_model() {
  model_ = Model{};
  results_.reset();
  results_path_.clear();
  path_.clear();
  history_.clear();
  layers_ = LayerTable{};  // a new model: the user layers of the old one go
  filter_ = ElementDisplayFilter{};
  open_warnings_.clear();
  results_notice_.clear();
  changed(false);
}

void Document::open_inp(const std::string& path) {
  Model model = read_inp(path, registry_);
  const ReadViewState view = read_view_state(path);
  model_ = std::move(model);
  results_.reset();
  results_path_.clear();
  path_ = path;
  history_.clear();
  layers_ = LayerTable{};  // a new model: the user layers of the old one go
  open_warnings_ = view.warnings;
  results_notice_.clear();
  filter_ = apply_view_state(view.state, path, model_, layers_, open_warnings_);
  changed(false);
}

void Document::open_results(const std::string& path) {
  ResultsFileContents contents = read_results_file(path);
  model_ = std::move(contents.model);
  results_ = std::move(contents.results);
  results_path_ = path;
  path_ = path;
  history_.clear();
  layers_ = LayerTable{};  // a new model: the user layers of the old one go
  filter_ = ElementDisplayFilter{};
  open_warnings_.clear();
  results_notice_ = contents.verified ? std::string() : unverified_notice(path);
  changed(true);
}

void Document::open_msh(const std::string& path, const GmshImportOptions& options) {
  Model model = import_gmsh(path, options);
  model_ = std::move(model);
  results_.reset();
  results_path_.clear();
  path_ = path;
  history_.clear();
  layers_ = LayerTable{};  // a new model: the user layers of the old one go
  filter_ = ElementDisplayFilter{};
  open_warnings_.clear();
  results_notice_.clear();
  changed(false);
}

void Document::save_inp(const std::string& path) {
  write_deck_copy(path);
  path_ = path;
  history_.set_clean();
}

void Document::recover_inp(const std::string& deck, const std::string& original_path) {
  Model model = read_inp(deck, registry_, DeckCompleteness::Draft);
  const ReadViewState view = read_view_state(deck);
  model_ = std::move(model);
  model_.source = original_path;
  results_.reset();
  results_path_.clear();
  path_ = original_path;
  history_.clear();
  history_.set_unsaved();
  layers_ = LayerTable{};
  open_warnings_ = view.warnings;
  results_notice_.clear();
  filter_ = apply_view_state(view.state, deck, model_, layers_, open_warnings_);
  changed(false);
}

void Document::write_deck_copy(const std::string& path, const std::string& comment) const {
  io::TempFile temporary(path);  // the same write-then-rename as every file styk writes
  {
    std::ofstream out(temporary.temp_path());
    if (!out) throw std::runtime_error("cannot write " + temporary.temp_path());
    if (!comment.empty()) out << "** " << comment << "\n";
    write_inp(model_, out);
    write_view_state(view_state_of(layers_, filter_), out);
    out.flush();
    if (!out) {
      temporary.throw_if_out_of_space("cannot write " + path, errno);
      throw std::runtime_error("error while writing " + temporary.temp_path());
    }
  }
  temporary.commit();
}

void Document::attach_results(Results results, std::string results_path) {
  for (const IncrementResult& inc : results.increments) {
    // A scalar-field increment (steady heat, electric potential) holds no displacements.
    const bool scalar = inc.scalar.kind != ScalarFieldResult::Kind::None;
    const std::size_t held = scalar && inc.U.empty() ? inc.scalar.value.size() : inc.U.size();
    if (held != model_.coords.size())
      throw std::runtime_error("the results hold " + std::to_string(held) + " nodes, the model " +
                               std::to_string(model_.coords.size()));
  }
  results_ = std::move(results);
  results_path_ = std::move(results_path);
  changed(true);
}

void Document::apply(std::unique_ptr<Command> command) {
  const bool keep_results = command->keeps_results();
  history_.push(model_, std::move(command));
  changed(keep_results);
}

void Document::undo() {
  if (!history_.can_undo()) return;
  const bool keep_results = history_.undo_keeps_results();
  history_.undo(model_);
  changed(keep_results);
}

void Document::redo() {
  if (!history_.can_redo()) return;
  const bool keep_results = history_.redo_keeps_results();
  history_.redo(model_);
  changed(keep_results);
}

void Document::changed(bool keep_results) {
  if (!keep_results) {
    results_.reset();
    results_path_.clear();
  }
  layers_.rebuild(model_);
  ++revision_;
}

}  // namespace styk::gui
