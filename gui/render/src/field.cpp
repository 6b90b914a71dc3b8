#include "styk/render/field.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <functional>

#include <Eigen/Eigenvalues>

#include "contact_field.hpp"
#include "styk/core/diagnostics.hpp"
#include "styk/render/point_field.hpp"

namespace styk::render {
namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string join(const std::vector<std::string>& items, const char* separator) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : separator) + item;
  return out;
}

// ---- vectors ----------------------------------------------------------------------------------
// Suffix -> component (0..2) or 3 = magnitude.
int vector_component(const std::string& suffix) {
  if (suffix.empty() || suffix == "mag" || suffix == "magnitude") return 3;
  if (suffix == "x" || suffix == "1") return 0;
  if (suffix == "y" || suffix == "2") return 1;
  if (suffix == "z" || suffix == "3") return 2;
  return -1;
}

// ---- tensors ----------------------------------------------------------------------------------
using TensorFunction = std::function<double(const Tensor6&)>;

std::array<double, 3> principal_values(const Tensor6& t) {  // ascending
  Eigen::Matrix3d m;
  // clang-format off
  m << t[0], t[3], t[4],
       t[3], t[1], t[5],
       t[4], t[5], t[2];
  // clang-format on
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(m, Eigen::EigenvaluesOnly);
  const Eigen::Vector3d ev = solver.eigenvalues();
  return {ev(0), ev(1), ev(2)};
}

double mises(const Tensor6& t) {
  const double a = t[0] - t[1], b = t[1] - t[2], c = t[2] - t[0];
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * (t[3] * t[3] + t[4] * t[4] + t[5] * t[5]));
}

// Tensor suffix -> function; empty function when unknown. Mises and Tresca only for stress.
TensorFunction tensor_function(const std::string& suffix, bool stress) {
  static const std::array<const char*, 6> kComponents = {"11", "22", "33", "12", "13", "23"};
  for (int i = 0; i < 6; ++i)
    if (suffix == kComponents[i]) return [i](const Tensor6& t) { return t[i]; };
  if (suffix == "p1" || suffix == "max_principal")
    return [](const Tensor6& t) { return principal_values(t)[2]; };
  if (suffix == "p2" || suffix == "mid_principal")
    return [](const Tensor6& t) { return principal_values(t)[1]; };
  if (suffix == "p3" || suffix == "min_principal")
    return [](const Tensor6& t) { return principal_values(t)[0]; };
  if (stress && suffix == "mises") return mises;
  if (stress && suffix == "tresca")
    return [](const Tensor6& t) {
      const auto p = principal_values(t);
      return p[2] - p[0];
    };
  return {};
}

struct TensorArrays {
  const std::vector<Tensor6>* element_nodes;
  const std::vector<Tensor6>* nodal_I;
  const std::vector<Tensor6>* nodal_II;
  const std::vector<Tensor6>* centroid;
  const std::vector<Tensor6>* points;
};

std::string held_data(const char* q, const TensorArrays& a) {
  std::vector<std::string> held;
  if (!a.element_nodes->empty())
    held.push_back(std::string("averaging none (") + q + "_element_nodes)");
  if (!a.nodal_I->empty()) held.push_back(std::string("averaging I (") + q + "_nodal_I)");
  if (!a.nodal_II->empty()) held.push_back(std::string("averaging II (") + q + "_nodal_II)");
  if (!a.centroid->empty()) held.push_back(std::string("averaging centroid (") + q + "_centroid)");
  if (!a.points->empty())
    held.push_back(std::string("integration-point ") + q +
                   " (drawn at the points: --ip-values, or \"Values at integration points\")");
  return held.empty() ? std::string("no ") + q + " data at all" : join(held, ", ");
}

