#include "styk/mesher/mesh_size_limit.hpp"

#include <cstdio>
#include <limits>

#include "styk/core/diagnostics.hpp"
#include "styk/core/machine_memory.hpp"

namespace styk::mesher {

namespace {

constexpr std::uint64_t kLargestCount = std::numeric_limits<std::int32_t>::max();
constexpr double kBytesPerNode = 100.0;
constexpr double kBytesPerElement = 64.0;
constexpr double kBytesPerElementNode = 4.0;

std::string gigabytes(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f GB", bytes / 1e9);
  return text;
}

}  // namespace

void check_mesh_fits(std::uint64_t nodes, std::uint64_t elements, int nodes_per_element,
                     const std::string& what) {
  if (nodes > kLargestCount || elements > kLargestCount)
    throw ResourceLimitError(what + " has " + std::to_string(nodes) + " grid points and " +
                             std::to_string(elements) + " elements; a Styk model holds at most " +
                             std::to_string(kLargestCount) +
                             " of each (32-bit ids and indices): use fewer divisions");
  const double needed =
      kBytesPerNode * static_cast<double>(nodes) +
      (kBytesPerElement + kBytesPerElementNode * nodes_per_element) * static_cast<double>(elements);
  const double available = physical_memory_bytes();
  if (available > 0.0 && needed > available)
    throw ResourceLimitError(what + " has " + std::to_string(nodes) + " grid points and " +
                             std::to_string(elements) + " elements, which need about " +
                             gigabytes(needed) + " to build, more than this machine's " +
                             gigabytes(available) + " of memory: use fewer divisions");
}

void check_block_fits(const std::array<int, 3>& divisions, int step, const std::string& type) {
  std::uint64_t grid_points = 1, elements = 1;
  for (const int d : divisions) {
    grid_points *= static_cast<std::uint64_t>(step) * static_cast<std::uint64_t>(d) + 1;
    elements *= static_cast<std::uint64_t>(d);
  }
  const std::string what = "the " + std::to_string(divisions[0]) + " x " +
                           std::to_string(divisions[1]) + " x " + std::to_string(divisions[2]) +
                           " " + type + " block";
  check_mesh_fits(grid_points, elements, step == 1 ? 8 : 20, what);
}

}  // namespace styk::mesher
