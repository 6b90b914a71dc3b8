#include "atomic_file.hpp"

#include <cstdio>
#include <stdexcept>

namespace styk::cli {

AtomicTextFile::AtomicTextFile(std::string path)
    : path_(std::move(path)), tmp_path_(path_ + ".tmp") {
  out_.open(tmp_path_, std::ios::out | std::ios::trunc);
  if (!out_) throw std::runtime_error("cannot write " + tmp_path_);
}

AtomicTextFile::~AtomicTextFile() {
  if (!committed_) {
    out_.close();
    std::remove(tmp_path_.c_str());
  }
}

void AtomicTextFile::commit() {
  out_.flush();
  const bool ok = static_cast<bool>(out_);
  out_.close();
  if (!ok || std::rename(tmp_path_.c_str(), path_.c_str()) != 0)
    throw std::runtime_error("cannot write " + path_);
  committed_ = true;
}

}  // namespace styk::cli
