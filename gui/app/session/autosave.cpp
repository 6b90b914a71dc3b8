#include "session/autosave.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace styk::gui {
namespace {

namespace fs = std::filesystem;

// The autosave's first line, "** styk-gui autosave of: PATH", names the file it came from.
constexpr const char* kOriginComment = "styk-gui autosave of: ";

// Takes the exclusive lock of `path` without waiting; -1 when another session holds it.
int try_lock(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0600);
  if (fd < 0) return -1;
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd);
    return -1;
  }
  return fd;
}

// The file an autosaved deck came from: its first line "** styk-gui autosave of: PATH".
std::string original_path_of(const std::string& deck) {
  std::ifstream in(deck);
  std::string line;
  std::getline(in, line);
  const std::string marker = std::string("** ") + kOriginComment;
  return line.rfind(marker, 0) == 0 ? line.substr(marker.size()) : std::string();
}

long long seconds_since_epoch(const fs::path& file) {
  std::error_code ec;
  const auto written = fs::last_write_time(file, ec);
  if (ec) return 0;
  const auto system = std::chrono::time_point_cast<std::chrono::seconds>(
      written - fs::file_time_type::clock::now() + std::chrono::system_clock::now());
  return system.time_since_epoch().count();
}

}  // namespace

std::string default_autosave_directory() {
  if (const char* dir = std::getenv("STYK_GUI_AUTOSAVE_DIR"); dir && *dir) return dir;
  if (const char* state = std::getenv("XDG_STATE_HOME"); state && *state)
    return std::string(state) + "/styk/autosave";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::string(home) + "/.local/state/styk/autosave";
  return (fs::temp_directory_path() / "styk-autosave").string();
}

Autosave::Autosave(std::string directory) : directory_(std::move(directory)) {
  std::error_code ec;
  fs::create_directories(directory_, ec);
  if (ec)
    throw std::runtime_error("cannot create the autosave directory " + directory_ + ": " +
                             ec.message());
  // session-<pid>-<n>: the first name that no live session locks and no interrupted session's
  // autosave uses (process ids are reused; several windows may share a process).
  for (int n = 0; n < 1000 && lock_fd_ < 0; ++n) {
    const std::string stem =
        directory_ + "/session-" + std::to_string(::getpid()) + "-" + std::to_string(n);
    if (fs::exists(stem + ".inp")) continue;
    lock_fd_ = try_lock(stem + ".lock");
    deck_ = stem + ".inp";
    lock_path_ = stem + ".lock";
  }
  if (lock_fd_ < 0) throw std::runtime_error("cannot lock a session file in " + directory_);
}

bool Autosave::update(const Document& document) {
  if (!document.is_modified()) {
    std::remove(deck_.c_str());
    written_revision_ = -1;
    return false;
  }
  if (document.revision() == written_revision_) return false;
  document.write_deck_copy(deck_, std::string(kOriginComment) + document.path());
  written_revision_ = document.revision();
  return true;
}

void Autosave::discard() {
  std::remove(deck_.c_str());
  written_revision_ = -1;
}

Autosave::~Autosave() {
  if (lock_fd_ < 0) return;
  // A session that wrote nothing leaves no lock file behind; one with an autosave keeps both
  // (the lock file marks it, free now, as interrupted).
  if (!fs::exists(deck_)) std::remove(lock_path_.c_str());
  ::close(lock_fd_);  // closing the file drops the flock
}

std::vector<InterruptedSession> Autosave::interrupted_sessions() const {
  std::vector<InterruptedSession> out;
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(directory_, ec)) {
    const fs::path deck = entry.path();
    if (deck.extension() != ".inp" || deck.string() == deck_) continue;
    if (deck.filename().string().rfind("session-", 0) != 0) continue;
    fs::path lock = deck;
    lock.replace_extension(".lock");
    const int fd = try_lock(lock.string());
    if (fd < 0) continue;  // its session is still running
    ::close(fd);
    out.push_back({deck.string(), original_path_of(deck.string()), seconds_since_epoch(deck)});
  }
  std::sort(out.begin(), out.end(), [](const InterruptedSession& a, const InterruptedSession& b) {
    return a.saved_at > b.saved_at;
  });
  return out;
}

void Autosave::forget(const InterruptedSession& session) const {
  fs::path lock = session.deck;
  lock.replace_extension(".lock");
  std::remove(session.deck.c_str());
  std::remove(lock.c_str());
}

}  // namespace styk::gui
