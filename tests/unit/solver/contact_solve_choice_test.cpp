// The automatic choice between the dense and the sparse contact solve (docs/contact.md, "Sparse
// contact solve"; solver/src/contact_solve_choice.hpp) on the sizes measured side by side in
// bench/contact/README.md ("Thousands of closed contact nodes"): each case expects the path that
// was faster there.
#include <gtest/gtest.h>

#include "contact_solve_choice.hpp"

namespace styk::solver_detail {
namespace {

constexpr double kLimit = 0.8 * 24e9;  // 80 % of a 24 GB machine

ContactSolveSize size(double constraints, double used_rows, double factor_nonzeros) {
  return {constraints, used_rows, factor_nonzeros, kLimit};
}

// SPEC 4.2 models: bulky C3D20 structures with a few thousand contact rows stay dense (model B:
// 180 s dense; one sparse LU of its K would take longer than a dense Newton step by ~20x).
TEST(ContactSolveChoice, BulkyJointsKeepTheDenseCompliance) {
  EXPECT_FALSE(sparse_contact_pays(size(625, 1875, 27.0e6)));    // model A, nnz(L) 27.0 M
  EXPECT_FALSE(sparse_contact_pays(size(2400, 7200, 212.0e6)));  // model B, 212 M
}

// The flat joint of write_plate_stack.py: 2601 nodes 27.0 s sparse against 28.7 s dense (0.63
// against 2.20 GB), 5041 nodes 55.0 s against 184.8 s (1.20 against 7.61 GB).
TEST(ContactSolveChoice, ThinJointsWithManyContactNodesGoSparse) {
  EXPECT_TRUE(sparse_contact_pays(size(2601, 7803, 5.4e6)));
  EXPECT_TRUE(sparse_contact_pays(size(5041, 15123, 11.8e6)));
}

// 20 164 frictional constraints: S alone would be 29.3 GB; sparse whatever K's factor costs.
TEST(ContactSolveChoice, ACompliancePastAQuarterOfTheMemoryGoesSparse) {
  EXPECT_TRUE(sparse_contact_pays(size(20164, 60492, 1e12)));
  ContactSolveSize small = size(625, 1875, 27.0e6);
  small.memory_limit_bytes = 4.0 * 8.0 * 9.0 * 625.0 * 625.0 * 0.99;  // S just past a quarter
  EXPECT_TRUE(sparse_contact_pays(small));
}

// Without a factor size (a backend that does not report one) only the memory rule applies.
TEST(ContactSolveChoice, UnknownFactorSizeKeepsTheDensePathWhileItFits) {
  EXPECT_FALSE(sparse_contact_pays(size(5041, 15123, 0.0)));
}

}  // namespace
}  // namespace styk::solver_detail
