// Reader of the .styk.h5 results file. Everything read is checked against the mesh so a damaged or
// foreign file gives a clear error instead of out-of-range indices downstream.
#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "h5_integrity.hpp"
#include "h5_util.hpp"
#include "results_contact.hpp"
#include "results_extras.hpp"
#include "results_integrity.hpp"
#include "results_open.hpp"
#include "results_rows.hpp"
#include "results_scalar.hpp"
#include "results_schema.hpp"
#include "results_structural.hpp"
#include "styk/io/results_file.hpp"

namespace styk {

namespace {

namespace h5 = io::h5;

[[noreturn]] void corrupt(const std::string& what) {
  throw std::runtime_error("inconsistent contents: " + what);
}

template <typename Array>
std::vector<Array> to_rows(const std::vector<double>& flat) {
  std::vector<Array> rows(flat.size() / std::tuple_size<Array>::value);
  std::copy(flat.begin(), flat.end(), rows.empty() ? nullptr : rows[0].data());
  return rows;
}

std::vector<int> to_indices(const std::vector<std::int64_t>& v, std::int64_t limit,
                            const std::string& what) {
  std::vector<int> out;
  out.reserve(v.size());
  for (const std::int64_t i : v) {
    if (i < 0 || i >= limit)
      corrupt(what + " holds index " + std::to_string(i) + " (range 0.." +
              std::to_string(limit - 1) + ")");
    out.push_back(static_cast<int>(i));
  }
  return out;
}

void read_nodes(hid_t mesh, const SourceLoc& where, Model& model) {
  const h5::Handle nodes = h5::open_group(mesh, "nodes");
  std::vector<std::int64_t> ids;
  std::vector<double> coordinates;
  const std::uint64_t count = h5::read_int64(nodes.get(), "ids", ids);
  if (h5::read_doubles(nodes.get(), "coordinates", 3, coordinates) != count)
    corrupt("node coordinates and ids differ in length");
  if (count > static_cast<std::uint64_t>(std::numeric_limits<int>::max()))
    corrupt("too many nodes");
  model.node_ids.reserve(count);
  model.coords.reserve(count);
  for (std::uint64_t i = 0; i < count; ++i)
    model.add_node(ids[i], {coordinates[3 * i], coordinates[3 * i + 1], coordinates[3 * i + 2]},
                   where);
}

void read_elements(hid_t mesh, const SourceLoc& where, Model& model) {
  const h5::Handle elements = h5::open_group(mesh, "elements");
  std::vector<std::int64_t> ids, connectivity, offsets;
  const std::uint64_t count = h5::read_int64(elements.get(), "ids", ids);
  const std::vector<std::string> types = h5::read_strings(elements.get(), "types");
  h5::read_int64(elements.get(), "connectivity", connectivity);
  h5::read_int64(elements.get(), "offsets", offsets);
  if (types.size() != count || offsets.size() != count + 1)
    corrupt("element ids, types and offsets differ in length");
  if (offsets.front() != 0 || offsets.back() != static_cast<std::int64_t>(connectivity.size()) ||
      !std::is_sorted(offsets.begin(), offsets.end()))
    corrupt("element offsets do not describe the connectivity array");
  const std::vector<int> node_indices =
      to_indices(connectivity, model.node_count(), "/model/elements/connectivity");
  model.elements.reserve(count);
  model.connectivity.reserve(node_indices.size());
  std::vector<int> element_nodes;
  for (std::uint64_t e = 0; e < count; ++e) {
    element_nodes.assign(node_indices.begin() + offsets[e], node_indices.begin() + offsets[e + 1]);
    model.add_element(ids[e], types[e], element_nodes, where);
  }
}

void read_sets(hid_t mesh, const SourceLoc& where, Model& model) {
  const h5::Handle sets = h5::open_group(mesh, "sets");
  std::vector<std::int64_t> members;
  const h5::Handle node_sets = h5::open_group(sets.get(), "nodes");
  for (const std::string& link : h5::link_names(node_sets.get())) {
    h5::read_int64(node_sets.get(), link, members);
    const std::string name = h5::unescape_name(link);
    model.nsets[name] =
        NodeSet{name, to_indices(members, model.node_count(), "node set " + name), where};
  }
  const h5::Handle element_sets = h5::open_group(sets.get(), "elements");
  for (const std::string& link : h5::link_names(element_sets.get())) {
    h5::read_int64(element_sets.get(), link, members);
    const std::string name = h5::unescape_name(link);
    model.elsets[name] =
        ElementSet{name, to_indices(members, model.element_count(), "element set " + name), where};
  }
}

IncrementResult read_increment(hid_t group, const std::string& label, const Model& model) {
  IncrementResult inc;
  inc.step = static_cast<int>(h5::read_int_attribute(group, "step"));
  inc.increment = static_cast<int>(h5::read_int_attribute(group, "increment"));
  inc.step_time = h5::read_double_attribute(group, "step_time");
  inc.total_time = h5::read_double_attribute(group, "total_time");
  const auto nodes = static_cast<std::uint64_t>(model.node_count());
  std::vector<double> flat;
  if (const std::uint64_t rows = h5::read_doubles(group, "U", 3, flat); rows != 0 && rows != nodes)
    corrupt(label + "/U has " + std::to_string(rows) + " rows for " + std::to_string(nodes) +
            " nodes");
  inc.U = to_rows<Vec3>(flat);
  if (const std::uint64_t rows = h5::read_doubles(group, "RF", 3, flat); rows != 0 && rows != nodes)
    corrupt(label + "/RF has " + std::to_string(rows) + " rows for " + std::to_string(nodes) +
            " nodes");
  inc.RF = to_rows<Vec3>(flat);

  std::vector<std::int64_t> offsets;
  h5::read_int64(group, "ip_offsets", offsets);
  if (!offsets.empty() && (offsets.size() != model.elements.size() + 1 || offsets.front() != 0 ||
                           !std::is_sorted(offsets.begin(), offsets.end()) ||
                           offsets.back() > std::numeric_limits<int>::max()))
    corrupt(label + "/ip_offsets does not fit the elements");
  inc.ip_offset.assign(offsets.begin(), offsets.end());
  const std::uint64_t points = offsets.empty() ? 0 : static_cast<std::uint64_t>(offsets.back());
  for (const char* field : {"S", "E"}) {
    const std::uint64_t rows = h5::read_doubles(group, field, 6, flat);
    if (rows != 0 && rows != points)
      corrupt(label + "/" + field + " has " + std::to_string(rows) + " rows for " +
              std::to_string(points) + " integration points");
    (field[0] == 'S' ? inc.S : inc.E) = to_rows<Tensor6>(flat);
  }
  for (const io::schema::RecoveredField& field : io::schema::kRecoveredFields) {
    if (!h5::has_link(group, field.name)) continue;  // a file from before the field existed
    using Per = io::schema::FieldPer;
    const std::uint64_t expected = field.per == Per::ElementNode ? model.connectivity.size()
                                   : field.per == Per::Element   ? model.elements.size()
                                                                 : nodes;
    const std::uint64_t rows = h5::read_doubles(group, field.name, 6, flat);
    if (rows != 0 && rows != expected)
      corrupt(label + "/" + field.name + " has " + std::to_string(rows) + " rows, expected " +
              std::to_string(expected));
    inc.*field.member = to_rows<Tensor6>(flat);
  }
  io::read_contact(group, label, model, inc);
  io::read_scalar(group, label, model, inc);
  io::read_structural(group, label, model, inc);
  io::read_extras(group, label, model, inc);
  return inc;
}

void read_steps(hid_t file, const Model& model, Results& results) {
  const h5::Handle steps = h5::open_group(file, "steps");
  for (const std::string& step_name : h5::link_names(steps.get())) {
    const h5::Handle step = h5::open_group(steps.get(), step_name);
    for (const std::string& name : h5::link_names(step.get())) {
      const h5::Handle group = h5::open_group(step.get(), name);
      results.increments.push_back(
          read_increment(group.get(), "/steps/" + step_name + "/" + name, model));
    }
  }
  // Group names sort as text (step_10 before step_2); the attributes give the true order.
  std::sort(results.increments.begin(), results.increments.end(),
            [](const IncrementResult& a, const IncrementResult& b) {
              return a.step != b.step ? a.step < b.step : a.increment < b.increment;
            });
}

ResultsFileContents read_contents(hid_t file, const std::string& path) {
  ResultsFileContents contents;
  if (!h5::has_link(file, "model") || H5Aexists(file, "format") <= 0 ||
      h5::read_string_attribute(file, "format") != io::schema::kFormat)
    throw std::runtime_error("not a Styk results file (root attribute format is not \"" +
                             std::string(io::schema::kFormat) + "\")");
  contents.schema_version = static_cast<int>(h5::read_int_attribute(file, "schema_version"));
  if (contents.schema_version < 1 || contents.schema_version > io::schema::kSchemaVersion)
    throw std::runtime_error("schema version " + std::to_string(contents.schema_version) +
                             " is not one this build reads (1.." +
                             std::to_string(io::schema::kSchemaVersion) + ")");
  // The digest first: a dataset lost or added is found before any is decoded.
  contents.verified = io::verify_digest(file) == io::FileIntegrity::Checksummed;
  contents.styk_version = h5::read_string_attribute(file, "styk_version");
  contents.model.source = h5::read_string_attribute(file, "source");
  contents.model.heading = h5::read_string_attribute(file, "heading");
  const SourceLoc where{path, 0};
  {
    const h5::Handle mesh = h5::open_group(file, "model");
    read_nodes(mesh.get(), where, contents.model);
    read_elements(mesh.get(), where, contents.model);
    read_sets(mesh.get(), where, contents.model);
    io::read_beam_sections(mesh.get(), where, contents.model);
    io::read_shell_sections(mesh.get(), where, contents.model);
    io::read_shell_normals(mesh.get(), where, contents.model);
  }
  read_steps(file, contents.model, contents.results);
  return contents;
}

}  // namespace

ResultsFileContents read_results_file(const std::string& path) {
  const h5::QuietErrors quiet;
  const SourceLoc where{path, 0};
  h5::Handle file;
  std::optional<io::ResultsSeal> seal;
  try {
    file = io::open_results_for_reading(path, &seal);
  } catch (const std::runtime_error& e) {
    throw InputError(where, e.what());
  }
  try {
    ResultsFileContents contents = read_contents(file.get(), path);
    contents.sealed = seal.has_value();
    return contents;
  } catch (const h5::NonFiniteError& e) {
    throw InputError(where, io::describe_non_finite(file.get(), e) +
                                " \u2014 a results file holds finite numbers only");
  } catch (const InputError& e) {
    throw InputError(where, e.message());
  } catch (const h5::Error& e) {  // HDF5 found its own structure broken
    throw InputError(where, std::string(e.what()) + " \u2014 the file is damaged");
  } catch (const std::runtime_error& e) {
    throw InputError(where, e.what());
  }
}

std::string unverified_notice(const std::string& path) {
  return path +
         ": notice: written before Styk results files carried checksums; what it holds cannot be "
         "verified";
}

}  // namespace styk
