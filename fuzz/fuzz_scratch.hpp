// The harnesses' scratch directory: readers take paths, so each input is written to a file first.
// One directory per fuzzing process (libFuzzer's -fork/-jobs workers each get their own),
// created on first use and left for the system's /tmp cleaning.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace styk::fuzz {

// The path of `name` in this process' scratch directory.
std::string scratch_path(const std::string& name);

// Writes `size` bytes to `path` (truncating it).
void write_bytes(const std::string& path, const std::uint8_t* data, std::size_t size);

}  // namespace styk::fuzz
