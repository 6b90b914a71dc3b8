// In-memory results of an analysis: what the solver produced and every consumer reads (HDF5
// writer, .dat writer, VTU export, renderer). One record per converged increment.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "styk/core/model.hpp"

namespace styk {

using Tensor6 = std::array<double, 6>;  // 11, 22, 33, 12, 13, 23

struct IncrementResult {
  int step = 1;                 // 1-based step number
  int increment = 1;            // 1-based increment within the step
  double step_time = 1.0;       // time within the step at the end of the increment
  double total_time = 1.0;      // time accumulated over the steps
  std::vector<Vec3> U;          // displacement per node
  std::vector<Vec3> RF;         // reaction force per node (zero where no dof is prescribed)
  // Integration-point values: element e owns points ip_offset[e] .. ip_offset[e+1]-1.
  std::vector<int> ip_offset;
  std::vector<Tensor6> S;       // stress
  std::vector<Tensor6> E;       // strain, tensor components (eps_12, not gamma_12)

  // Recovered values (SPEC §5); empty when not computed. Element-node values follow the layout
  // of Model::connectivity (element e's node k at elements[e].first_node + k).
  std::vector<Tensor6> S_element_nodes;  // integration-point values extrapolated, unaveraged
  std::vector<Tensor6> E_element_nodes;
  std::vector<Tensor6> S_centroid;       // per element, evaluated at the element centre
  std::vector<Tensor6> E_centroid;
  std::vector<Tensor6> S_nodal_I;        // per node: method I, mean of the element-node values
  std::vector<Tensor6> S_nodal_II;       // per node: method II, mean of the centroid values
  std::vector<Tensor6> E_nodal_I;
  std::vector<Tensor6> E_nodal_II;
};

struct Results {
  std::vector<IncrementResult> increments;
};

}  // namespace styk
