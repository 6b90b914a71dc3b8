// A text output of the command line (the .dat report, decks) written through io::TempFile, so a
// failed, interrupted or killed run never leaves a half-written file behind.
#pragma once

#include <fstream>
#include <string>

#include "styk/io/temp_file.hpp"

namespace styk::cli {

class AtomicTextFile {
 public:
  explicit AtomicTextFile(std::string path);
  AtomicTextFile(const AtomicTextFile&) = delete;
  AtomicTextFile& operator=(const AtomicTextFile&) = delete;

  std::ostream& stream() { return out_; }
  // Flushes, closes and renames the temporary onto the final path; throws ResourceLimitError on
  // a full disk, std::runtime_error on any other failure.
  void commit();

 private:
  std::string path_;
  io::TempFile temp_;  // removes the temporary unless committed
  std::ofstream out_;
};

}  // namespace styk::cli
