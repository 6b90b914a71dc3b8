#include "results_structural.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include "styk/core/beam_section.hpp"

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

const char* integration_name(BeamIntegration integration) {
  return integration == BeamIntegration::Full ? "FULL" : "REDUCED";
}

BeamShape shape_of(const std::string& name, const std::string& where) {
  for (const BeamShape shape : {BeamShape::Rect, BeamShape::Circ, BeamShape::Pipe, BeamShape::Box})
    if (name == beam_shape_name(shape)) return shape;
  corrupt(where + " names beam section shape '" + name + "'");
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
  if (!inc.SFQ.empty() && inc.SFQ.size() != stations(inc))
    return "SFQ has " + std::to_string(inc.SFQ.size()) + " rows for " +
           std::to_string(stations(inc)) + " stations";
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
  if (!inc.SFQ.empty())
    h5::write_dataset(increment, "SFQ", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, inc.SFQ[0].data(),
                      inc.SFQ.size(), 2);
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
  if (h5::has_link(increment, "SFQ")) {  // shells' transverse shear forces (Q13, Q23)
    const std::uint64_t rows = h5::read_doubles(increment, "SFQ", 2, flat);
    if (rows != stations(inc))
      corrupt(label + "/SFQ has " + std::to_string(rows) + " rows, expected " +
              std::to_string(stations(inc)));
    inc.SFQ.resize(rows);
    for (std::uint64_t i = 0; i < rows; ++i) inc.SFQ[i] = {flat[2 * i], flat[2 * i + 1]};
  }
}

void write_beam_sections(hid_t mesh, const Model& model) {
  std::vector<std::string> elsets, shapes, integration;
  std::vector<std::int64_t> counts;
  std::vector<double> dimensions, directions;
  for (const Section& section : model.sections) {
    if (!section.beam) continue;
    const BeamSection& beam = *section.beam;
    elsets.push_back(section.elset);
    shapes.push_back(beam_shape_name(beam.shape));
    integration.push_back(integration_name(beam.integration));
    counts.push_back(static_cast<std::int64_t>(beam.dimensions.size()));
    for (std::size_t k = 0; k < 6; ++k)
      dimensions.push_back(k < beam.dimensions.size() ? beam.dimensions[k] : 0.0);
    directions.insert(directions.end(), beam.direction.begin(), beam.direction.end());
  }
  if (elsets.empty()) return;
  const h5::Handle group = h5::create_group(mesh, "beam_sections");
  h5::write_strings(group.get(), "elsets", elsets);
  h5::write_strings(group.get(), "shapes", shapes);
  h5::write_strings(group.get(), "integration", integration);
  h5::write_int64(group.get(), "dimension_counts", counts);
  h5::write_dataset(group.get(), "dimensions", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, dimensions.data(),
                    elsets.size(), 6);
  h5::write_dataset(group.get(), "directions", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, directions.data(),
                    elsets.size(), 3);
}

void read_beam_sections(hid_t mesh, const SourceLoc& where, Model& model) {
  if (!h5::has_link(mesh, "beam_sections")) return;
  const h5::Handle group = h5::open_group(mesh, "beam_sections");
  const std::string label = "/model/beam_sections";
  const std::vector<std::string> elsets = h5::read_strings(group.get(), "elsets");
  const std::vector<std::string> shapes = h5::read_strings(group.get(), "shapes");
  const std::vector<std::string> integration = h5::read_strings(group.get(), "integration");
  std::vector<std::int64_t> counts;
  std::vector<double> dimensions, directions;
  h5::read_int64(group.get(), "dimension_counts", counts);
  const std::uint64_t rows = h5::read_doubles(group.get(), "dimensions", 6, dimensions);
  if (h5::read_doubles(group.get(), "directions", 3, directions) != rows || shapes.size() != rows ||
      integration.size() != rows || counts.size() != rows || elsets.size() != rows)
    corrupt(label + ": its datasets differ in length");
  for (std::uint64_t i = 0; i < rows; ++i) {
    BeamSection beam;
    beam.shape = shape_of(shapes[i], label);
    if (counts[i] < 1 || counts[i] > 6) corrupt(label + "/dimension_counts out of range");
    beam.dimensions.assign(dimensions.begin() + 6 * i, dimensions.begin() + 6 * i + counts[i]);
    beam.direction = {directions[3 * i], directions[3 * i + 1], directions[3 * i + 2]};
    beam.integration = integration[i] == "FULL" ? BeamIntegration::Full : BeamIntegration::Reduced;
    if (const std::string why = check_beam_section(beam); !why.empty())
      corrupt(label + " row " + std::to_string(i) + ": " + why);
    const ElementSet* set = model.find_elset(elsets[i]);
    if (set == nullptr) corrupt(label + " names element set " + elsets[i] + ", not in the file");
    Section section;
    section.elset = elsets[i];
    section.beam = beam;
    section.where = where;
    const int index = static_cast<int>(model.sections.size());
    model.sections.push_back(std::move(section));
    for (int e : set->elements) model.elements[e].section = index;
  }
}

