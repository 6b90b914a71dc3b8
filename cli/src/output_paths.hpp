// Where a job's outputs go: <dir>/<job>.styk.h5 and <dir>/<job>.dat, job = deck name without .inp.
#pragma once

#include <string>

namespace styk::cli {

std::string job_name(const std::string& deck_path);
std::string join_path(const std::string& dir, const std::string& file);

}  // namespace styk::cli
