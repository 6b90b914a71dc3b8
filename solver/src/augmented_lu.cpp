#include "augmented_lu.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "styk/core/diagnostics.hpp"

namespace styk::solver_detail {

void AugmentedMatrix::end_row() {
  if (col.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw ResourceLimitError(
        "sparse contact solve: the stiffness with the contact rows has more than 2147483647 "
        "nonzeros (32-bit sparse indices)");
  ptr.push_back(static_cast<int>(col.size()));
}

double backward_error(const AugmentedMatrix& A, const std::vector<double>& x,
                      const std::vector<double>& b, std::vector<double>* residual) {
  double worst = 0.0;
  for (int i = 0; i < A.size(); ++i) {
    double sum = -b[i], scale = std::abs(b[i]);
    for (int p = A.ptr[i]; p < A.ptr[i + 1]; ++p) {
      sum += A.value[p] * x[A.col[p]];
      scale += std::abs(A.value[p] * x[A.col[p]]);
    }
    if (residual) (*residual)[i] = -sum;
    if (!std::isfinite(sum)) return 1.0;
    if (scale > 0.0) worst = std::max(worst, std::abs(sum) / scale);
  }
  return worst;
}

}  // namespace styk::solver_detail
