// AugmentedLu in a build without PETSc: the sparse contact solve is not available (the automatic
// choice keeps the dense compliance; asking for it is refused before the analysis starts).
#include <stdexcept>

#include "augmented_lu.hpp"

namespace styk::solver_detail {

struct AugmentedLu::Mumps {};

AugmentedLu::AugmentedLu() = default;
AugmentedLu::~AugmentedLu() = default;

bool AugmentedLu::solve(const AugmentedMatrix&, const std::vector<double>&, std::vector<double>&) {
  throw std::runtime_error("the sparse contact solve needs PETSc with MUMPS");
}

double AugmentedLu::refine(const AugmentedMatrix&, const std::vector<double>&,
                           const std::vector<double>&, const std::vector<double>&,
                           std::vector<double>&) const {
  return 1.0;
}
void AugmentedLu::solve_scaled(std::vector<double>&, std::vector<double>&) const {}

bool augmented_lu_available() { return false; }

}  // namespace styk::solver_detail
