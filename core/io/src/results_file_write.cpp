// Writer of the .styk.h5 results file.
#include <cerrno>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "h5_integrity.hpp"
#include "h5_util.hpp"
#include "results_contact.hpp"
#include "results_extras.hpp"
#include "results_file_layout.hpp"
#include "results_integrity.hpp"
#include "results_rows.hpp"
#include "results_scalar.hpp"
#include "results_schema.hpp"
#include "results_structural.hpp"
#include "styk/core/diagnostics.hpp"
#include "styk/io/results_file.hpp"
#include "styk/io/results_seal.hpp"
#include "styk/io/temp_file.hpp"

namespace styk {

namespace {

namespace h5 = io::h5;

static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 must be three packed doubles");
static_assert(sizeof(Tensor6) == 6 * sizeof(double), "Tensor6 must be six packed doubles");

std::string increment_label(const IncrementResult& inc) {
  return "step " + std::to_string(inc.step) + ", increment " + std::to_string(inc.increment);
}

// Sizes are checked before any file is touched, so a mismatch never costs a partial write.
void check_sizes(const Model& model, const IncrementResult& inc) {
  const std::size_t nodes = model.node_ids.size();
  const std::size_t elements = model.elements.size();
  auto complain = [&](const std::string& what) {
    throw std::runtime_error("results of " + increment_label(inc) +
                             " do not match the model: " + what);
  };
  if (inc.step < 1 || inc.increment < 1) complain("step and increment numbers start at 1");
  if (!inc.U.empty() && inc.U.size() != nodes)
    complain(std::to_string(inc.U.size()) + " displacements for " + std::to_string(nodes) +
             " nodes");
  if (!inc.RF.empty() && inc.RF.size() != nodes)
    complain(std::to_string(inc.RF.size()) + " reaction forces for " + std::to_string(nodes) +
             " nodes");
  if (const std::string error = io::structural_size_error(model, inc); !error.empty())
    complain(error);
  for (const io::schema::RecoveredField& field : io::schema::kRecoveredFields) {
    using Per = io::schema::FieldPer;
    const std::size_t rows = (inc.*field.member).size();
    const std::size_t expected = field.per == Per::ElementNode ? model.connectivity.size()
                                 : field.per == Per::Element   ? elements
                                                               : nodes;
    if (rows != 0 && rows != expected)
      complain(std::string(field.name) + " has " + std::to_string(rows) + " rows, expected " +
               std::to_string(expected));
  }
  for (const auto* field : {&inc.scalar.value, &inc.scalar.reaction})
    if (!field->empty() && field->size() != nodes)
      complain(std::to_string(field->size()) + " nodal scalar values for " + std::to_string(nodes) +
               " nodes");
  if (!inc.scalar.flux_nodal.empty() && inc.scalar.flux_nodal.size() != nodes)
    complain(std::to_string(inc.scalar.flux_nodal.size()) + " nodal fluxes for " +
             std::to_string(nodes) + " nodes");
  if (const std::string problem = io::extras_size_problem(model, inc); !problem.empty())
    complain(problem);
  if (inc.ip_offset.empty()) {
    if (!inc.S.empty() || !inc.E.empty()) complain("integration-point values without ip_offset");
    return;
  }
  if (inc.ip_offset.size() != elements + 1)
    complain("ip_offset has " + std::to_string(inc.ip_offset.size()) + " entries for " +
             std::to_string(elements) + " elements (expected elements + 1)");
  for (std::size_t e = 0; e < elements; ++e)
    if (inc.ip_offset[e + 1] < inc.ip_offset[e]) complain("ip_offset decreases");
  const auto points = static_cast<std::size_t>(inc.ip_offset.back());
  if (inc.ip_offset.front() != 0) complain("ip_offset does not start at 0");
  if (!inc.S.empty() && inc.S.size() != points)
    complain(std::to_string(inc.S.size()) + " stresses for " + std::to_string(points) +
             " integration points");
  for (const auto* field : {&inc.scalar.gradient, &inc.scalar.flux})
    if (!field->empty() && field->size() != points)
      complain(std::to_string(field->size()) + " scalar-field gradients or fluxes for " +
               std::to_string(points) + " integration points");
  if (!inc.E.empty() && inc.E.size() != points)
    complain(std::to_string(inc.E.size()) + " strains for " + std::to_string(points) +
             " integration points");
}

void write_rows(hid_t group, const std::string& name, const double* data, std::size_t rows,
                std::size_t cols) {
  io::h5::write_dataset(group, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, data, rows, cols);
}

std::vector<std::int64_t> widen(const std::vector<int>& v) {
  return std::vector<std::int64_t>(v.begin(), v.end());
}

void write_mesh(hid_t file, const Model& model) {
  const h5::Handle mesh = h5::create_group(file, "model");
  {
    const h5::Handle nodes = h5::create_group(mesh.get(), "nodes");
    h5::write_int64(nodes.get(), "ids", model.node_ids);
    write_rows(nodes.get(), "coordinates", model.coords.empty() ? nullptr : model.coords[0].data(),
               model.coords.size(), 3);
  }
  {
    const h5::Handle elements = h5::create_group(mesh.get(), "elements");
    std::vector<std::int64_t> ids, connectivity, offsets{0};
    std::vector<std::string> types;
    ids.reserve(model.elements.size());
    types.reserve(model.elements.size());
    offsets.reserve(model.elements.size() + 1);
    connectivity.reserve(model.connectivity.size());
    for (int e = 0; e < model.element_count(); ++e) {
      const Element& element = model.elements[e];
      ids.push_back(element.id);
      types.push_back(element.type);
      const int* nodes = model.element_nodes(e);
      connectivity.insert(connectivity.end(), nodes, nodes + element.node_count);
      offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
    }
    h5::write_int64(elements.get(), "ids", ids);
    h5::write_strings(elements.get(), "types", types);
    h5::write_int64(elements.get(), "connectivity", connectivity);
    h5::write_int64(elements.get(), "offsets", offsets);
  }
  io::write_beam_sections(mesh.get(), model);
  io::write_shell_sections(mesh.get(), model);
  io::write_shell_normals(mesh.get(), model);
  const h5::Handle sets = h5::create_group(mesh.get(), "sets");
  const h5::Handle node_sets = h5::create_group(sets.get(), "nodes");
  for (const auto& [name, set] : model.nsets)
    h5::write_int64(node_sets.get(), h5::escape_name(name), widen(set.nodes));
  const h5::Handle element_sets = h5::create_group(sets.get(), "elements");
  for (const auto& [name, set] : model.elsets)
    h5::write_int64(element_sets.get(), h5::escape_name(name), widen(set.elements));
}

void write_increment(hid_t steps, const IncrementResult& inc) {
  const std::string step_name = io::schema::step_group(inc.step);
  const h5::Handle step = h5::has_link(steps, step_name) ? h5::open_group(steps, step_name)
                                                         : h5::create_group(steps, step_name);
  const std::string name = io::schema::increment_group(inc.increment);
  if (h5::has_link(step.get(), name))
    throw std::runtime_error(increment_label(inc) + " appears twice in the results");
  const h5::Handle group = h5::create_group(step.get(), name);
  h5::write_attribute(group.get(), "step", std::int64_t{inc.step});
  h5::write_attribute(group.get(), "increment", std::int64_t{inc.increment});
  h5::write_attribute(group.get(), "step_time", inc.step_time);
  h5::write_attribute(group.get(), "total_time", inc.total_time);
  // The index first: a refusal of a non-finite value names its element and integration point.
  h5::write_int64(group.get(), "ip_offsets", widen(inc.ip_offset));
  write_rows(group.get(), "U", inc.U.empty() ? nullptr : inc.U[0].data(), inc.U.size(), 3);
  write_rows(group.get(), "RF", inc.RF.empty() ? nullptr : inc.RF[0].data(), inc.RF.size(), 3);
  write_rows(group.get(), "S", inc.S.empty() ? nullptr : inc.S[0].data(), inc.S.size(), 6);
  write_rows(group.get(), "E", inc.E.empty() ? nullptr : inc.E[0].data(), inc.E.size(), 6);
  for (const io::schema::RecoveredField& field : io::schema::kRecoveredFields) {
    const std::vector<Tensor6>& values = inc.*field.member;
    write_rows(group.get(), field.name, values.empty() ? nullptr : values[0].data(), values.size(),
               6);
  }
  io::write_contact(group.get(), inc);
  io::write_scalar(group.get(), inc);
  io::write_structural(group.get(), inc);
  io::write_extras(group.get(), inc);
}

void write_contents(hid_t file, const Model& model, const Results& results) {
  h5::write_attribute(file, "format", std::string(io::schema::kFormat));
  h5::write_attribute(file, "schema_version", std::int64_t{io::schema::kSchemaVersion});
  h5::write_attribute(file, "styk_version", std::string(STYK_VERSION_STRING));
  h5::write_attribute(file, "source", model.source);
  h5::write_attribute(file, "heading", model.heading);
  write_mesh(file, model);
  const h5::Handle steps = h5::create_group(file, "steps");
  for (const IncrementResult& inc : results.increments) write_increment(steps.get(), inc);
}

h5::Handle create_file(const std::string& path, io::ResultsLayout layout) {
  if (layout != io::ResultsLayout::PreChecksum)
    return io::create_checksummed_file(path, layout == io::ResultsLayout::Sealed);
  return h5::Handle(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose,
                    "cannot create " + path);
}

}  // namespace

namespace io {

void write_results_file_as(const std::string& path, const Model& model, const Results& results,
                           ResultsLayout layout) {
  const h5::QuietErrors quiet;
  const std::string what = "cannot write results file " + path;
  try {
    for (const IncrementResult& inc : results.increments) check_sizes(model, inc);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(what + ": " + e.what());
  }
  TempFile temp(path);
  try {
    {
      h5::Handle file = create_file(temp.temp_path(), layout);
      try {
        write_contents(file.get(), model, results);
      } catch (const h5::NonFiniteError& e) {
        throw NonFiniteResultsError(what + ": " + describe_non_finite(file.get(), e) +
                                    "; Styk writes finite results only, so nothing was written");
      }
      if (layout != ResultsLayout::PreChecksum) write_digest(file.get());
      file.close("cannot finish " + temp.temp_path());
    }
    // Over the bytes HDF5 left on the disk, once it has closed the file.
    if (layout == ResultsLayout::Sealed) seal_results_file(temp.temp_path());
    temp.commit();
  } catch (const NonFiniteResultsError&) {
    throw;
  } catch (const ResourceLimitError&) {
    throw;
  } catch (const std::runtime_error& e) {
    const int error = errno;  // of the failed write, unless the library has called on since
    temp.throw_if_out_of_space(what, error);
    throw std::runtime_error(what + ": " + e.what());
  }
}

}  // namespace io

void write_results_file(const std::string& path, const Model& model, const Results& results) {
  io::write_results_file_as(path, model, results, io::ResultsLayout::Sealed);
}

}  // namespace styk
