#include "assembly.hpp"

#include <algorithm>

#include "parallel.hpp"

namespace styk::solver_detail {

void element_geometry_without_normals(const Model& model, int e, ElementGeometry& geometry) {
  const Element& element = model.elements[e];
  const int* nodes = model.element_nodes(e);
  geometry.X.resize(element.node_count, 3);
  for (int k = 0; k < element.node_count; ++k)
    for (int d = 0; d < 3; ++d) geometry.X(k, d) = model.coords[nodes[k]][d];
  geometry.id = element.id;
  geometry.where = element.where;
  geometry.cross_section = cross_section_of(model, e);  // thickness / area of plane and truss
  const int section = element.section;
  geometry.section = section >= 0 && section < static_cast<int>(model.sections.size())
                         ? &model.sections[section]
                         : nullptr;
  geometry.nodal_normals.resize(0, 3);
}

void element_geometry(const Model& model, const PreparedModel& prepared, int e,
                      ElementGeometry& geometry) {
  element_geometry_without_normals(model, e, geometry);
  const Element& element = model.elements[e];
  const ShellNormals& normals = prepared.shell_normals;
  if (normals.any() && takes_nodal_normals(*prepared.formulation[e])) {
    geometry.nodal_normals.resize(element.node_count, 3);
    for (int k = 0; k < element.node_count; ++k)
      for (int d = 0; d < 3; ++d)
        geometry.nodal_normals(k, d) = normals.at_slot[element.first_node + k][d];
  }
}

void assemble_stiffness(const Model& model, const PreparedModel& prepared,
                        const ElementStates& states, StiffnessMatrix& K, int threads,
                        const std::vector<char>* owned) {
  threads = resolve_threads(threads);
  std::vector<double>& values = K.values();
  values.assign(static_cast<std::size_t>(K.nonzeros()), 0.0);

  struct Scratch {
    ElementGeometry geometry;
    Eigen::MatrixXd Ke;
    std::vector<int> active;
  };
  // Element entry (node p, component r) x (node q, component t) lands in the block of the nodes'
  // active indices at row r, column t: both nodes list their translations first, then rotations,
  // and an element with fewer dofs per node than the node carries fills the leading part.
  std::vector<Scratch> scratch(threads);
  const ElementColouring& colouring = K.colouring();
  for (int c = 0; c < colouring.colours(); ++c) {
    const int first = colouring.ptr[c];
    // Elements of one colour share no node, so their scatters never touch the same entry.
    parallel_for(colouring.ptr[c + 1] - first, threads, 8, [&](int begin, int end, int worker) {
      Scratch& s = scratch[worker];
      for (int i = begin; i < end; ++i) {
        const int e = colouring.order[first + i];
        if (owned != nullptr && !(*owned)[e]) continue;
        element_geometry(model, prepared, e, s.geometry);
        const ElementOptions options{
            model.sections[model.elements[e].section].selective_volumetric};
        prepared.formulation[e]->stiffness(s.geometry, states.stiffness_law(e),
                                           prepared.rule_kind[e], s.Ke, options);
        const int n = model.elements[e].node_count;
        const int m = prepared.formulation[e]->node_dofs();
        const int* nodes = model.element_nodes(e);
        s.active.resize(n);
        for (int p = 0; p < n; ++p) s.active[p] = prepared.active_of_node[nodes[p]];
        for (int p = 0; p < n; ++p) {
          const int a = s.active[p];
          const std::int64_t stride = K.row_stride(a);
          for (int q = 0; q < n; ++q) {
            double* block = values.data() + K.block_start(a, s.active[q]);
            for (int r = 0; r < m; ++r)
              for (int t = 0; t < m; ++t) block[r * stride + t] += s.Ke(m * p + r, m * q + t);
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
  std::vector<int> dofs;
  for (const DistributedLoad& load : conditions.pressures) {
    element_geometry(model, prepared, load.element, geometry);
    try {
      prepared.formulation[load.element]->pressure_load(geometry, load.face - 1, load.magnitude,
                                                        fe);
    } catch (const InputError& error) {  // a label the element cannot take: say so at the load
      if (error.where().line == load.where.line && error.where().file == load.where.file) throw;
      throw InputError(load.where, error.message());
    }
    prepared.element_dofs(model, load.element, dofs);
    for (std::size_t i = 0; i < dofs.size(); ++i) f[dofs[i]] += fe(static_cast<Eigen::Index>(i));
  }
  return f;
}

}  // namespace styk::solver_detail