ScalarField tensor_field(const Model& model, const IncrementResult& inc, const char* quantity,
                         const TensorArrays& arrays, const TensorFunction& f, Averaging averaging) {
  ScalarField field;
  field.uses_averaging = true;
  const std::vector<Tensor6>* source = nullptr;
  std::size_t expected = 0;
  const char* array_name = "";
  switch (averaging) {
    case Averaging::None:
      source = arrays.element_nodes, expected = model.connectivity.size(),
      array_name = "_element_nodes";
      field.location = FieldLocation::ElementNode;
      break;
    case Averaging::MethodI:
      source = arrays.nodal_I, expected = model.coords.size(), array_name = "_nodal_I";
      field.location = FieldLocation::Node;
      break;
    case Averaging::MethodII:
      source = arrays.nodal_II, expected = model.coords.size(), array_name = "_nodal_II";
      field.location = FieldLocation::Node;
      break;
    case Averaging::Centroid:
      source = arrays.centroid, expected = model.elements.size(), array_name = "_centroid";
      field.location = FieldLocation::Element;
      break;
  }
  if (source->empty())
    throw InputError({}, "step " + std::to_string(inc.step) + " increment " +
                             std::to_string(inc.increment) + " holds no " + quantity + array_name +
                             " for averaging " + averaging_name(averaging) +
                             "; it holds: " + held_data(quantity, arrays));
  if (source->size() != expected)
    throw InputError({}, std::string(quantity) + array_name + " has " +
                             std::to_string(source->size()) + " entries, the model needs " +
                             std::to_string(expected));
  field.values.resize(source->size());
  std::transform(source->begin(), source->end(), field.values.begin(), f);
  return field;
}

// What an increment holds that can be drawn, for messages: "U, RF, S (averaging II), ...".
std::string drawable_data(const Model& model, const IncrementResult& inc) {
  std::vector<std::string> held;
  if (inc.U.size() == model.coords.size() && !inc.U.empty()) held.push_back("U");
  if (inc.RF.size() == model.coords.size() && !inc.RF.empty()) held.push_back("RF");
  if (inc.UR.size() == model.coords.size() && !inc.UR.empty()) held.push_back("UR");
  if (inc.RM.size() == model.coords.size() && !inc.RM.empty()) held.push_back("RM");
  const auto tensors = [&](const char* q, const TensorArrays& a) {
    std::vector<std::string> ways;
    if (!a.element_nodes->empty()) ways.push_back("none");
    if (!a.nodal_I->empty()) ways.push_back("I");
    if (!a.nodal_II->empty()) ways.push_back("II");
    if (!a.centroid->empty()) ways.push_back("centroid");
    if (!ways.empty()) held.push_back(std::string(q) + ".* (averaging " + join(ways, ", ") + ")");
  };
  tensors("S", {&inc.S_element_nodes, &inc.S_nodal_I, &inc.S_nodal_II, &inc.S_centroid, &inc.S});
  tensors("E", {&inc.E_element_nodes, &inc.E_nodal_I, &inc.E_nodal_II, &inc.E_centroid, &inc.E});
  if (!inc.contact.empty()) held.push_back("contact (" + join(contact_field_names(), ", ") + ")");
  if (inc.ERR.size() == model.elements.size() && !inc.ERR.empty()) held.push_back("ERR");
  if (inc.scalar.kind == ScalarFieldResult::Kind::Temperature) held.push_back("NT, RFL, HFL.*");
  if (inc.scalar.kind == ScalarFieldResult::Kind::Potential) held.push_back("EPOT, RECUR, ECD.*");
  return held.empty() ? std::string("nothing drawable") : join(held, ", ");
}

// NT / EPOT, RFL / RECUR (nodal scalars) and HFL / ECD (nodal flux vectors) of a scalar-field
// increment; the heat names need a temperature field, the electric ones a potential.
template <class Unknown>
ScalarField scalar_field_quantity(const Model& model, const IncrementResult& inc,
                                  const std::string& quantity, const std::string& suffix,
                                  const Unknown& unknown) {
  const ScalarFieldResult& s = inc.scalar;
  const bool heat_name = quantity == "NT" || quantity == "RFL" || quantity == "HFL";
  const bool matches = s.kind == (heat_name ? ScalarFieldResult::Kind::Temperature
                                            : ScalarFieldResult::Kind::Potential);
  if (!matches)
    throw InputError({}, "step " + std::to_string(inc.step) + " increment " +
                             std::to_string(inc.increment) + " holds no " + quantity +
                             "; it holds: " + drawable_data(model, inc));
  ScalarField field;
  field.location = FieldLocation::Node;
  if (quantity == "HFL" || quantity == "ECD") {
    const int component = vector_component(suffix);
    if (component < 0) throw unknown();
    if (s.flux_nodal.size() != model.coords.size())
      throw InputError({}, quantity + " holds " + std::to_string(s.flux_nodal.size()) +
                               " nodal values for " + std::to_string(model.coords.size()) +
                               " nodes");
    field.name = quantity + "." + (component == 3 ? "mag" : std::string(1, "xyz"[component]));
    field.values.resize(s.flux_nodal.size());
    for (std::size_t i = 0; i < s.flux_nodal.size(); ++i) {
      const Vec3& v = s.flux_nodal[i];
      field.values[i] =
          component == 3 ? std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) : v[component];
    }
  } else {
    if (!suffix.empty()) throw unknown();
    const bool value = quantity == "NT" || quantity == "EPOT";
    const std::vector<double>& data = value ? s.value : s.reaction;
    if (data.size() != model.coords.size())
      throw InputError({}, quantity + " holds " + std::to_string(data.size()) +
                               " nodal values for " + std::to_string(model.coords.size()) +
                               " nodes");
    field.name = quantity;
    field.values = data;
  }
  field.description = field.name;
  return field;
}

}  // namespace

