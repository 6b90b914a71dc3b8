// How SolveOptions::contact_solve = Automatic picks the contact iteration's linear algebra
// (docs/contact.md, "Sparse contact solve"): from counts only, never timings, so a model always
// takes the same path and gives the same answer bit for bit.
#pragma once

namespace styk::solver_detail {

struct ContactSolveSize {
  double constraints = 0.0;         // m: the dense compliance holds 3 m x 3 m doubles
  double used_rows = 0.0;           // rows that can carry force: the largest dense Newton system
  double factor_nonzeros = 0.0;     // of the Cholesky factor of K (its symbolic analysis)
  double memory_limit_bytes = 0.0;  // SolveOptions::memory_limit_gb, or 80 % of the memory
};

// True when the sparse contact solve should be used: the dense compliance would take more than
// a quarter of the memory limit, or a Newton step's sparse LU of K with the contact rows is
// expected to cost less than the dense LU over every used row.
bool sparse_contact_pays(const ContactSolveSize& size);

}  // namespace styk::solver_detail
