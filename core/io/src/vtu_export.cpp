// VTK XML UnstructuredGrid writer (file format version 1.0, UInt64 block headers). Every data
// array is written inline as format="binary": base64 of [byte count as UInt64][raw little-endian
// values], header and values encoded as one stream, which is what VTK expects for uncompressed
// inline data.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "base64.hpp"
#include "styk/io/temp_file.hpp"
#include "styk/io/vtu_export.hpp"

namespace styk {

namespace {

bool little_endian() {
  const std::uint16_t probe = 1;
  return *reinterpret_cast<const unsigned char*>(&probe) == 1;
}

template <typename T>
const char* vtk_type_name();
template <>
const char* vtk_type_name<double>() {
  return "Float64";
}
template <>
const char* vtk_type_name<std::int64_t>() {
  return "Int64";
}
template <>
const char* vtk_type_name<std::uint8_t>() {
  return "UInt8";
}

class VtuWriter {
 public:
  explicit VtuWriter(std::ostream& out) : out_(out) {}

  // `component_names` may be empty; otherwise one per component (shown by ParaView).
  template <typename T>
  void array(const std::string& name, int components, const std::vector<T>& values,
             const std::vector<std::string>& component_names = {}) {
    out_ << "        <DataArray type=\"" << vtk_type_name<T>() << "\"";
    if (!name.empty()) out_ << " Name=\"" << name << "\"";
    out_ << " NumberOfComponents=\"" << components << "\" NumberOfTuples=\""
         << values.size() / components << "\"";
    for (std::size_t k = 0; k < component_names.size(); ++k)
      out_ << " ComponentName" << k << "=\"" << component_names[k] << "\"";
    out_ << " format=\"binary\">\n          ";
    const std::uint64_t bytes = values.size() * sizeof(T);
    std::string block(sizeof bytes + bytes, '\0');
    std::memcpy(block.data(), &bytes, sizeof bytes);
    if (bytes > 0) std::memcpy(block.data() + sizeof bytes, values.data(), bytes);
    encoded_.clear();
    io::base64_append(block.data(), block.size(), encoded_);
    out_ << encoded_ << "\n        </DataArray>\n";
  }

