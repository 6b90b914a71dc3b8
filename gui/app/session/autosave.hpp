// Autosave and crash recovery of the model being edited (docs/gui.md "Autosave and recovery").
// Each running session owns DIR/session-<pid>-<n>.inp (the deck, written by
// Document::write_deck_copy, atomically) and DIR/session-<pid>-<n>.lock, which it holds with an
// exclusive flock(2) for as long as it lives; the first line of the deck names the file it was
// autosaved from. The operating system drops the lock when the process ends however it ends
// (a crash, SIGKILL), so a later session finds an autosave whose lock it can take: that session
// was interrupted, and its model can be recovered. A session ending normally (saved, or the
// changes discarded) removes its files with discard().
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "session/document.hpp"

namespace styk::gui {

// An autosave left by an interrupted session.
struct InterruptedSession {
  std::string deck;           // the autosaved deck
  std::string original_path;  // the file the model came from ("" for a new model)
  long long saved_at = 0;     // seconds since the epoch of the last autosave
};

class Autosave {
 public:
  // `directory` is created when missing; throws std::runtime_error when it cannot be, or when
  // the session's lock cannot be taken.
  explicit Autosave(std::string directory);
  // Releases the lock and keeps an autosave written since the last discard(): what a crash
  // leaves (the next session offers it).
  ~Autosave();
  Autosave(const Autosave&) = delete;
  Autosave& operator=(const Autosave&) = delete;

  // Writes the document's deck when it has unsaved changes and its revision differs from the
  // last one written; a document without unsaved changes removes the autosave instead.
  // Returns whether a deck was written.
  bool update(const Document& document);
  // The session ends normally, or its model was saved: no autosave remains.
  void discard();

  // The autosaves of sessions that were interrupted (their lock is free), newest first.
  std::vector<InterruptedSession> interrupted_sessions() const;
  // Removes an interrupted session's files once it is recovered or declined.
  void forget(const InterruptedSession& session) const;

  const std::string& deck_path() const { return deck_; }
  const std::string& directory() const { return directory_; }

 private:
  std::string directory_;
  std::string deck_;
  std::string lock_path_;
  int lock_fd_ = -1;
  long written_revision_ = -1;
};

// The autosave directory: $STYK_GUI_AUTOSAVE_DIR, else $XDG_STATE_HOME/styk/autosave, else
// $HOME/.local/state/styk/autosave (a temporary directory when HOME is unset).
std::string default_autosave_directory();

}  // namespace styk::gui