bool ScalarField::carries(int element, int face, const std::vector<int>& nodes,
                          const Vec3& outward) const {
  const bool all_defined =
      std::all_of(nodes.begin(), nodes.end(), [&](int n) { return defined_at(n); });
  if (!on_surfaces() || !all_defined) return all_defined;
  const auto faces_the_normals = [&] {
    if (normals.empty()) return true;
    Vec3 mean{};
    for (int n : nodes)
      for (int k = 0; k < 3; ++k) mean[k] += normals[n][k];
    const double length = std::sqrt(mean[0] * mean[0] + mean[1] * mean[1] + mean[2] * mean[2]);
    const double along = mean[0] * outward[0] + mean[1] * outward[1] + mean[2] * outward[2];
    return length > 0 && along > 0.5 * length;  // within 60 degrees
  };
  if (!support.empty()) {
    if (std::binary_search(support.begin(), support.end(), std::make_pair(element, face)))
      return true;
    return node_surfaces && faces_the_normals();
  }
  return faces_the_normals();
}

Averaging parse_averaging(const std::string& text) {
  const std::string t = lower(text);
  if (t == "none" || t == "0") return Averaging::None;
  if (t == "i" || t == "1") return Averaging::MethodI;
  if (t == "ii" || t == "2") return Averaging::MethodII;
  if (t == "centroid") return Averaging::Centroid;
  throw InputError({}, "unknown averaging '" + text + "'; use none, I, II or centroid");
}

std::string averaging_name(Averaging averaging) {
  switch (averaging) {
    case Averaging::None:
      return "none";
    case Averaging::MethodI:
      return "I";
    case Averaging::MethodII:
      return "II";
    case Averaging::Centroid:
      return "centroid";
  }
  return "?";
}

ShellFibre parse_shell_fibre(const std::string& name) {
  const std::string t = lower(name);
  if (t == "bottom") return ShellFibre::Bottom;
  if (t == "middle") return ShellFibre::Middle;
  if (t == "top") return ShellFibre::Top;
  throw InputError({}, "unknown shell fibre '" + name + "'; use bottom, middle or top");
}

std::string shell_fibre_name(ShellFibre fibre) {
  switch (fibre) {
    case ShellFibre::Bottom:
      return "bottom";
    case ShellFibre::Middle:
      return "middle";
    case ShellFibre::Top:
      return "top";
  }
  return "?";
}

std::vector<std::string> field_names() {
  std::vector<std::string> names;
  for (const char* v : {"U", "RF", "UR", "RM"})
    for (const char* s : {"mag", "x", "y", "z"}) names.push_back(std::string(v) + "." + s);
  for (const char* q : {"S", "E"}) {
    for (const char* s : {"11", "22", "33", "12", "13", "23", "p1", "p2", "p3"})
      names.push_back(std::string(q) + "." + s);
    if (std::string(q) == "S") {
      names.push_back("S.mises");
      names.push_back("S.tresca");
    }
  }
  for (const std::string& name : contact_field_names()) names.push_back(name);
  for (const char* v : {"SF", "SM"})
    for (const char* s : {"1", "2", "3"}) names.push_back(std::string(v) + "." + s);
  for (const char* s : {"SF.4", "SF.5"}) names.push_back(s);  // shells' Q13, Q23
  names.push_back("ERR");
  for (const char* v : {"NT", "RFL", "EPOT", "RECUR"}) names.push_back(v);
  for (const char* v : {"HFL", "ECD"})
    for (const char* s : {"mag", "x", "y", "z"}) names.push_back(std::string(v) + "." + s);
  return names;
}