 private:
  std::ostream& out_;
  std::string encoded_;
};

std::vector<double> flatten(const std::vector<Vec3>& v) {
  std::vector<double> out;
  out.reserve(3 * v.size());
  for (const Vec3& x : v) out.insert(out.end(), x.begin(), x.end());
  return out;
}

double mises(const Tensor6& s) {
  const double d1 = s[0] - s[1], d2 = s[1] - s[2], d3 = s[2] - s[0];
  return std::sqrt(0.5 * (d1 * d1 + d2 * d2 + d3 * d3) +
                   3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

std::string increment_label(const IncrementResult& inc) {
  return "step " + std::to_string(inc.step) + ", increment " + std::to_string(inc.increment);
}

void check_sizes(const Model& model, const IncrementResult& inc) {
  const std::size_t nodes = model.node_ids.size();
  for (const auto* field : {&inc.U, &inc.RF, &inc.UR, &inc.RM})
    if (!field->empty() && field->size() != nodes)
      throw std::runtime_error("results of " + increment_label(inc) + " hold " +
                               std::to_string(field->size()) + " nodal vectors for " +
                               std::to_string(nodes) + " nodes");
  for (const auto* field : {&inc.S_nodal_I, &inc.S_nodal_II})
    if (!field->empty() && field->size() != nodes)
      throw std::runtime_error("results of " + increment_label(inc) + " hold " +
                               std::to_string(field->size()) + " nodal stresses for " +
                               std::to_string(nodes) + " nodes");
  for (const auto* field : {&inc.scalar.value, &inc.scalar.reaction})
    if (!field->empty() && field->size() != nodes)
      throw std::runtime_error("results of " + increment_label(inc) + " hold " +
                               std::to_string(field->size()) + " nodal scalars for " +
                               std::to_string(nodes) + " nodes");
  if (!inc.scalar.flux_nodal.empty() && inc.scalar.flux_nodal.size() != nodes)
    throw std::runtime_error("results of " + increment_label(inc) + " hold " +
                             std::to_string(inc.scalar.flux_nodal.size()) + " nodal fluxes for " +
                             std::to_string(nodes) + " nodes");
  for (const ContactNodeResult& c : inc.contact)
    if (c.node < 0 || static_cast<std::size_t>(c.node) >= nodes)
      throw std::runtime_error("results of " + increment_label(inc) +
                               " hold contact output for node index " + std::to_string(c.node) +
                               " of a model with " + std::to_string(nodes) + " nodes");
  if (!inc.S.empty() && (inc.ip_offset.size() != model.elements.size() + 1 ||
                         inc.S.size() != static_cast<std::size_t>(inc.ip_offset.back())))
    throw std::runtime_error("results of " + increment_label(inc) +
                             ": stresses do not match ip_offset and the elements");
}

// Tensors in VTK's symmetric-tensor order (XX YY ZZ XY YZ XZ; ours is 11 22 33 12 13 23) and
// their von Mises values.
void write_tensor_array(VtuWriter& writer, const std::string& name,
                        const std::vector<Tensor6>& tensors) {
  std::vector<double> components, mises_values;
  components.reserve(6 * tensors.size());
  mises_values.reserve(tensors.size());
  for (const Tensor6& s : tensors) {
    components.insert(components.end(), {s[0], s[1], s[2], s[3], s[5], s[4]});
    mises_values.push_back(mises(s));
  }
  writer.array(name, 6, components, {"XX", "YY", "ZZ", "XY", "YZ", "XZ"});
  writer.array(name + "_mises", 1, mises_values);
}

// Contact output as point data: one value per node, NaN at nodes that are no slave node (ParaView
// leaves NaN out of colour ranges and draws it in its NaN colour). A node that is a slave of more
// than one pair shows its most engaged entry: the highest status (slip > stick > open), then the
// larger pressure -- the same rule as the renderer (docs/render.md).
void write_contact_arrays(VtuWriter& writer, const Model& model, const IncrementResult& inc) {
  std::vector<const ContactNodeResult*> entry(model.node_ids.size(), nullptr);
  for (const ContactNodeResult& c : inc.contact) {
    const ContactNodeResult*& held = entry[c.node];
    if (!held || c.status > held->status ||
        (c.status == held->status && c.pressure > held->pressure))
      held = &c;
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> pressure(entry.size(), nan), shear(entry.size(), nan),
      slip(entry.size(), nan), gap(entry.size(), nan), status(entry.size(), nan);
  for (std::size_t n = 0; n < entry.size(); ++n) {
    const ContactNodeResult* c = entry[n];
    if (!c) continue;
    pressure[n] = c->pressure;
    shear[n] = std::hypot(c->shear[0], c->shear[1]);
    slip[n] = std::hypot(c->slip[0], c->slip[1]);
    gap[n] = c->gap;
    status[n] = static_cast<double>(static_cast<int>(c->status));
  }
  writer.array("CPRESS", 1, pressure);
  writer.array("CSHEAR", 1, shear);
  writer.array("CSLIP", 1, slip);
  writer.array("CGAP", 1, gap);
  writer.array("CSTATUS", 1, status);
}

// The VTK cell of every element type of the model, checked: a type the registry does not know,
// or one without a cell, is refused at the first element of that type.
std::map<std::string, VtkCell> cells_of_types(const Model& model, const ElementRegistry& registry) {
  std::map<std::string, VtkCell> cells;
  for (const Element& element : model.elements) {
    if (cells.count(element.type)) continue;
    const TElement* formulation = registry.find(element.type);
    if (formulation == nullptr) {
      std::string message = "element " + std::to_string(element.id) + " has type " + element.type +
                            ", which no loaded formulation describes";
      if (!registry.searched_paths.empty())
        message += " (plug-ins searched in " + registry.searched_paths + ")";
      throw InputError(element.where, message + ": it cannot be exported");
    }
    VtkCell cell = formulation->vtk_cell();
    const bool valid = cell.type > 0 && !cell.nodes.empty() &&
                       std::all_of(cell.nodes.begin(), cell.nodes.end(), [&](int k) {
                         return k >= 0 && k < formulation->node_count() && k < element.node_count;
                       });
    if (!valid)
      throw InputError(element.where, "element " + std::to_string(element.id) + " (" +
                                          element.type +
                                          ") describes no VTK cell (TElement::vtk_cell()): it "
                                          "cannot be exported");
    cells.emplace(element.type, std::move(cell));
  }
  return cells;
}

}  // namespace

VtuExportSummary write_vtu(const std::string& path, const Model& model,
                           const ElementRegistry& registry, const IncrementResult* inc) {
  if (inc != nullptr) check_sizes(model, *inc);
  const std::map<std::string, VtkCell> cells = cells_of_types(model, registry);
  VtuExportSummary summary;
  std::vector<std::int64_t> connectivity, offsets, element_ids;
  std::vector<std::uint8_t> types;
  std::vector<int> exported;  // element index of each cell
  for (int e = 0; e < model.element_count(); ++e) {
    const Element& element = model.elements[e];
    const VtkCell& cell = cells.at(element.type);
    const int* nodes = model.element_nodes(e);
    for (const int k : cell.nodes) connectivity.push_back(nodes[k]);
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
    types.push_back(static_cast<std::uint8_t>(cell.type));
    element_ids.push_back(element.id);
    exported.push_back(e);
  }
  summary.cells_written = static_cast<int>(exported.size());

  io::TempFile temp(path);
  {
    std::ofstream out(temp.temp_path(), std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot create " + temp.temp_path());
    VtuWriter writer(out);
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\""
        << (little_endian() ? "LittleEndian" : "BigEndian") << "\" header_type=\"UInt64\">\n"
        << "  <UnstructuredGrid>\n";
    if (inc != nullptr) {
      // TimeValue is the field ParaView reads as the dataset's time.
      out << "    <FieldData>\n";
      writer.array("TimeValue", 1, std::vector<double>{inc->total_time});
      writer.array("step", 1, std::vector<std::int64_t>{inc->step});
      writer.array("increment", 1, std::vector<std::int64_t>{inc->increment});
      out << "    </FieldData>\n";
    }
    out << "    <Piece NumberOfPoints=\"" << model.node_count() << "\" NumberOfCells=\""
        << exported.size() << "\">\n";

    out << "      <PointData>\n";
    if (inc != nullptr && !inc->U.empty()) writer.array("U", 3, flatten(inc->U));
    if (inc != nullptr && !inc->RF.empty()) writer.array("RF", 3, flatten(inc->RF));
    // Rotations and reaction moments of models with beams.
    if (inc != nullptr && !inc->UR.empty()) writer.array("UR", 3, flatten(inc->UR));
    if (inc != nullptr && !inc->RM.empty()) writer.array("RM", 3, flatten(inc->RM));
    if (inc != nullptr && !inc->S_nodal_I.empty())
      write_tensor_array(writer, "S_nodal_I", inc->S_nodal_I);
    if (inc != nullptr && !inc->S_nodal_II.empty())
      write_tensor_array(writer, "S_nodal_II", inc->S_nodal_II);
    if (inc != nullptr && !inc->contact.empty()) write_contact_arrays(writer, model, *inc);
    if (inc != nullptr && inc->scalar.kind != ScalarFieldResult::Kind::None) {
      // Steady heat / electric potential: the field, its reaction flows and the nodal flux.
      const bool heat = inc->scalar.kind == ScalarFieldResult::Kind::Temperature;
      if (!inc->scalar.value.empty()) writer.array(heat ? "NT" : "EPOT", 1, inc->scalar.value);
      if (!inc->scalar.reaction.empty())
        writer.array(heat ? "RFL" : "RECUR", 1, inc->scalar.reaction);
      if (!inc->scalar.flux_nodal.empty())
        writer.array(heat ? "HFL" : "ECD", 3, flatten(inc->scalar.flux_nodal));
    }
    out << "      </PointData>\n";

    out << "      <CellData>\n";
    writer.array("element_id", 1, element_ids);
    if (inc != nullptr && !inc->S.empty()) {
      std::vector<Tensor6> means;
      means.reserve(exported.size());
      for (const int e : exported) {
        const int first = inc->ip_offset[e], last = inc->ip_offset[e + 1];
        Tensor6 s{};
        for (int p = first; p < last; ++p)
          for (int k = 0; k < 6; ++k) s[k] += inc->S[p][k];
        const double scale =
            last > first ? 1.0 / (last - first) : std::numeric_limits<double>::quiet_NaN();
        for (double& v : s) v *= scale;
        means.push_back(s);
      }
      write_tensor_array(writer, "S_ip_mean", means);
    }
    // Beam section forces and moments, the mean over the element's stations (NaN elsewhere).
    if (inc != nullptr && !inc->SF.empty()) {
      using Named = std::pair<const char*, const std::vector<Vec3>*>;
      for (const auto& [name, field] : {Named{"SF", &inc->SF}, Named{"SM", &inc->SM}}) {
        std::vector<Vec3> means;
        means.reserve(exported.size());
        for (const int e : exported) {
          const int first = inc->station_offset[e], last = inc->station_offset[e + 1];
          Vec3 v{0.0, 0.0, 0.0};
          for (int p = first; p < last; ++p)
            for (int k = 0; k < 3; ++k) v[k] += (*field)[p][k];
          const double scale =
              last > first ? 1.0 / (last - first) : std::numeric_limits<double>::quiet_NaN();
          for (double& c : v) c *= scale;
          means.push_back(v);
        }
        writer.array(name, 3, flatten(means));
      }
    }
    // Shells' transverse shear forces Q13, Q23, the mean over the element's stations (NaN at
    // elements without them; beams carry theirs in SF).
    if (inc != nullptr && !inc->SFQ.empty()) {
      std::vector<double> means;
      means.reserve(2 * exported.size());
      for (const int e : exported) {
        const int first = inc->station_offset[e], last = inc->station_offset[e + 1];
        const TElement* type = registry.find(model.elements[e].type);
        const bool shell =
            last > first && type != nullptr && type->section_measure() == SectionMeasure::Shell;
        double q[2] = {0.0, 0.0};
        for (int p = first; shell && p < last; ++p)
          for (int k = 0; k < 2; ++k) q[k] += inc->SFQ[p][k];
        for (const double v : q)
          means.push_back(shell ? v / (last - first) : std::numeric_limits<double>::quiet_NaN());
      }
      writer.array("SFQ", 2, means, {"Q13", "Q23"});
    }
    out << "      </CellData>\n";

    out << "      <Points>\n";
    writer.array("Points", 3, flatten(model.coords));
    out << "      </Points>\n";

    out << "      <Cells>\n";
    writer.array("connectivity", 1, connectivity);
    writer.array("offsets", 1, offsets);
    writer.array("types", 1, types);
    out << "      </Cells>\n"
        << "    </Piece>\n"
        << "  </UnstructuredGrid>\n"
        << "</VTKFile>\n";
    out.close();
    if (!out) {
      temp.throw_if_out_of_space("cannot write " + path, errno);
      throw std::runtime_error("cannot write " + temp.temp_path());
    }
  }
  temp.commit();
  return summary;
}

}  // namespace styk
