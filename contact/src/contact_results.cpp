#include "styk/contact/contact_results.hpp"

#include <Eigen/Geometry>

namespace styk::contact {
namespace {

Vec3 to_vec3(const Eigen::Vector3d& v) { return {v[0], v[1], v[2]}; }

}  // namespace

Eigen::Vector3d slave_force(const ContactConstraint& constraint, const ConstraintState& state) {
  Eigen::Vector3d f = Eigen::Vector3d::Zero();
  for (int c = 0; c < 3; ++c) f -= state.lambda[c] * constraint.row(c);
  return f;
}

void fill_contact_results(const Model& model, const std::vector<ContactConstraint>& constraints,
                          const ContactState& state, IncrementResult& out) {
  out.contact.clear();
  out.contact.reserve(constraints.size());
  out.contact_pairs.assign(model.contact_pairs.size(), ContactPairResult{});
  for (std::size_t j = 0; j < constraints.size(); ++j) {
    const ContactConstraint& c = constraints[j];
    const ConstraintState& s = state.nodes.at(j);
    ContactNodeResult r;
    r.pair = c.pair;
    r.node = c.slave;
    r.status = static_cast<ContactStatus>(static_cast<int>(s.status));
    r.area = c.area;
    const Eigen::Vector3d f = slave_force(c, s);
    const double per_area = c.area > 0.0 ? 1.0 / c.area : 1.0;
    r.pressure = s.lambda[0] * per_area;
    r.shear = {f.dot(c.t1) * per_area, f.dot(c.t2) * per_area};
    r.slip = {s.slip[0] / c.gap_scale, s.slip[1] / c.gap_scale};
    r.gap = (c.gap0 - s.d[0]) / c.gap_scale;
    r.normal = to_vec3(c.normal);
    r.t1 = to_vec3(c.t1);
    r.t2 = to_vec3(c.t2);
    r.force = to_vec3(f);
    r.fluid_pressure = s.fluid * per_area;
    out.contact.push_back(r);

    // The pair's force on the slave body: the node's own, and the opposite of it times the weight
    // at slave-side terms (mortar rows of quadratic slave faces).
    ContactPairResult& total = out.contact_pairs.at(c.pair);
    auto add = [&](int node, const Eigen::Vector3d& force) {
      const Eigen::Vector3d x(model.coords[node][0], model.coords[node][1], model.coords[node][2]);
      const Eigen::Vector3d moment = x.cross(force);
      for (int d = 0; d < 3; ++d) {
        total.force[d] += force[d];
        total.moment[d] += moment[d];
      }
    };
    add(c.slave, f);
    for (const MasterTerm& t : c.master)
      if (t.slave_side) add(t.node, -t.weight * f);
  }
}

}  // namespace styk::contact