namespace {

// Section forces SF or moments SM of beams and shells (docs/results.md): component 1..3 per
// station, drawn over the beams' axes and the shells' surfaces like the fibre tensors.
ScalarField shell_shear_field(const Model& model, const IncrementResult& inc, int component);

ScalarField section_resultant_field(const Model& model, const IncrementResult& inc,
                                    const std::string& quantity, const std::string& suffix) {
  if (quantity == "SF" && (suffix == "4" || suffix == "5"))
    return shell_shear_field(model, inc, suffix == "4" ? 0 : 1);
  const int component = suffix == "1" ? 0 : suffix == "2" ? 1 : suffix == "3" ? 2 : -1;
  if (component < 0)
    throw InputError({}, "unknown field '" + quantity + "." + suffix + "'; " + quantity +
                             " has the components " + quantity + ".1, " + quantity + ".2, " +
                             quantity + ".3" +
                             (quantity == "SF" ? " (shells also SF.4, SF.5)" : ""));
  const std::vector<Vec3>& data = quantity == "SF" ? inc.SF : inc.SM;
  if (data.empty() || inc.station_offset.size() != model.elements.size() + 1)
    throw InputError({}, "step " + std::to_string(inc.step) + " increment " +
                             std::to_string(inc.increment) + " holds no " + quantity +
                             " (section forces and moments of beams and shells); it holds: " +
                             drawable_data(model, inc));
  ScalarField field;
  field.name = quantity + "." + suffix;
  field.description = field.name + (quantity == "SF" ? ", section force" : ", section moment");
  field.location = FieldLocation::Node;
  field.values.assign(model.coords.size(), 0.0);
  field.defined.assign(model.coords.size(), 0);
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    if (inc.station_offset[e + 1] <= inc.station_offset[e]) continue;
    const int* nodes = model.element_nodes(static_cast<int>(e));
    for (int k = 0; k < model.elements[e].node_count; ++k) field.defined[nodes[k]] = 1;
  }
  field.point_offset.assign(inc.station_offset.begin(), inc.station_offset.end());
  for (const Vec3& v : data) field.point_tensors.push_back(Tensor6{v[0], v[1], v[2], 0, 0, 0});
  field.tensor_value = [](const Tensor6& t) { return t[0]; };
  if (component > 0)
    for (Tensor6& t : field.point_tensors) t[0] = t[component];
  field.station_values = true;
  return field;
}

// SF.4 / SF.5: the shells' transverse shear forces Q13, Q23 per station, defined at the nodes
// of shell elements alone.
ScalarField shell_shear_field(const Model& model, const IncrementResult& inc, int component) {
  const std::string name = component == 0 ? "SF.4" : "SF.5";
  if (inc.SFQ.empty() || inc.station_offset.size() != model.elements.size() + 1)
    throw InputError(
        {}, "step " + std::to_string(inc.step) + " increment " + std::to_string(inc.increment) +
                " holds no " + name +
                " (transverse shear forces of shells); it holds: " + drawable_data(model, inc));
  ScalarField field;
  field.name = name;
  field.description =
      name + (component == 0 ? ", transverse shear force Q13" : ", transverse shear force Q23");
  field.location = FieldLocation::Node;
  field.values.assign(model.coords.size(), 0.0);
  field.defined.assign(model.coords.size(), 0);
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const int section = model.elements[e].section;  // shells keep theirs in the results file
    const bool shell = inc.station_offset[e + 1] > inc.station_offset[e] && section >= 0 &&
                       section < static_cast<int>(model.sections.size()) &&
                       model.sections[section].shell;
    if (!shell) continue;
    const int* nodes = model.element_nodes(static_cast<int>(e));
    for (int k = 0; k < model.elements[e].node_count; ++k) field.defined[nodes[k]] = 1;
  }
  field.point_offset.assign(inc.station_offset.begin(), inc.station_offset.end());
  for (const auto& q : inc.SFQ) field.point_tensors.push_back(Tensor6{q[component], 0, 0, 0, 0, 0});
  field.tensor_value = [](const Tensor6& t) { return t[0]; };
  field.station_values = true;
  return field;
}

}  // namespace

