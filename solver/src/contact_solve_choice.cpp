#include "contact_solve_choice.hpp"

namespace styk::solver_detail {
namespace {

// A Newton step's time, measured side by side (bench/contact/README.md, "Thousands of closed
// contact nodes"): a sparse Newton step took 0.6-0.8 us per entry of K's Cholesky factor on the
// flat joints of write_plate_stack.py (5.4-59 M entries) and 0.27 us on SPEC 4.2 model A (27 M),
// the dense LU (2/3) r^3 flops at ~5e10 flop/s on the two cores. At 0.5 us bulky models stay on
// the dense path by a wide margin (model B, 7200 rows and 212 M entries: by 20x) and the 2601-node
// joint, even in the measurement (27.0 s sparse, 28.7 s dense), goes sparse for its memory.
constexpr double kSparseSecondsPerFactorEntry = 0.5e-6;
constexpr double kDenseFlopsPerSecond = 5e10;
constexpr double kDenseMemoryShare = 0.25;

}  // namespace

bool sparse_contact_pays(const ContactSolveSize& size) {
  const double dense_bytes = 8.0 * 9.0 * size.constraints * size.constraints;
  if (size.memory_limit_bytes > 0.0 && dense_bytes > kDenseMemoryShare * size.memory_limit_bytes)
    return true;
  if (!(size.factor_nonzeros > 0.0)) return false;
  const double r = size.used_rows;
  const double dense_seconds = 2.0 / 3.0 * r * r * r / kDenseFlopsPerSecond;
  return kSparseSecondsPerFactorEntry * size.factor_nonzeros < dense_seconds;
}

}  // namespace styk::solver_detail
