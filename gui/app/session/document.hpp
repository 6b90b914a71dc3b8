// The session's document: the Model being edited, optionally the results of one analysis of it,
// the layers, the view's element filter, and the edit history. No Qt here, so it is tested without
// a display; the main window owns one Document and redraws when revision() changes.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "session/commands.hpp"
#include "session/element_filter.hpp"
#include "session/layers.hpp"
#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"
#include "styk/core/results.hpp"
#include "styk/gmsh/gmsh_import.hpp"

namespace styk::gui {

class Document {
 public:
  // The registry must outlive the document (element types for reading decks and drawing).
  explicit Document(const ElementRegistry& registry);

  void new_model();
  // Throws InputError ("file:line: message") and leaves the document unchanged on failure. The
  // layers and the filter saved with the deck come back (view_state.hpp); view lines the model
  // cannot take are dropped and listed in open_warnings().
  void open_inp(const std::string& path);
  // A .styk.h5 file: its mesh becomes the model (no materials or steps) and its results attach.
  // Every checksum is verified and NaN/Inf refused: throws InputError ("file: dataset ...:
  // checksum mismatch — the file is damaged") or std::runtime_error on failure, document
  // unchanged. A file written before checksums opens with results_notice() set.
  void open_results(const std::string& path);
  // A Gmsh mesh (.msh, as `styk import` reads it: styk/gmsh/gmsh_import.hpp): its elements and
  // nodes become the model, its physical groups sets; no materials or steps yet, and Save asks
  // for a deck name. `options` says what a surface or line mesh's elements are. Throws
  // InputError ("file:line: message") and leaves the document unchanged on failure.
  void open_msh(const std::string& path, const GmshImportOptions& options);
  // Writes the model as a deck (atomically: a temporary file renamed over `path`), followed by the
  // layers and the filter as comment lines (view_state.hpp).
  void save_inp(const std::string& path);
  // Writes the same deck to `path` (atomically) without making it the document's file or
  // marking the model saved: the autosave (session/autosave.hpp). A non-empty `comment` goes
  // first, as a comment line ("** " + comment).
  void write_deck_copy(const std::string& path, const std::string& comment = {}) const;
  // Opens a deck written by write_deck_copy() as a draft (it may lack a step: the model was
  // being built) and keeps it unsaved, its file `original_path` (empty: a new model). Throws
  // InputError as open_inp() does, the document unchanged.
  void recover_inp(const std::string& deck, const std::string& original_path);
  // Attaches the results of an analysis of the current model (from a solve); throws
  // std::runtime_error when their node count does not match the model.
  void attach_results(Results results, std::string results_path);

  // Every edit goes through here (undoable). Stale results are dropped: they belong to the
  // model before the edit (unless the command keeps_results(), e.g. a new set).
  void apply(std::unique_ptr<Command> command);
  void undo();
  void redo();
  const UndoStack& history() const { return history_; }

  const Model& model() const { return model_; }
  const Results* results() const { return results_ ? &*results_ : nullptr; }
  const std::string& results_path() const { return results_path_; }
  const ElementRegistry& registry() const { return registry_; }
  LayerTable& layers() { return layers_; }
  const LayerTable& layers() const { return layers_; }
  // The view's element filter (a display setting: changing it is no model edit and not undone).
  const ElementDisplayFilter& filter() const { return filter_; }
  void set_filter(ElementDisplayFilter filter) { filter_ = std::move(filter); }
  // "file:line: message" for each view line of the last opened deck that was dropped.
  const std::vector<std::string>& open_warnings() const { return open_warnings_; }
  // Non-empty after open_results() of a file that cannot be verified (written before results
  // files carried checksums): the notice to show; cleared by any other open.
  const std::string& results_notice() const { return results_notice_; }
  const std::string& path() const { return path_; }  // the deck (or results file) opened/saved
  bool is_modified() const { return !history_.is_clean(); }
  // Increases with every change of the model or the results.
  long revision() const { return revision_; }

 private:
  void changed(bool keep_results);

  const ElementRegistry& registry_;
  Model model_;
  std::optional<Results> results_;
  std::string results_path_;
  LayerTable layers_;
  ElementDisplayFilter filter_;
  std::vector<std::string> open_warnings_;
  std::string results_notice_;
  UndoStack history_;
  std::string path_;
  long revision_ = 0;
};

}  // namespace styk::gui
