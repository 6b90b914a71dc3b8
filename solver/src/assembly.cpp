#include "assembly.hpp"

#include <algorithm>

#include "parallel.hpp"

namespace styk::solver_detail {

void element_geometry(const Model& model, int e, ElementGeometry& geometry) {
  const Element& element = model.elements[e];
  const int* nodes = model.element_nodes(e);
  geometry.X.resize(element.node_count, 3);
  for (int k = 0; k < element.node_count; ++k)
    for (int d = 0; d < 3; ++d) geometry.X(k, d) = model.coords[nodes[k]][d];
  geometry.id = element.id;
  geometry.where = element.where;
  geometry.cross_section = cross_section_of(model, e);  // thickness / area of plane and truss
}

void assemble_stiffness(const Model& model, const PreparedModel& prepared,
                        const ElementStates& states, StiffnessMatrix& K, int threads) {
  threads = resolve_threads(threads);
  std::vector<double>& values = K.values();
  values.assign(static_cast<std::size_t>(K.nonzeros()), 0.0);

  struct Scratch {
    ElementGeometry geometry;
    Eigen::MatrixXd Ke;
    std::vector<int> active;
  };
  std::vector<Scratch> scratch(threads);
  const ElementColouring& colouring = K.colouring();
  for (int c = 0; c < colouring.colours(); ++c) {
    const int first = colouring.ptr[c];
    // Elements of one colour share no node, so their scatters never touch the same entry.
    parallel_for(colouring.ptr[c + 1] - first, threads, 8, [&](int begin, int end, int worker) {
      Scratch& s = scratch[worker];
      for (int i = begin; i < end; ++i) {
        const int e = colouring.order[first + i];
        element_geometry(model, e, s.geometry);
        const ElementOptions options{model.sections[model.elements[e].section].selective_volumetric};
        prepared.formulation[e]->stiffness(s.geometry, states.stiffness_law(e), RuleKind::Full,
                                           s.Ke, options);
        const int n = model.elements[e].node_count;
        const int* nodes = model.element_nodes(e);
        s.active.resize(n);
        for (int p = 0; p < n; ++p) s.active[p] = prepared.active_of_node[nodes[p]];
        for (int p = 0; p < n; ++p) {
          const int a = s.active[p];
          const std::int64_t stride = K.row_stride(a);
          for (int q = 0; q < n; ++q) {
            double* block = values.data() + K.block_start(a, s.active[q]);
            for (int r = 0; r < 3; ++r)
              for (int t = 0; t < 3; ++t) block[r * stride + t] += s.Ke(3 * p + r, 3 * q + t);
          }
        }
      }
    });
  }
  K.set_pristine(true);
}

std::vector<double> assemble_loads(const Model& model, const PreparedModel& prepared,
                                   const StepConditions& conditions) {
  std::vector<double> f(prepared.active_dofs(), 0.0);
  for (const DofValue& load : conditions.nodal_loads) f[load.dof] += load.value;
  ElementGeometry geometry;
  Eigen::VectorXd fe;
  for (const DistributedLoad& load : conditions.pressures) {
    element_geometry(model, load.element, geometry);
    prepared.formulation[load.element]->pressure_load(geometry, load.face - 1, load.magnitude, fe);
    const int* nodes = model.element_nodes(load.element);
    for (int k = 0; k < model.elements[load.element].node_count; ++k) {
      const int a = prepared.active_of_node[nodes[k]];
      for (int d = 0; d < 3; ++d) f[3 * a + d] += fe(3 * k + d);
    }
  }
  return f;
}

}  // namespace styk::solver_detail
