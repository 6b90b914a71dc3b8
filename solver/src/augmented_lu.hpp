// The sparse LU behind the sparse contact solve (sparse_contact_structure.hpp): the augmented
// matrix of one Newton step (K with the contact rows; unsymmetric where nodes slip, zero
// diagonals on the constraint rows) equilibrated, factorised by MUMPS through PETSc and refined.
#pragma once

#include <memory>
#include <vector>

namespace styk::solver_detail {

// CSR, columns sorted in each row, 32-bit indices as PETSc's AIJ matrices take them.
struct AugmentedMatrix {
  std::vector<int> ptr{0}, col;
  std::vector<double> value;
  int size() const { return static_cast<int>(ptr.size()) - 1; }
  void add(long c, double v) {
    col.push_back(static_cast<int>(c));
    value.push_back(v);
  }
  void end_row();  // throws ResourceLimitError past 2^31 - 1 entries
};

// max_i |A x - b|_i / (|A| |x| + |b|)_i: the componentwise backward error of x (Oettli-Prager),
// row by row, so the contact rows are judged at their own scale, not at K's. `residual` (when
// given, of A's size) receives b - A x from the same pass.
double backward_error(const AugmentedMatrix& A, const std::vector<double>& x,
                      const std::vector<double>& b, std::vector<double>* residual = nullptr);

class AugmentedLu {
 public:
  AugmentedLu();
  ~AugmentedLu();
  AugmentedLu(const AugmentedLu&) = delete;
  AugmentedLu& operator=(const AugmentedLu&) = delete;

  // Analyses and factorises A and solves A x = b. False when A is numerically singular. Throws
  // ResourceLimitError when the factor does not fit in memory, std::runtime_error when this build
  // has no PETSc.
  bool solve(const AugmentedMatrix& A, const std::vector<double>& b, std::vector<double>& x);

  int factorisations() const { return factorisations_; }

 private:
  // Returns the backward error of the x it leaves.
  double refine(const AugmentedMatrix& A, const std::vector<double>& row,
                const std::vector<double>& column, const std::vector<double>& b,
                std::vector<double>& x) const;
  void solve_scaled(std::vector<double>& rhs, std::vector<double>& solution) const;

  struct Mumps;
  std::unique_ptr<Mumps> mumps_;
  int factorisations_ = 0;
};

// Whether this build has the sparse LU (PETSc with MUMPS).
bool augmented_lu_available();

}  // namespace styk::solver_detail
