#include "recovery.hpp"

#include "assembly.hpp"
#include "parallel.hpp"
#include <optional>

#include "thermal_load.hpp"

namespace styk::solver_detail {
namespace {

// Scratch of one worker, sized on first use and reused for every element.
struct RecoveryScratch {
  ElementGeometry geometry;
  Eigen::VectorXd ue, fe, dv;
  Eigen::MatrixXd strain, stress, positions;
  std::vector<MaterialPoint> laws;
  std::vector<double> internal;  // internal force (global) on the compact reaction nodes
};

// ENER, THE, the element's volume and internal energy from the stresses and strains just
// recovered (s.stress, s.strain): ENER = 1/2 (sigma + sigma0) : (eps - eps_th), the energy
// density of a linear law from the unstrained state, its integral the element's energy.
void element_energies(const TElement& element, const ElementGeometry& g, const ElementMaterial& law,
                      const Eigen::MatrixXd* sigma0, int e, int first, RecoveryScratch& s,
                      IncrementResult& out) {
  element.point_laws(g, law, RuleKind::Full, s.laws);
  element.point_volumes(g, RuleKind::Full, s.dv);
  for (int p = 0; p < s.stress.rows(); ++p) {
    Tensor6 thermal{};
    for (int c = 0; c < 6; ++c) thermal[c] = s.laws[p].thermal_strain[c] * (c < 3 ? 1.0 : 0.5);
    if (!out.THE.empty()) out.THE[first + p] = thermal;
    if (out.ENER.empty()) continue;
    double energy = 0.0;
    for (int c = 0; c < 6; ++c) {
      const double stress = s.stress(p, c) + (sigma0 ? (*sigma0)(p, c) : 0.0);
      energy += (c < 3 ? 0.5 : 1.0) * stress * (s.strain(p, c) - thermal[c]);
    }
    out.ENER[first + p] = energy;
    out.element_energy[e] += energy * s.dv(p);
    out.element_volume[e] += s.dv(p);
  }
}

}  // namespace

void recover_increment(const Model& model, const PreparedModel& prepared,
                       const RecoveryInput& input, int threads, IncrementResult& out) {
  threads = resolve_threads(threads);
  const std::vector<double>& u = input.u;
  const std::optional<ElementStates> initial_states =
      input.states ? std::nullopt
                   : std::optional<ElementStates>(std::in_place, model, prepared, 0, nullptr);
  const ElementStates& states = input.states ? *input.states : *initial_states;
  out.U.assign(model.node_count(), Vec3{0.0, 0.0, 0.0});
  out.RF.assign(model.node_count(), Vec3{0.0, 0.0, 0.0});
  for (int a = 0; a < prepared.active_nodes(); ++a)
    out.U[prepared.node_of_active[a]] = {u[3 * a], u[3 * a + 1], u[3 * a + 2]};
  out.ip_offset = prepared.ip_offset;
  out.S.assign(prepared.ip_offset.back(), Tensor6{});
  out.E.assign(prepared.ip_offset.back(), Tensor6{});
  if (input.energies) {
    out.ENER.assign(prepared.ip_offset.back(), 0.0);
    out.element_volume.assign(model.element_count(), 0.0);
    out.element_energy.assign(model.element_count(), 0.0);
  }
  if (input.thermal_strains) out.THE.assign(prepared.ip_offset.back(), Tensor6{});
  bool cylindrical = false;  // some material axes depend on the point: keep the positions
  for (const Section& section : model.sections)
    if (const auto o = model.orientations.find(section.orientation); o != model.orientations.end())
      cylindrical = cylindrical || o->second.axes.system == CoordinateSystem::Cylindrical;
  if (cylindrical) out.ip_position.assign(prepared.ip_offset.back(), Vec3{});

  // Compact index of each node with a constrained dof: only elements touching one need the
  // internal force.
  std::vector<int> reaction_node(prepared.active_nodes(), -1);
  std::vector<int> node_of_reaction;
  for (int dof : input.reaction_dofs)
    if (reaction_node[dof / 3] < 0) {
      reaction_node[dof / 3] = static_cast<int>(node_of_reaction.size());
      node_of_reaction.push_back(dof / 3);
    }

  std::vector<RecoveryScratch> scratch(threads);
  for (RecoveryScratch& s : scratch) s.internal.assign(3 * node_of_reaction.size(), 0.0);
  parallel_for(model.element_count(), threads, 16, [&](int begin, int end, int worker) {
    RecoveryScratch& s = scratch[worker];
    for (int e = begin; e < end; ++e) {
      const TElement& element = *prepared.formulation[e];
      const int n = model.elements[e].node_count;
      const int* nodes = model.element_nodes(e);
      element_geometry(model, e, s.geometry);
      s.ue.resize(3 * n);
      bool touches_reaction = false;
      for (int k = 0; k < n; ++k) {
        const int a = prepared.active_of_node[nodes[k]];
        for (int d = 0; d < 3; ++d) s.ue(3 * k + d) = u[3 * a + d];
        touches_reaction = touches_reaction || reaction_node[a] >= 0;
      }
      const ElementOptions options{model.sections[model.elements[e].section].selective_volumetric};
      const ElementMaterial law = states.law(e);
      const Eigen::MatrixXd* sigma0 = states.initial_stress(e);
      element.strains_stresses(s.geometry, law, RuleKind::Full, s.ue, s.strain, s.stress, options,
                               sigma0);
      const int first = prepared.ip_offset[e];
      for (int p = 0; p < s.stress.rows(); ++p)
        for (int c = 0; c < 6; ++c) {
          out.S[first + p][c] = s.stress(p, c);
          out.E[first + p][c] = s.strain(p, c);
        }
      if (input.energies || input.thermal_strains)
        element_energies(element, s.geometry, law, sigma0, e, first, s, out);
      if (!out.ip_position.empty()) {
        element.point_positions(s.geometry, RuleKind::Full, s.positions);
        for (int p = 0; p < s.positions.rows(); ++p)
          out.ip_position[first + p] = {s.positions(p, 0), s.positions(p, 1), s.positions(p, 2)};
      }
      if (!touches_reaction) continue;

      // Internal force of the element (B-bar, incompatible modes, hourglass forces and the
      // thermal strain included).
      element.internal_force(s.geometry, law, RuleKind::Full, s.ue, s.fe, options, sigma0);
      for (int k = 0; k < n; ++k) {
        const int r = reaction_node[prepared.active_of_node[nodes[k]]];
        if (r < 0) continue;
        for (int d = 0; d < 3; ++d) s.internal[3 * r + d] += s.fe(3 * k + d);
      }
    }
  });

  // Constraint force in the nodal system, kept on the constrained dofs, reported globally.
  std::vector<char> constrained(prepared.active_dofs(), 0);
  for (int dof : input.reaction_dofs) constrained[dof] = 1;
  for (std::size_t r = 0; r < node_of_reaction.size(); ++r) {
    const int a = node_of_reaction[r];
    Eigen::Vector3d internal = Eigen::Vector3d::Zero();
    for (const RecoveryScratch& s : scratch)
      for (int d = 0; d < 3; ++d) internal[d] += s.internal[3 * r + d];
    const Eigen::Matrix3d* R = input.rotations != nullptr ? input.rotations->of(a) : nullptr;
    if (R != nullptr) internal = R->transpose() * internal;
    Eigen::Vector3d rf = Eigen::Vector3d::Zero();
    for (int d = 0; d < 3; ++d)
      if (constrained[3 * a + d]) rf[d] = internal[d] - input.f[3 * a + d];
    if (R != nullptr) rf = *R * rf;
    out.RF[prepared.node_of_active[a]] = {rf[0], rf[1], rf[2]};
  }
}

void recover_increment(const Model& model, const PreparedModel& prepared,
                       const std::vector<int>& prescribed, const std::vector<double>& u,
                       const std::vector<double>& f, int threads, IncrementResult& out) {
  recover_increment(model, prepared, RecoveryInput{prescribed, u, f}, threads, out);
}

}  // namespace styk::solver_detail
