#include "results_extras.hpp"

#include <cstdint>
#include <stdexcept>
#include <vector>

namespace styk::io {
namespace {

void write_values(hid_t group, const char* name, const std::vector<double>& values) {
  if (values.empty()) return;
  h5::write_dataset(group, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, values.data(), values.size(),
                    0);
}

[[noreturn]] void corrupt(const std::string& what) {
  throw std::runtime_error("inconsistent contents: " + what);
}

}  // namespace

std::string extras_size_problem(const Model& model, const IncrementResult& inc) {
  const std::size_t points =
      inc.ip_offset.empty() ? 0 : static_cast<std::size_t>(inc.ip_offset.back());
  const std::size_t elements = model.elements.size();
  auto mismatch = [](const char* name, std::size_t rows, std::size_t expected) {
    return rows != 0 && rows != expected ? std::string(name) + " has " + std::to_string(rows) +
                                               " rows, expected " + std::to_string(expected)
                                         : std::string();
  };
  for (const std::string& problem :
       {mismatch("ENER", inc.ENER.size(), points), mismatch("THE", inc.THE.size(), points),
        mismatch("EVOL", inc.element_volume.size(), elements),
        mismatch("ELSE", inc.element_energy.size(), elements),
        mismatch("ERR", inc.ERR.size(), elements)})
    if (!problem.empty()) return problem;
  return {};
}

void write_extras(hid_t increment, const IncrementResult& inc) {
  write_values(increment, "ENER", inc.ENER);
  if (!inc.THE.empty())
    h5::write_dataset(increment, "THE", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, inc.THE[0].data(),
                      inc.THE.size(), 6);
  write_values(increment, "EVOL", inc.element_volume);
  write_values(increment, "ELSE", inc.element_energy);
  write_values(increment, "ERR", inc.ERR);
}

void read_extras(hid_t increment, const std::string& label, const Model& model,
                 IncrementResult& inc) {
  const std::uint64_t points =
      inc.ip_offset.empty() ? 0 : static_cast<std::uint64_t>(inc.ip_offset.back());
  const auto elements = static_cast<std::uint64_t>(model.element_count());
  auto read_values = [&](const char* name, std::uint64_t expected, std::vector<double>& out) {
    if (!h5::has_link(increment, name)) return;
    const std::uint64_t rows = h5::read_doubles(increment, name, 0, out);
    if (rows != expected)
      corrupt(label + "/" + name + " has " + std::to_string(rows) + " rows, expected " +
              std::to_string(expected));
  };
  read_values("ENER", points, inc.ENER);
  read_values("EVOL", elements, inc.element_volume);
  read_values("ELSE", elements, inc.element_energy);
  read_values("ERR", elements, inc.ERR);
  if (h5::has_link(increment, "THE")) {
    std::vector<double> flat;
    const std::uint64_t rows = h5::read_doubles(increment, "THE", 6, flat);
    if (rows != points)
      corrupt(label + "/THE has " + std::to_string(rows) + " rows, expected " +
              std::to_string(points));
    inc.THE.assign(rows, Tensor6{});
    for (std::uint64_t i = 0; i < rows; ++i)
      for (int c = 0; c < 6; ++c) inc.THE[i][c] = flat[6 * i + c];
  }
}

}  // namespace styk::io
