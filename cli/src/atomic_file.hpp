// Write-to-temporary-then-rename, so a failed run never leaves a half-written output behind.
#pragma once

#include <fstream>
#include <string>

namespace styk::cli {

class AtomicTextFile {
 public:
  explicit AtomicTextFile(std::string path);
  ~AtomicTextFile();  // removes the temporary unless commit() succeeded
  AtomicTextFile(const AtomicTextFile&) = delete;
  AtomicTextFile& operator=(const AtomicTextFile&) = delete;

  std::ostream& stream() { return out_; }
  // Flushes, closes and renames the temporary onto the final path; throws on failure.
  void commit();

 private:
  std::string path_;
  std::string tmp_path_;
  std::ofstream out_;
  bool committed_ = false;
};

}  // namespace styk::cli
