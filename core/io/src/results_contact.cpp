#include "results_contact.hpp"

#include <cstdint>
#include <stdexcept>
#include <vector>

namespace styk::io {
namespace {

// Doubles of member `get` of every contact row, `cols` per row.
template <typename Get>
std::vector<double> column(const std::vector<ContactNodeResult>& rows, int cols, Get get) {
  std::vector<double> out;
  out.reserve(rows.size() * cols);
  for (const ContactNodeResult& r : rows) {
    const double* v = get(r);
    out.insert(out.end(), v, v + cols);
  }
  return out;
}

void write(hid_t group, const std::string& name, const std::vector<double>& flat, std::size_t rows,
           std::size_t cols) {
  h5::write_dataset(group, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                    flat.empty() ? nullptr : flat.data(), rows, cols);
}

[[noreturn]] void corrupt(const std::string& what) {
  throw std::runtime_error("inconsistent contents: " + what);
}

}  // namespace

void write_contact(hid_t increment, const IncrementResult& inc) {
  if (inc.contact.empty()) return;
  const h5::Handle group = h5::create_group(increment, "contact");
  const std::vector<ContactNodeResult>& c = inc.contact;
  std::vector<std::int64_t> nodes, pairs, status;
  for (const ContactNodeResult& r : c) {
    nodes.push_back(r.node);
    pairs.push_back(r.pair);
    status.push_back(static_cast<std::int64_t>(r.status));
  }
  h5::write_int64(group.get(), "nodes", nodes);
  h5::write_int64(group.get(), "pairs", pairs);
  h5::write_int64(group.get(), "status", status);
  const std::size_t n = c.size();
  write(group.get(), "area", column(c, 1, [](const ContactNodeResult& r) { return &r.area; }), n,
        0);
  write(group.get(), "pressure",
        column(c, 1, [](const ContactNodeResult& r) { return &r.pressure; }), n, 0);
  write(group.get(), "gap", column(c, 1, [](const ContactNodeResult& r) { return &r.gap; }), n, 0);
  write(group.get(), "shear",
        column(c, 2, [](const ContactNodeResult& r) { return r.shear.data(); }), n, 2);
  write(group.get(), "slip", column(c, 2, [](const ContactNodeResult& r) { return r.slip.data(); }),
        n, 2);
  write(group.get(), "normal",
        column(c, 3, [](const ContactNodeResult& r) { return r.normal.data(); }), n, 3);
  write(group.get(), "t1", column(c, 3, [](const ContactNodeResult& r) { return r.t1.data(); }), n,
        3);
  write(group.get(), "t2", column(c, 3, [](const ContactNodeResult& r) { return r.t2.data(); }), n,
        3);
  write(group.get(), "force",
        column(c, 3, [](const ContactNodeResult& r) { return r.force.data(); }), n, 3);
  std::vector<double> force, moment;
  for (const ContactPairResult& p : inc.contact_pairs) {
    force.insert(force.end(), p.force.begin(), p.force.end());
    moment.insert(moment.end(), p.moment.begin(), p.moment.end());
  }
  write(group.get(), "pair_force", force, inc.contact_pairs.size(), 3);
  write(group.get(), "pair_moment", moment, inc.contact_pairs.size(), 3);
  if (inc.contact_equilibrium.valid) {
    const ContactEquilibrium& e = inc.contact_equilibrium;
    std::vector<double> balance;
    for (const Vec3* v : {&e.applied, &e.reactions, &e.contact_slave, &e.contact_master})
      balance.insert(balance.end(), v->begin(), v->end());
    write(group.get(), "equilibrium", balance, 4, 3);
    h5::write_attribute(group.get(), "equilibrium_residual", e.relative_residual);
  }
}

void read_contact(hid_t increment, const std::string& label, const Model& model,
                  IncrementResult& inc) {
  if (!h5::has_link(increment, "contact")) return;
  const h5::Handle group = h5::open_group(increment, "contact");
  const std::string where = label + "/contact";
  std::vector<std::int64_t> nodes, pairs, status;
  const std::uint64_t n = h5::read_int64(group.get(), "nodes", nodes);
  if (h5::read_int64(group.get(), "pairs", pairs) != n ||
      h5::read_int64(group.get(), "status", status) != n)
    corrupt(where + ": nodes, pairs and status differ in length");
  inc.contact.assign(n, ContactNodeResult{});
  for (std::uint64_t i = 0; i < n; ++i) {
    ContactNodeResult& r = inc.contact[i];
    if (nodes[i] < 0 || nodes[i] >= model.node_count())
      corrupt(where + "/nodes holds index " + std::to_string(nodes[i]));
    if (pairs[i] < 0 || status[i] < 0 || status[i] > 2)
      corrupt(where + ": bad pair index or status in row " + std::to_string(i));
    r.node = static_cast<int>(nodes[i]);
    r.pair = static_cast<int>(pairs[i]);
    r.status = static_cast<ContactStatus>(status[i]);
  }
  std::vector<double> flat;
  auto read = [&](const char* name, std::uint64_t cols, auto assign) {
    if (h5::read_doubles(group.get(), name, cols, flat) != n)
      corrupt(where + "/" + name + " does not have one row per contact node");
    const std::uint64_t width = cols == 0 ? 1 : cols;
    for (std::uint64_t i = 0; i < n; ++i) assign(inc.contact[i], flat.data() + i * width);
  };
  read("area", 0, [](ContactNodeResult& r, const double* v) { r.area = v[0]; });
  read("pressure", 0, [](ContactNodeResult& r, const double* v) { r.pressure = v[0]; });
  read("gap", 0, [](ContactNodeResult& r, const double* v) { r.gap = v[0]; });
  read("shear", 2, [](ContactNodeResult& r, const double* v) { r.shear = {v[0], v[1]}; });
  read("slip", 2, [](ContactNodeResult& r, const double* v) { r.slip = {v[0], v[1]}; });
  read("normal", 3, [](ContactNodeResult& r, const double* v) { r.normal = {v[0], v[1], v[2]}; });
  read("t1", 3, [](ContactNodeResult& r, const double* v) { r.t1 = {v[0], v[1], v[2]}; });
  read("t2", 3, [](ContactNodeResult& r, const double* v) { r.t2 = {v[0], v[1], v[2]}; });
  read("force", 3, [](ContactNodeResult& r, const double* v) { r.force = {v[0], v[1], v[2]}; });
  std::vector<double> force, moment;
  const std::uint64_t pair_count = h5::read_doubles(group.get(), "pair_force", 3, force);
  if (h5::read_doubles(group.get(), "pair_moment", 3, moment) != pair_count)
    corrupt(where + ": pair_force and pair_moment differ in length");
  inc.contact_pairs.assign(pair_count, ContactPairResult{});
  for (std::uint64_t p = 0; p < pair_count; ++p)
    for (int d = 0; d < 3; ++d) {
      inc.contact_pairs[p].force[d] = force[3 * p + d];
      inc.contact_pairs[p].moment[d] = moment[3 * p + d];
    }
  if (h5::has_link(group.get(), "equilibrium")) {
    if (h5::read_doubles(group.get(), "equilibrium", 3, flat) != 4)
      corrupt(where + "/equilibrium is not 4 x 3");
    ContactEquilibrium& e = inc.contact_equilibrium;
    e.valid = true;
    Vec3* rows[] = {&e.applied, &e.reactions, &e.contact_slave, &e.contact_master};
    for (int k = 0; k < 4; ++k)
      for (int d = 0; d < 3; ++d) (*rows[k])[d] = flat[3 * k + d];
    e.relative_residual = h5::read_double_attribute(group.get(), "equilibrium_residual");
  }
}

}  // namespace styk::io
