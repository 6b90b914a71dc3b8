// The dense kernels of the supernodal substitutions, from the BLAS Styk links (OpenBLAS on Debian:
// kernels chosen for the CPU at run time, e.g. AVX2, where Eigen's own are compiled for generic
// x86-64), and a guard that keeps OpenBLAS single-threaded while Styk's own worker threads call it.
#pragma once

#include <cstddef>

extern "C" {
void dgemm_(const char* transa, const char* transb, const int* m, const int* n, const int* k,
            const double* alpha, const double* a, const int* lda, const double* b, const int* ldb,
            const double* beta, double* c, const int* ldc, std::size_t transa_length,
            std::size_t transb_length);
void dtrsm_(const char* side, const char* uplo, const char* transa, const char* diag, const int* m,
            const int* n, const double* alpha, const double* a, const int* lda, double* b,
            const int* ldb, std::size_t side_length, std::size_t uplo_length,
            std::size_t transa_length, std::size_t diag_length);
void openblas_set_num_threads(int threads);
int openblas_get_num_threads(void);
}

namespace styk::solver_detail {

// B := op(L)^-1 B for a lower triangular L (m x m, leading dimension lda) and B m x n (ldb).
inline void lower_triangular_solve(bool transpose, int m, int n, const double* L, int lda,
                                   double* B, int ldb) {
  const double one = 1.0;
  dtrsm_("L", "L", transpose ? "T" : "N", "N", &m, &n, &one, L, &lda, B, &ldb, 1, 1, 1, 1);
}

// C := C + alpha op(A) B with op(A) m x k, B k x n, C m x n (column-major, leading dimensions).
inline void multiply_add(bool transpose_a, int m, int n, int k, double alpha, const double* A,
                         int lda, const double* B, int ldb, double* C, int ldc) {
  const double one = 1.0;
  dgemm_(transpose_a ? "T" : "N", "N", &m, &n, &k, &alpha, A, &lda, B, &ldb, &one, C, &ldc, 1, 1);
}

// OpenBLAS runs single-threaded while this lives (callers that spread independent work over
// their own threads would otherwise oversubscribe the cores); the previous count comes back after.
class SingleThreadedBlas {
 public:
  SingleThreadedBlas() : previous_(openblas_get_num_threads()) { openblas_set_num_threads(1); }
  ~SingleThreadedBlas() { openblas_set_num_threads(previous_); }
  SingleThreadedBlas(const SingleThreadedBlas&) = delete;
  SingleThreadedBlas& operator=(const SingleThreadedBlas&) = delete;

 private:
  int previous_;
};

}  // namespace styk::solver_detail
