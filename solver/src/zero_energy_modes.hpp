// Zero-energy modes of an element type beyond its rigid-body motions, counted in a small patch a
// mesh of the type forms: 2 x 2 x 2 reference cubes for bricks, 2 x 2 reference squares for plane
// and axisymmetric quadrilaterals (the latter off the axis, at 2 <= r <= 6), and for a shape that
// does not tile by translation (tetrahedra, wedges) the element with its mirror image across each
// face. Counted on the displacements the type stiffens; the rigid motions are 6 for solids, 3 for
// plane elements and 1 (along the axis) for axisymmetric ones. A patch is used because
// single-element modes of some types (C3D20R; C3D6's twist about its axis) do not spread.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "styk/core/element.hpp"

namespace styk::solver_detail {

// The zero eigenvalues (below 1e-9 of the largest in magnitude) of the symmetric matrix
// K(kept, kept): the zero-energy modes of a stiffness over the dofs in `kept`. The beam and
// shell warnings count theirs with it too.
int zero_eigenvalue_count(const Eigen::MatrixXd& K, const std::vector<Eigen::Index>& kept);

// 0 for line elements.
int spurious_zero_energy_modes(const TElement& element, RuleKind kind = RuleKind::Full);

}  // namespace styk::solver_detail
