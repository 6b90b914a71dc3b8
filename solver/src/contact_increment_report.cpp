#include "contact_increment_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <Eigen/Geometry>

#include "styk/contact/contact_results.hpp"
#include "styk/core/vec3.hpp"

namespace styk::solver_detail {
namespace {

// Sums of the force part of a nodal field on active dofs (moments of rotational dofs left out).
Vec3 dof_sum(const PreparedModel& prepared, const std::vector<double>& f) {
  Vec3 sum{0.0, 0.0, 0.0};
  for (int a = 0; a < prepared.active_nodes(); ++a)
    for (int d = 0; d < 3; ++d) sum[d] += f[prepared.dof(a, d)];
  return sum;
}

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
  char buffer[200];
  std::snprintf(buffer, sizeof buffer, pattern, a, b, c);
  return buffer;
}

}  // namespace

std::string node_ids(const Model& model, const std::vector<contact::ContactConstraint>& constraints,
                     const std::vector<int>& which) {
  std::string list;
  const std::size_t shown = std::min<std::size_t>(which.size(), 20);
  for (std::size_t i = 0; i < shown; ++i) {
    if (i > 0) list += ", ";
    list += std::to_string(model.node_ids[constraints[which[i]].slave]);
  }
  if (which.size() > shown) list += ", ... (" + std::to_string(which.size()) + " nodes)";
  return list;
}

void check_equilibrium(const PreparedModel& prepared, const std::vector<double>& applied,
                       const IncrementResult& increment,
                       const std::vector<contact::ContactConstraint>& constraints,
                       const contact::ContactState& state, ContactEquilibrium& out) {
  out.valid = true;
  out.applied = dof_sum(prepared, applied);
  out.reactions = Vec3{0.0, 0.0, 0.0};
  for (const Vec3& rf : increment.RF)
    for (int d = 0; d < 3; ++d) out.reactions[d] += rf[d];
  out.contact_slave = out.contact_master = Vec3{0.0, 0.0, 0.0};
  for (std::size_t j = 0; j < constraints.size(); ++j) {
    const Eigen::Vector3d f = contact::slave_force(constraints[j], state.nodes[j]);
    for (const contact::MasterTerm& t : constraints[j].master)
      for (int d = 0; d < 3; ++d) out.contact_master[d] -= t.weight * f[d];
    for (int d = 0; d < 3; ++d) out.contact_slave[d] += f[d];
  }
  Vec3 imbalance;
  for (int d = 0; d < 3; ++d) imbalance[d] = out.applied[d] + out.reactions[d];
  // Relative to the forces involved, not only to their sums: in a self-balanced model (a full
  // shrink fit under heat) every sum is round-off and a ratio of sums would be meaningless.
  double magnitude = 0.0;
  for (const Vec3& rf : increment.RF) magnitude += as_eigen(rf).norm();
  for (std::size_t j = 0; j < constraints.size(); ++j)
    magnitude += contact::slave_force(constraints[j], state.nodes[j]).norm();
  for (double f : applied) magnitude += std::abs(f);
  const double scale = std::max({as_eigen(out.applied).norm(), as_eigen(out.reactions).norm(),
                                 as_eigen(out.contact_slave).norm(),
                                 magnitude / static_cast<double>(std::max<std::size_t>(
                                                 1, constraints.size() + increment.RF.size())),
                                 1e-300});
  out.relative_residual = as_eigen(imbalance).norm() / scale;
}

std::vector<char> full_slip(const Model& model,
                            const std::vector<contact::ContactConstraint>& constraints,
                            const contact::ContactState& state) {
  std::vector<int> closed(model.contact_pairs.size(), 0), stick(model.contact_pairs.size(), 0);
  std::vector<char> frictional(model.contact_pairs.size(), 0);
  for (std::size_t j = 0; j < constraints.size(); ++j) {
    const int p = constraints[j].pair;
    frictional[p] = frictional[p] || constraints[j].law.kind == contact::FrictionLaw::Kind::Coulomb;
    if (state.nodes[j].status == contact::NodeStatus::Open) continue;
    ++closed[p];
    if (state.nodes[j].status == contact::NodeStatus::Stick) ++stick[p];
  }
  std::vector<char> out(model.contact_pairs.size(), 0);
  for (std::size_t p = 0; p < out.size(); ++p)
    out[p] = frictional[p] && closed[p] > 0 && stick[p] == 0;
  return out;
}

std::string full_slip_report(const Model& model, const IncrementResult& increment, int pair) {
  const ContactPair& cp = model.contact_pairs[pair];
  const ContactPairResult& r = increment.contact_pairs[pair];
  int closed = 0;
  for (const ContactNodeResult& c : increment.contact)
    closed += c.pair == pair && c.status != ContactStatus::Open ? 1 : 0;
  std::string text =
      "contact pair " + cp.slave + "/" + cp.master +
      format(": full slip, all %.0f closed slave nodes slip; contact force ", closed) +
      format("(%.6g, %.6g, %.6g), ", r.force[0], r.force[1], r.force[2]) +
      format("moment (%.6g, %.6g, %.6g) about the origin", r.moment[0], r.moment[1], r.moment[2]);
  for (const CyclicSymmetry& c : model.cyclic_symmetries) {
    const Eigen::Vector3d axis = (as_eigen(c.b) - as_eigen(c.a)).normalized();
    // Moment about the axis through a: (M_origin - a x F) . axis.
    const double m = (as_eigen(r.moment) - as_eigen(c.a).cross(as_eigen(r.force))).dot(axis);
    text += format("; about the axis of cyclic symmetry %.6g per sector, %.6g on the whole", m,
                   m * c.sectors) +
            format(" structure (%.0f sectors)", c.sectors);
  }
  return text;
}

std::string iteration_line(const contact::IterationRecord& r, bool fluid) {
  return format(": iteration %.0f: %.0f stick, ", r.iteration, r.stick) +
         format("%.0f slip, %.0f open, ", r.slip, r.open) +
         format("%.0f changes, residual %.2e", r.changes, r.residual) +
         (r.anticipated > 0 ? format(" (%.0f of them ahead of the slip front)", r.anticipated)
                            : "") +
         (fluid ? format(", %.0f penetrated", r.penetrated) : "") +
         (r.sweeps > 0 ? format(", front predicted by %.0f Gauss-Seidel sweeps", r.sweeps) : "") +
         (r.cycle ? format(", cycle detected: step length %.3g", r.damping) : "") +
         (r.regularised ? ", held by slipping nodes alone: slip springs" : "") +
         (r.reused_factor ? ", previous factor refined" : "");
}

}  // namespace styk::solver_detail
