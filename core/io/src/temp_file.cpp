#include "temp_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace styk::io {

TempFile::TempFile(std::string final_path)
    : final_path_(std::move(final_path)), temp_path_(final_path_ + ".tmp") {}

TempFile::~TempFile() {
  if (!committed_) std::remove(temp_path_.c_str());
}

void TempFile::commit() {
  if (std::rename(temp_path_.c_str(), final_path_.c_str()) != 0)
    throw std::runtime_error("cannot rename " + temp_path_ + " to " + final_path_ + ": " +
                             std::strerror(errno));
  committed_ = true;
}

}  // namespace styk::io
