// Scratch directories under the build tree. A test owns its directory alone: ctest runs the cases
// of one executable as separate processes in parallel, so decks written under a shared directory
// with names that only depend on their content's parameters would be overwritten by another case
// mid-read.
#pragma once

#include <filesystem>
#include <string>

namespace styk::test {

// STYK_BINARY_DIR/<relative>, emptied and created.
std::filesystem::path fresh_scratch_dir(const std::filesystem::path& relative);

// STYK_BINARY_DIR/<area>/<suite>.<test> of the running test (parameterised names with '/'
// flattened), created; what an earlier run left there stays.
std::filesystem::path test_scratch_dir(const std::string& area);

}  // namespace styk::test
