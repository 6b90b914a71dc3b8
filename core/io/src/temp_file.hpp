// Write-then-rename: output goes to "<path>.tmp" and replaces <path> only on commit(), so readers
// never see a half-written file and a failure leaves the previous file untouched.
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
  // Renames the temporary file onto the final path. Throws std::runtime_error on failure.
  void commit();

 private:
  std::string final_path_;
  std::string temp_path_;
  bool committed_ = false;
};

}  // namespace styk::io