ScalarField evaluate_field(const Model& model, const IncrementResult& inc, const std::string& name,
                           Averaging averaging, const std::string& contact_pair) {
  const std::size_t dot = name.find('.');
  std::string quantity = name.substr(0, dot);
  for (char& c : quantity) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  const std::string suffix = dot == std::string::npos ? "" : lower(name.substr(dot + 1));
  const auto unknown = [&]() {
    return InputError({}, "unknown field '" + name + "'; fields: " + join(field_names(), ", "));
  };

  // Contact output (DESIGN "Data flow": pressure, shear, slip, gap, status) at the slave nodes.
  if (is_contact_quantity(quantity))
    return evaluate_contact_field(model, inc, quantity, suffix, drawable_data(model, inc),
                                  contact_pair);

  if (quantity == "U" || quantity == "RF" || quantity == "UR" || quantity == "RM") {
    const int component = vector_component(suffix);
    if (component < 0) throw unknown();
    const std::vector<Vec3>& data = quantity == "U"    ? inc.U
                                    : quantity == "RF" ? inc.RF
                                    : quantity == "UR" ? inc.UR
                                                       : inc.RM;
    if (data.empty() && (quantity == "UR" || quantity == "RM"))
      throw InputError({}, "step " + std::to_string(inc.step) + " increment " +
                               std::to_string(inc.increment) + " holds no " + quantity +
                               " (rotations exist in models with beam elements); it holds: " +
                               drawable_data(model, inc));
    if (data.size() != model.coords.size())
      throw InputError({}, "step " + std::to_string(inc.step) + " increment " +
                               std::to_string(inc.increment) + " holds " +
                               std::to_string(data.size()) + " " + quantity + " values for " +
                               std::to_string(model.coords.size()) + " nodes");
    ScalarField field;
    field.name = quantity + "." + (component == 3 ? "mag" : std::string(1, "xyz"[component]));
    field.description = field.name;
    field.location = FieldLocation::Node;
    field.values.resize(data.size());
    for (std::size_t i = 0; i < data.size(); ++i) {
      const Vec3& v = data[i];
      field.values[i] =
          component == 3 ? std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) : v[component];
    }
    return field;
  }
  // Steady heat / electric potential (docs/solver.md): the nodal field, its reaction flows, and
  // the nodal-averaged flux (magnitude or component).
  if (quantity == "NT" || quantity == "EPOT" || quantity == "RFL" || quantity == "RECUR" ||
      quantity == "HFL" || quantity == "ECD")
    return scalar_field_quantity(model, inc, quantity, suffix, unknown);
  // The stress error estimate of each element (*EL FILE, ERR; docs/results.md), drawn flat.
  if (quantity == "ERR") {
    if (!suffix.empty()) throw unknown();
    if (inc.ERR.size() != model.elements.size() || inc.ERR.empty())
      throw InputError({}, "step " + std::to_string(inc.step) + " increment " +
                               std::to_string(inc.increment) +
                               " holds no ERR (ask for it with *EL FILE, S or ERR); it holds: " +
                               drawable_data(model, inc));
    ScalarField field;
    field.name = "ERR";
    field.description = "ERR, stress error estimate (%)";
    field.location = FieldLocation::Element;
    field.values = inc.ERR;
    return field;
  }
  if (quantity == "SF" || quantity == "SM")
    return section_resultant_field(model, inc, quantity, suffix);
  if (quantity == "S" || quantity == "E") {
    const bool stress = quantity == "S";
    const TensorFunction f = tensor_function(suffix, stress);
    if (!f) throw unknown();
    const TensorArrays arrays = stress ? TensorArrays{&inc.S_element_nodes, &inc.S_nodal_I,
                                                      &inc.S_nodal_II, &inc.S_centroid, &inc.S}
                                       : TensorArrays{&inc.E_element_nodes, &inc.E_nodal_I,
                                                      &inc.E_nodal_II, &inc.E_centroid, &inc.E};
    ScalarField field = tensor_field(model, inc, stress ? "S" : "E", arrays, f, averaging);
    // Beams and shells are coloured from their fibre tensors (beam_geometry.hpp,
    // shell_geometry.hpp).
    const bool fibres =
        std::any_of(model.sections.begin(), model.sections.end(),
                    [](const Section& s) { return s.beam.has_value() || s.shell.has_value(); });
    const std::vector<Tensor6>& points = stress ? inc.S : inc.E;
    if (fibres && !points.empty() && inc.ip_offset.size() == model.elements.size() + 1) {
      field.point_offset = inc.ip_offset;
      field.point_tensors = points;
      field.tensor_value = f;
    }
    field.name = quantity + "." + suffix;
    if (suffix == "max_principal") field.name = quantity + ".p1";
    if (suffix == "mid_principal") field.name = quantity + ".p2";
    if (suffix == "min_principal") field.name = quantity + ".p3";
    field.description = field.name + ", averaging " + averaging_name(averaging);
    return field;
  }
  throw unknown();
}

