// Stress recovery: strains and stresses at the integration points of every element (full rule),
// nodal displacements, and reactions RF = internal force - external load at prescribed dofs, the
// internal force integral B^T sigma being summed in the same pass (no second stiffness pass).
#pragma once

#include <vector>

#include "prepared_model.hpp"
#include "step_conditions.hpp"
#include "styk/core/results.hpp"

namespace styk::solver_detail {

// Fills U, RF, ip_offset, S and E of `out`. u and f are on active dofs.
void recover_increment(const Model& model, const PreparedModel& prepared,
                       const std::vector<int>& prescribed, const std::vector<double>& u,
                       const std::vector<double>& f, int threads, IncrementResult& out);

}  // namespace styk::solver_detail
