// Write-then-rename for every file Styk writes (results file, .dat, VTU, decks): output goes to
// "<path>.tmp" and replaces <path> only on commit(), after the data has reached the disk (fsync),
// so a reader never sees a half-written file and a failed, interrupted or killed run leaves the
// previous file untouched. While a TempFile lives, its temporary is listed for the handlers of
// remove_temporaries_on_signals(): SIGINT, SIGTERM or SIGHUP remove it before the process dies.
// SIGKILL cannot be caught: the stale "<path>.tmp" it leaves is replaced by the next run that
// writes <path>.
#pragma once

#include <string>

namespace styk::io {

class TempFile {
 public:
  explicit TempFile(std::string final_path);
  ~TempFile();  // removes the temporary file unless commit() succeeded
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;

  const std::string& temp_path() const { return temp_path_; }
  // Flushes the temporary to the disk and renames it onto the final path. Throws
  // ResourceLimitError when the disk is full (see throw_if_out_of_space), else
  // std::runtime_error on failure.
  void commit();
  // After a failed write to the temporary: throws ResourceLimitError("<what>: <cause>; ...")
  // when the cause is a full disk (ENOSPC, EDQUOT, or no free blocks left on its file system)
  // or the process' file-size limit (EFBIG, or the temporary has reached `ulimit -f`); returns
  // otherwise. `error` is the errno of the failed call (0 when unknown).
  void throw_if_out_of_space(const std::string& what, int error) const;

 private:
  std::string final_path_;
  std::string temp_path_;
  bool committed_ = false;
};

// Installs handlers for SIGINT, SIGTERM and SIGHUP that remove the live temporaries and then let
// the signal end the process as before (the exit status still names the signal), and ignores
// SIGXFSZ, so that a file-size limit fails the write (EFBIG, reported as above) instead of
// killing the process. For programs (styk); the library installs no handler on its own.
void remove_temporaries_on_signals();

// Tells HDF5 not to shut itself down at exit. Its shutdown closes the files left open and
// crashes on one whose close failed (a full disk while writing a results file: the failure is
// reported, then the process would die of SIGSEGV at exit instead of exiting with its code).
// Styk closes every file it writes through RAII, so the shutdown has nothing else to do. For
// programs, first thing in main (before any other HDF5 call).
void skip_hdf5_shutdown_at_exit();

}  // namespace styk::io
