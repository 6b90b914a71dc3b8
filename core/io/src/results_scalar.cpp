#include "results_scalar.hpp"

#include <cstdint>
#include <stdexcept>
#include <vector>

namespace styk::io {
namespace {

void write_vectors(hid_t group, const std::string& name, const std::vector<Vec3>& rows) {
  h5::write_dataset(group, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                    rows.empty() ? nullptr : rows[0].data(), rows.size(), 3);
}

void write_values(hid_t group, const std::string& name, const std::vector<double>& values) {
  h5::write_dataset(group, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                    values.empty() ? nullptr : values.data(), values.size(), 0);
}

[[noreturn]] void corrupt(const std::string& what) {
  throw std::runtime_error("inconsistent contents: " + what);
}

}  // namespace

void write_scalar(hid_t increment, const IncrementResult& inc) {
  const ScalarFieldResult& s = inc.scalar;
  if (s.kind == ScalarFieldResult::Kind::None) return;
  const h5::Handle group = h5::create_group(increment, "scalar");
  const bool temperature = s.kind == ScalarFieldResult::Kind::Temperature;
  h5::write_attribute(group.get(), "field", std::string(temperature ? "NT" : "EPOT"));
  write_values(group.get(), "value", s.value);
  write_values(group.get(), "reaction", s.reaction);
  write_vectors(group.get(), "gradient", s.gradient);
  write_vectors(group.get(), "flux", s.flux);
  write_vectors(group.get(), "flux_nodal", s.flux_nodal);
}

void read_scalar(hid_t increment, const std::string& label, const Model& model,
                 IncrementResult& inc) {
  if (!h5::has_link(increment, "scalar")) return;
  const h5::Handle group = h5::open_group(increment, "scalar");
  const std::string where = label + "/scalar";
  ScalarFieldResult& s = inc.scalar;
  const std::string field = h5::read_string_attribute(group.get(), "field");
  if (field == "NT")
    s.kind = ScalarFieldResult::Kind::Temperature;
  else if (field == "EPOT")
    s.kind = ScalarFieldResult::Kind::Potential;
  else
    corrupt(where + " names field '" + field + "' (expected NT or EPOT)");
  const auto nodes = static_cast<std::uint64_t>(model.node_count());
  const std::uint64_t points =
      inc.ip_offset.empty() ? 0 : static_cast<std::uint64_t>(inc.ip_offset.back());
  auto read_values = [&](const char* name, std::vector<double>& out) {
    const std::uint64_t rows = h5::read_doubles(group.get(), name, 0, out);
    if (rows != 0 && rows != nodes)
      corrupt(where + "/" + name + " has " + std::to_string(rows) + " rows for " +
              std::to_string(nodes) + " nodes");
  };
  auto read_vectors = [&](const char* name, std::uint64_t expected, std::vector<Vec3>& out) {
    std::vector<double> flat;
    const std::uint64_t rows = h5::read_doubles(group.get(), name, 3, flat);
    if (rows != 0 && rows != expected)
      corrupt(where + "/" + name + " has " + std::to_string(rows) + " rows, expected " +
              std::to_string(expected));
    out.assign(rows, Vec3{});
    for (std::uint64_t i = 0; i < rows; ++i)
      for (int d = 0; d < 3; ++d) out[i][d] = flat[3 * i + d];
  };
  read_values("value", s.value);
  read_values("reaction", s.reaction);
  read_vectors("gradient", points, s.gradient);
  read_vectors("flux", points, s.flux);
  read_vectors("flux_nodal", nodes, s.flux_nodal);
}

}  // namespace styk::io
