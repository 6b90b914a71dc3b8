#include "output_paths.hpp"

#include <filesystem>

namespace styk::cli {

std::string job_name(const std::string& deck_path) {
  std::filesystem::path p(deck_path);
  std::string ext = p.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".inp" ? p.stem().string() : p.filename().string();
}

std::string join_path(const std::string& dir, const std::string& file) {
  return (std::filesystem::path(dir) / file).string();
}

}  // namespace styk::cli
