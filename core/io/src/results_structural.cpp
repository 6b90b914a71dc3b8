#include "results_structural.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace styk::io {
namespace {

[[noreturn]] void corrupt(const std::string& what) {
  throw std::runtime_error("inconsistent contents: " + what);
}

// The per-node and per-station vector fields of this part, by dataset name.
struct VectorField {
  const char* name;
  std::vector<Vec3> IncrementResult::*member;
  bool per_node;  // else per station
};
constexpr VectorField kFields[] = {{"UR", &IncrementResult::UR, true},
                                   {"RM", &IncrementResult::RM, true},
                                   {"SF", &IncrementResult::SF, false},
                                   {"SM", &IncrementResult::SM, false}};

std::size_t stations(const IncrementResult& inc) {
  return inc.station_offset.empty() ? 0 : static_cast<std::size_t>(inc.station_offset.back());
}

void write_vectors(hid_t group, const char* name, const std::vector<Vec3>& rows) {
  h5::write_dataset(group, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, rows[0].data(), rows.size(), 3);
}

}  // namespace

std::string structural_size_error(const Model& model, const IncrementResult& inc) {
  if (!inc.station_offset.empty()) {
    if (inc.station_offset.size() != model.elements.size() + 1 || inc.station_offset.front() != 0 ||
        !std::is_sorted(inc.station_offset.begin(), inc.station_offset.end()))
      return "station_offset does not fit the elements";
  }
  for (const VectorField& field : kFields) {
    const std::size_t rows = (inc.*field.member).size();
    const std::size_t expected = field.per_node ? model.node_ids.size() : stations(inc);
    if (rows != 0 && rows != expected)
      return std::string(field.name) + " has " + std::to_string(rows) + " rows for " +
             std::to_string(expected) + (field.per_node ? " nodes" : " beam stations");
  }
  return {};
}

void write_structural(hid_t increment, const IncrementResult& inc) {
  if (!inc.station_offset.empty())
    h5::write_int64(
        increment, "station_offsets",
        std::vector<std::int64_t>(inc.station_offset.begin(), inc.station_offset.end()));
  for (const VectorField& field : kFields) {
    const std::vector<Vec3>& rows = inc.*field.member;
    if (!rows.empty()) write_vectors(increment, field.name, rows);
  }
}

void read_structural(hid_t increment, const std::string& label, const Model& model,
                     IncrementResult& inc) {
  if (h5::has_link(increment, "station_offsets")) {
    std::vector<std::int64_t> offsets;
    h5::read_int64(increment, "station_offsets", offsets);
    if (offsets.size() != model.elements.size() + 1 || offsets.front() != 0 ||
        !std::is_sorted(offsets.begin(), offsets.end()) ||
        offsets.back() > std::numeric_limits<int>::max())
      corrupt(label + "/station_offsets does not fit the elements");
    inc.station_offset.assign(offsets.begin(), offsets.end());
  }
  std::vector<double> flat;
  for (const VectorField& field : kFields) {
    if (!h5::has_link(increment, field.name)) continue;
    const std::uint64_t expected =
        field.per_node ? static_cast<std::uint64_t>(model.node_count()) : stations(inc);
    const std::uint64_t rows = h5::read_doubles(increment, field.name, 3, flat);
    if (rows != 0 && rows != expected)
      corrupt(label + "/" + field.name + " has " + std::to_string(rows) + " rows, expected " +
              std::to_string(expected));
    std::vector<Vec3>& out = inc.*field.member;
    out.resize(rows);
    for (std::uint64_t i = 0; i < rows; ++i)
      out[i] = {flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]};
  }
}

}  // namespace styk::io