void write_shell_sections(hid_t mesh, const Model& model) {
  std::vector<std::string> elsets;
  std::vector<double> thickness, offset;
  std::vector<std::int64_t> points;
  for (const Section& section : model.sections) {
    if (!section.shell || !section.thickness) continue;
    elsets.push_back(section.elset);
    thickness.push_back(*section.thickness);
    offset.push_back(section.shell->offset);
    points.push_back(section.shell->section_points);
  }
  if (elsets.empty()) return;
  const h5::Handle group = h5::create_group(mesh, "shell_sections");
  h5::write_strings(group.get(), "elsets", elsets);
  h5::write_dataset(group.get(), "thickness", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, thickness.data(),
                    elsets.size(), 0);
  h5::write_dataset(group.get(), "offset", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, offset.data(),
                    elsets.size(), 0);
  h5::write_int64(group.get(), "section_points", points);
}

void read_shell_sections(hid_t mesh, const SourceLoc& where, Model& model) {
  if (!h5::has_link(mesh, "shell_sections")) return;
  const h5::Handle group = h5::open_group(mesh, "shell_sections");
  const std::string label = "/model/shell_sections";
  const std::vector<std::string> elsets = h5::read_strings(group.get(), "elsets");
  std::vector<double> thickness, offset;
  std::vector<std::int64_t> points;
  h5::read_int64(group.get(), "section_points", points);
  const std::uint64_t rows = h5::read_doubles(group.get(), "thickness", 0, thickness);
  if (h5::read_doubles(group.get(), "offset", 0, offset) != rows || elsets.size() != rows ||
      points.size() != rows)
    corrupt(label + ": its datasets differ in length");
  for (std::uint64_t i = 0; i < rows; ++i) {
    if (!(thickness[i] > 0) || !(std::abs(offset[i]) <= 0.5) || points[i] < 1 || points[i] % 2 == 0)
      corrupt(label + " row " + std::to_string(i) +
              ": thickness must be > 0, |offset| <= 0.5 and section points odd");
    const ElementSet* set = model.find_elset(elsets[i]);
    if (set == nullptr) corrupt(label + " names element set " + elsets[i] + ", not in the file");
    Section section;
    section.elset = elsets[i];
    section.thickness = thickness[i];
    section.shell = ShellSection{offset[i], static_cast<int>(points[i]), true};
    section.where = where;
    const int index = static_cast<int>(model.sections.size());
    model.sections.push_back(std::move(section));
    for (int e : set->elements) model.elements[e].section = index;
  }
}

void write_shell_normals(hid_t mesh, const Model& model) {
  if (model.normals.empty()) return;
  std::vector<std::int64_t> elements, nodes;
  std::vector<double> directions;
  for (const UserNormal& n : model.normals) {
    elements.push_back(n.element);
    nodes.push_back(n.node);
    directions.insert(directions.end(), n.direction.begin(), n.direction.end());
  }
  const h5::Handle group = h5::create_group(mesh, "shell_normals");
  h5::write_int64(group.get(), "elements", elements);
  h5::write_int64(group.get(), "nodes", nodes);
  h5::write_dataset(group.get(), "directions", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, directions.data(),
                    elements.size(), 3);
}

void read_shell_normals(hid_t mesh, const SourceLoc& where, Model& model) {
  if (!h5::has_link(mesh, "shell_normals")) return;
  const h5::Handle group = h5::open_group(mesh, "shell_normals");
  const std::string label = "/model/shell_normals";
  std::vector<std::int64_t> elements, nodes;
  std::vector<double> directions;
  h5::read_int64(group.get(), "elements", elements);
  h5::read_int64(group.get(), "nodes", nodes);
  const std::uint64_t rows = h5::read_doubles(group.get(), "directions", 3, directions);
  if (elements.size() != rows || nodes.size() != rows)
    corrupt(label + ": its datasets differ in length");
  for (std::uint64_t i = 0; i < rows; ++i) {
    const std::int64_t e = elements[i], node = nodes[i];
    if (e < 0 || e >= model.element_count() || node < 0 || node >= model.node_count())
      corrupt(label + " row " + std::to_string(i) + ": element or node index out of range");
    const int* first = model.element_nodes(static_cast<int>(e));
    const int* last = first + model.elements[static_cast<std::size_t>(e)].node_count;
    if (std::find(first, last, static_cast<int>(node)) == last)
      corrupt(label + " row " + std::to_string(i) + ": the node is not one of the element's");
    const Vec3 direction{directions[3 * i], directions[3 * i + 1], directions[3 * i + 2]};
    if (!(std::hypot(direction[0], direction[1], direction[2]) > 0.0))
      corrupt(label + " row " + std::to_string(i) + ": the normal is zero or not finite");
    model.normals.push_back({static_cast<int>(e), static_cast<int>(node), direction, where});
  }
}

}  // namespace styk::io
