#include "atomic_file.hpp"

#include <cerrno>
#include <stdexcept>

namespace styk::cli {

AtomicTextFile::AtomicTextFile(std::string path) : path_(std::move(path)), temp_(path_) {
  out_.open(temp_.temp_path(), std::ios::out | std::ios::trunc);
  if (!out_) throw std::runtime_error("cannot write " + temp_.temp_path());
}

void AtomicTextFile::commit() {
  out_.flush();
  out_.close();
  if (!out_) {
    temp_.throw_if_out_of_space("cannot write " + path_, errno);
    throw std::runtime_error("cannot write " + path_);
  }
  temp_.commit();
}

}  // namespace styk::cli
