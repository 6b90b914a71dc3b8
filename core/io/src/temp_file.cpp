#include "styk/io/temp_file.hpp"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <optional>
#include <stdexcept>

#include <hdf5.h>

#include "styk/core/diagnostics.hpp"

namespace styk::io {
namespace {

// The live temporaries' paths, read by the signal handler. Process-wide by nature (a signal
// handler has no other way to reach them); lock-free atomics keep it async-signal-safe. A
// TempFile that finds no free slot (more than kSlots alive at once) is simply not removed on a
// signal, as after SIGKILL.
constexpr int kSlots = 64;
std::atomic<const char*> live_temporaries[kSlots];

int list_temporary(const char* path) {
  for (int k = 0; k < kSlots; ++k) {
    const char* expected = nullptr;
    if (live_temporaries[k].compare_exchange_strong(expected, path)) return k;
  }
  return -1;
}

void unlist_temporary(const char* path) {
  for (auto& slot : live_temporaries) {
    const char* expected = path;
    if (slot.compare_exchange_strong(expected, nullptr)) return;
  }
}

extern "C" void remove_temporaries_and_die(int signal_number) {
  for (auto& slot : live_temporaries) {
    const char* path = slot.load();
    if (path != nullptr) ::unlink(path);
  }
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

// The temporary's data on the disk before the rename makes it the file: otherwise a power loss
// just after the rename could leave an empty or partial file under the final name.
void sync_file(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY);
  if (fd < 0) throw std::runtime_error("cannot open " + path + ": " + std::strerror(errno));
  const int result = ::fsync(fd);
  const int error = errno;
  ::close(fd);
  if (result != 0 && error != EINVAL)  // EINVAL: a file system without fsync (nothing to do)
    throw std::runtime_error("cannot flush " + path + " to the disk: " + std::strerror(error));
}

// The rename itself on the disk (best effort: some file systems cannot sync a directory).
void sync_directory_of(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : path.substr(0, slash + 1);
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

// The cause of a failed write when the machine, not Styk, is out of room: a full file system or
// the file-size limit. Asked of the system, so it holds whatever errno the library left.
std::optional<std::string> out_of_space_cause(const std::string& temp_path, int error) {
  if (error == ENOSPC || error == EDQUOT)
    return std::string("the disk is full (") + std::strerror(error) + ")";
  struct rlimit limit {};
  if (::getrlimit(RLIMIT_FSIZE, &limit) != 0) limit.rlim_cur = RLIM_INFINITY;
  struct stat file {};
  const bool sized = ::stat(temp_path.c_str(), &file) == 0;
  if (error == EFBIG || (limit.rlim_cur != RLIM_INFINITY && sized &&
                         static_cast<rlim_t>(file.st_size) + 65536 >= limit.rlim_cur))
    return std::string("the file has reached the size limit of this process (ulimit -f: ") +
           (limit.rlim_cur == RLIM_INFINITY ? std::string("EFBIG")
                                            : std::to_string(limit.rlim_cur) + " bytes") +
           ")";
  struct statvfs fs {};
  const std::size_t slash = temp_path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : temp_path.substr(0, slash + 1);
  if (::statvfs(dir.c_str(), &fs) == 0 && fs.f_bavail == 0)
    return std::string("the disk is full (0 blocks free)");
  return std::nullopt;
}

}  // namespace

TempFile::TempFile(std::string final_path)
    : final_path_(std::move(final_path)), temp_path_(final_path_ + ".tmp") {
  list_temporary(temp_path_.c_str());
}

TempFile::~TempFile() {
  if (!committed_) std::remove(temp_path_.c_str());
  unlist_temporary(temp_path_.c_str());
}

void TempFile::commit() {
  sync_file(temp_path_);
  if (std::rename(temp_path_.c_str(), final_path_.c_str()) != 0) {
    const int error = errno;
    throw_if_out_of_space("cannot rename " + temp_path_ + " to " + final_path_, error);
    throw std::runtime_error("cannot rename " + temp_path_ + " to " + final_path_ + ": " +
                             std::strerror(error));
  }
  committed_ = true;
  unlist_temporary(temp_path_.c_str());
  sync_directory_of(final_path_);
}

void TempFile::throw_if_out_of_space(const std::string& what, int error) const {
  const std::optional<std::string> cause = out_of_space_cause(temp_path_, error);
  if (cause)
    throw ResourceLimitError(what + ": " + *cause + "; nothing was written and the previous " +
                             final_path_ +
                             ", if any, is unchanged (free space, or write "
                             "elsewhere with -o)");
}

void skip_hdf5_shutdown_at_exit() { H5dont_atexit(); }

void remove_temporaries_on_signals() {
  for (const int signal_number : {SIGINT, SIGTERM, SIGHUP})
    std::signal(signal_number, remove_temporaries_and_die);
  std::signal(SIGXFSZ, SIG_IGN);
}

}  // namespace styk::io
