// RAII owners for CHOLMOD objects (long-index interface, so factors above 2^31 entries work).
#pragma once

#include <cholmod.h>

#include <memory>

namespace styk::solver_detail {

class CholmodCommon {
 public:
  CholmodCommon() { cholmod_l_start(&common_); }
  ~CholmodCommon() { cholmod_l_finish(&common_); }
  CholmodCommon(const CholmodCommon&) = delete;
  CholmodCommon& operator=(const CholmodCommon&) = delete;
  cholmod_common* get() { return &common_; }
  cholmod_common* operator->() { return &common_; }

 private:
  cholmod_common common_;
};

struct CholmodSparseDeleter {
  cholmod_common* common;
  void operator()(cholmod_sparse* A) const { cholmod_l_free_sparse(&A, common); }
};
struct CholmodFactorDeleter {
  cholmod_common* common;
  void operator()(cholmod_factor* L) const { cholmod_l_free_factor(&L, common); }
};
struct CholmodDenseDeleter {
  cholmod_common* common;
  void operator()(cholmod_dense* X) const { cholmod_l_free_dense(&X, common); }
};

using CholmodSparse = std::unique_ptr<cholmod_sparse, CholmodSparseDeleter>;
using CholmodFactor = std::unique_ptr<cholmod_factor, CholmodFactorDeleter>;
using CholmodDense = std::unique_ptr<cholmod_dense, CholmodDenseDeleter>;

}  // namespace styk::solver_detail
