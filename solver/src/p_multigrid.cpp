#include "p_multigrid.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include "petsc_runtime.hpp"
#include "rigid_body_modes.hpp"

namespace styk::solver_detail {
namespace {

// Where the coarse dofs live: coarse node j belongs to the rank owning its corner node's rows,
// and each rank's coarse nodes are numbered consecutively in the order of those rows (one process:
// the order of the space).
struct CoarseLayout {
  std::vector<PetscInt> first_row;  // coarse node -> its first coarse row (3 per node)
  std::vector<int> owned;           // this rank's coarse nodes, in row order
  PetscInt begin = 0, end = 0;      // this rank's coarse rows
};

CoarseLayout coarse_layout(const LinearCoarseSpace& space, const RankRows& rows) {
  const int nodes = space.coarse_nodes;
  std::vector<std::vector<std::pair<int, int>>> by_rank(rows.size);  // (fine row, coarse node)
  for (int j = 0; j < nodes; ++j) {
    const int fine_row = rows.row(3 * space.corner_node[j]);
    by_rank[rows.owner(fine_row)].push_back({fine_row, j});
  }
  CoarseLayout layout;
  layout.first_row.assign(nodes, 0);
  PetscInt next = 0;
  for (int r = 0; r < rows.size; ++r) {
    std::sort(by_rank[r].begin(), by_rank[r].end());
    if (r == rows.rank) layout.begin = next;
    for (const auto& [fine_row, j] : by_rank[r]) {
      layout.first_row[j] = next;
      next += 3;
      if (r == rows.rank) layout.owned.push_back(j);
    }
    if (r == rows.rank) layout.end = next;
  }
  return layout;
}

// P = P_node (x) I_3 over this rank's fine rows: dof 3a + c takes w_j times coarse row
// first_row[j] + c.
Mat interpolation(const LinearCoarseSpace& space, const RankRows& rows, const CoarseLayout& layout,
                  MPI_Comm comm) {
  const PetscInt local = rows.end() - rows.begin();
  std::vector<PetscInt> inside(local, 0), outside(local, 0);
  for (PetscInt p = 0; p < local; ++p) {
    const int a = rows.dof(static_cast<int>(rows.begin() + p)) / 3;
    for (int k = space.ptr[a]; k < space.ptr[a + 1]; ++k) {
      const PetscInt column = layout.first_row[space.node[k]];
      (column >= layout.begin && column < layout.end ? inside : outside)[p] += 1;
    }
  }
  Mat P = nullptr;
  petsc_check(MatCreateAIJ(comm, local, layout.end - layout.begin, PETSC_DETERMINE, PETSC_DETERMINE,
                           0, inside.data(), 0, outside.data(), &P),
              "MatCreateAIJ");
  std::vector<PetscInt> columns;
  for (PetscInt row = rows.begin(); row < rows.end(); ++row) {
    const int dof = rows.dof(static_cast<int>(row));
    const int a = dof / 3, c = dof % 3;
    columns.clear();
    for (int k = space.ptr[a]; k < space.ptr[a + 1]; ++k)
      columns.push_back(layout.first_row[space.node[k]] + c);
    petsc_check(MatSetValues(P, 1, &row, static_cast<PetscInt>(columns.size()), columns.data(),
                             space.weight.data() + space.ptr[a], INSERT_VALUES),
                "MatSetValues");
  }
  petsc_check(MatAssemblyBegin(P, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  petsc_check(MatAssemblyEnd(P, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  petsc_check(MatSetBlockSizes(P, 3, 3), "MatSetBlockSizes");
  return P;
}

// The coordinates of the corner nodes this rank owns, in coarse row order.
std::vector<double> owned_corner_coordinates(const std::vector<double>& xyz,
                                             const CoarseLayout& layout) {
  std::vector<double> out;
  out.reserve(3 * layout.owned.size());
  for (int j : layout.owned)
    for (int d = 0; d < 3; ++d) out.push_back(xyz[3 * j + d]);
  return out;
}

}  // namespace

PMultigrid::~PMultigrid() {
  MatDestroy(&coarse_);
  MatDestroy(&P_);
}

void PMultigrid::configure(PC pc, Mat A, const LinearCoarseSpace& space,
                           const std::vector<double>& corner_xyz, PetscReal threshold,
                           const RankRows* rows) {
  RankRows one_process;
  if (rows == nullptr) {
    PetscInt fine_rows = 0;
    petsc_check(MatGetSize(A, &fine_rows, nullptr), "MatGetSize");
    one_process.first = {0, static_cast<int>(fine_rows)};
    rows = &one_process;
  }
  const MPI_Comm comm = rows->size > 1 ? PETSC_COMM_WORLD : PETSC_COMM_SELF;
  MatDestroy(&coarse_);  // a PC configured again (a new system) drops the previous level
  MatDestroy(&P_);
  const CoarseLayout layout = coarse_layout(space, *rows);
  P_ = interpolation(space, *rows, layout, comm);
  petsc_check(MatPtAP(A, P_, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &coarse_), "MatPtAP");
  petsc_check(MatSetBlockSize(coarse_, 3), "MatSetBlockSize");
  attach_rigid_body_modes(coarse_, comm, owned_corner_coordinates(corner_xyz, layout));
  coarse_rows_ = 3 * static_cast<PetscInt>(space.coarse_nodes);

  petsc_check(PCSetType(pc, PCMG), "PCSetType");
  petsc_check(PCMGSetLevels(pc, 2, nullptr), "PCMGSetLevels");
  petsc_check(PCMGSetGalerkin(pc, PC_MG_GALERKIN_NONE), "PCMGSetGalerkin");
  petsc_check(PCMGSetInterpolation(pc, 1, P_), "PCMGSetInterpolation");
  // Fine level: Chebyshev over Jacobi, eigenvalue bounds estimated as GAMG's levels do.
  KSP smoother = nullptr;
  petsc_check(PCMGGetSmoother(pc, 1, &smoother), "PCMGGetSmoother");
  petsc_check(KSPSetType(smoother, KSPCHEBYSHEV), "KSPSetType");
  petsc_check(KSPChebyshevEstEigSet(smoother, 0.0, 0.1, 0.0, 1.1), "KSPChebyshevEstEigSet");
  petsc_check(KSPSetTolerances(smoother, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, 2),
              "KSPSetTolerances");
  PC jacobi = nullptr;
  petsc_check(KSPGetPC(smoother, &jacobi), "KSPGetPC");
  petsc_check(PCSetType(jacobi, PCJACOBI), "PCSetType");
  // Coarse level: one GAMG V-cycle on P^T A P.
  petsc_check(PCMGGetCoarseSolve(pc, &coarse_solve_), "PCMGGetCoarseSolve");
  petsc_check(KSPSetOperators(coarse_solve_, coarse_, coarse_), "KSPSetOperators");
  petsc_check(KSPSetType(coarse_solve_, KSPPREONLY), "KSPSetType");
  PC gamg = nullptr;
  petsc_check(KSPGetPC(coarse_solve_, &gamg), "KSPGetPC");
  petsc_check(PCSetType(gamg, PCGAMG), "PCSetType");
  petsc_check(PCGAMGSetType(gamg, PCGAMGAGG), "PCGAMGSetType");
  petsc_check(PCGAMGSetNSmooths(gamg, 1), "PCGAMGSetNSmooths");
  PetscReal thresholds[] = {threshold};
  petsc_check(PCGAMGSetThreshold(gamg, thresholds, 1), "PCGAMGSetThreshold");
}

PetscInt PMultigrid::gamg_levels() const {
  if (!coarse_solve_) return 0;
  PC gamg = nullptr;
  KSPGetPC(coarse_solve_, &gamg);
  PetscInt levels = 0;
  PCMGGetLevels(gamg, &levels);
  return levels;
}

}  // namespace styk::solver_detail
