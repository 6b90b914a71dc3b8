#include "styk/mesher/merge.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace styk::mesher {
namespace {

std::uint64_t cell_key(std::int64_t i, std::int64_t j, std::int64_t k) {
  // 21 bits per axis (wrapping is harmless: a collision only costs a distance test).
  const std::uint64_t m = (1u << 21) - 1;
  return (static_cast<std::uint64_t>(i) & m) | ((static_cast<std::uint64_t>(j) & m) << 21) |
         ((static_cast<std::uint64_t>(k) & m) << 42);
}

}  // namespace

int merge_coincident_nodes(Mesh& mesh, double relative_tolerance) {
  const std::size_t n = mesh.nodes.size();
  if (n == 0) return 0;
  const double tol = relative_tolerance * mesh.size();
  if (!(tol > 0.0)) return 0;
  const double tol2 = tol * tol;
  const double inv = 1.0 / (2.0 * tol);  // cells of size 2 tol: a partner is in a neighbour cell

  std::unordered_map<std::uint64_t, int> head;  // cell -> last representative placed there
  head.reserve(n);
  std::vector<int> next(n, -1);  // chain of representatives in the same cell
  std::vector<int> old_to_new(n, -1);
  std::vector<int> representative_new(n, -1);
  int count = 0;
  for (std::size_t p = 0; p < n; ++p) {
    const Vec3& x = mesh.nodes[p];
    const std::int64_t c[3] = {static_cast<std::int64_t>(std::floor(x[0] * inv)),
                               static_cast<std::int64_t>(std::floor(x[1] * inv)),
                               static_cast<std::int64_t>(std::floor(x[2] * inv))};
    int found = -1;
    for (int di = -1; di <= 1 && found < 0; ++di)
      for (int dj = -1; dj <= 1 && found < 0; ++dj)
        for (int dk = -1; dk <= 1 && found < 0; ++dk) {
          const auto it = head.find(cell_key(c[0] + di, c[1] + dj, c[2] + dk));
          if (it == head.end()) continue;
          for (int q = it->second; q >= 0; q = next[q]) {
            const Vec3& y = mesh.nodes[q];
            const double d2 = (x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
                              (x[2] - y[2]) * (x[2] - y[2]);
            if (d2 <= tol2) {
              found = q;
              break;
            }
          }
        }
    if (found >= 0) {
      old_to_new[p] = old_to_new[found];
    } else {
      old_to_new[p] = count++;
      int& h = head.try_emplace(cell_key(c[0], c[1], c[2]), -1).first->second;
      next[p] = h;
      h = static_cast<int>(p);
    }
  }
  const int removed = static_cast<int>(n) - count;
  if (removed == 0) return 0;
  // Coordinates: keep the first node of each group (renumber_nodes moves by old_to_new, and a
  // later duplicate would overwrite the first), so write them here.
  std::vector<Vec3> kept(count);
  for (std::size_t p = n; p-- > 0;) kept[old_to_new[p]] = mesh.nodes[p];
  std::vector<int> identity(n);
  for (std::size_t p = 0; p < n; ++p) identity[p] = old_to_new[p];
  mesh.renumber_nodes(identity, count);
  mesh.nodes = std::move(kept);
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    std::vector<int> sorted = mesh.elements[e].nodes;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      throw std::invalid_argument("merge_coincident_nodes: element " + std::to_string(e + 1) +
                                  " would have two coincident nodes (tolerance too large?)");
  }
  return removed;
}

}  // namespace styk::mesher