ColorScale color_scale_for(const ScalarField& field, const std::array<double, 2>& range, int bands,
                           bool smooth) {
  if (field.categories.empty()) return ColorScale{range[0], range[1], bands, smooth};
  // Category k sits in the middle of band k: value k maps to (k + 0.5) / count.
  ColorScale scale;
  const int count = static_cast<int>(field.categories.size());
  scale.min = -0.5;
  scale.max = count - 0.5;
  scale.bands = count;
  scale.smooth = false;
  for (int k = 0; k < count; ++k) scale.palette.push_back(contact_status_color(k));
  scale.labels = field.categories;
  return scale;
}

PointField evaluate_point_field(const Model& model, const IncrementResult& inc,
                                const std::string& name) {
  const std::size_t dot = name.find('.');
  const std::string quantity = to_upper(name.substr(0, dot));
  const std::string suffix = dot == std::string::npos ? "" : lower(name.substr(dot + 1));
  const auto refuse = [&](const std::string& why) {
    return InputError({}, "field '" + name + "' " + why +
                              "; values at the integration points: S.* and E.* (components, "
                              "mises, tresca, p1..p3), HFL.* and ECD.*");
  };
  PointField field;
  field.offset = inc.ip_offset;
  if (quantity == "S" || quantity == "E") {
    const TensorFunction f = tensor_function(suffix, quantity == "S");
    if (!f) throw refuse("is unknown");
    const std::vector<Tensor6>& data = quantity == "S" ? inc.S : inc.E;
    if (data.empty()) throw refuse("has no integration-point values in this increment");
    field.name = quantity + "." + suffix;
    field.values.resize(data.size());
    std::transform(data.begin(), data.end(), field.values.begin(), f);
  } else if (quantity == "HFL" || quantity == "ECD") {
    const int component = vector_component(suffix);
    const bool heat = quantity == "HFL";
    if (component < 0) throw refuse("is unknown");
    if (inc.scalar.kind !=
            (heat ? ScalarFieldResult::Kind::Temperature : ScalarFieldResult::Kind::Potential) ||
        inc.scalar.flux.empty())
      throw refuse("has no integration-point values in this increment");
    field.name = quantity + "." + (component == 3 ? "mag" : std::string(1, "xyz"[component]));
    for (const Vec3& v : inc.scalar.flux)
      field.values.push_back(component == 3 ? std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
                                            : v[component]);
  } else {
    throw refuse("has no values at the integration points");
  }
  if (field.offset.size() != model.elements.size() + 1 ||
      field.offset.back() != static_cast<int>(field.values.size()))
    throw InputError({}, "the integration-point layout (ip_offset) of step " +
                             std::to_string(inc.step) + " increment " +
                             std::to_string(inc.increment) + " does not match the model's " +
                             std::to_string(model.elements.size()) + " elements");
  return field;
}

double max_displacement(const IncrementResult& inc, const std::vector<int>& nodes) {
  double largest = 0.0;
  const auto visit = [&](const Vec3& u) {
    largest = std::max(largest, std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]));
  };
  if (nodes.empty()) {
    for (const Vec3& u : inc.U) visit(u);
  } else {
    for (int n : nodes)
      if (n >= 0 && static_cast<std::size_t>(n) < inc.U.size()) visit(inc.U[n]);
  }
  return largest;
}

}  // namespace styk::render
