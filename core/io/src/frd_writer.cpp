// The .frd's ASCII layout: fixed columns (the format's Fortran edit descriptors), node ids in
// ten columns ("long" format 1), values as E12.5.
#include "styk/io/frd_writer.hpp"

#include <cerrno>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "frd_elements.hpp"
#include "styk/io/temp_file.hpp"

namespace styk {
namespace {

// One fixed-width record at a time; values below the E12.5 range are written as 0 (a three-digit
// exponent would shift every column after it).
class FrdStream {
 public:
  explicit FrdStream(std::ostream& out) : out_(out) {}

  void text(const char* format, ...) __attribute__((format(printf, 2, 3))) {
    char buffer[256];
    va_list args;
    va_start(args, format);
    std::vsnprintf(buffer, sizeof buffer, format, args);
    va_end(args);
    out_ << buffer;
  }
  void value(double x) {
    if (std::fabs(x) < 1e-99) x = 0.0;
    text("%12.5E", x);
  }
  void end_line() { out_ << '\n'; }

 private:
  std::ostream& out_;
};

void write_header(FrdStream& out, const Model& model, const std::string& job) {
  out.text("    1C%s", job.c_str());
  out.end_line();
  if (!model.heading.empty()) {
    out.text("    1U%s", model.heading.substr(0, model.heading.find('\n')).c_str());
    out.end_line();
  }
  out.text("    1UPGM               Styk");
  out.end_line();
}

void write_nodes(FrdStream& out, const Model& model) {
  out.text("    2C%18s%12d%37s%1d", "", model.node_count(), "", 1);
  out.end_line();
  for (int n = 0; n < model.node_count(); ++n) {
    out.text(" -1%10lld", static_cast<long long>(model.node_ids[n]));
    for (double c : model.coords[n]) out.value(c);
    out.end_line();
  }
  out.text(" -3");
  out.end_line();
}

int material_number(const Model& model, const Element& element) {
  if (element.section < 0 || element.section >= static_cast<int>(model.sections.size())) return 1;
  return model.sections[element.section].material_index + 1;
}

frd::FrdCell cell_of(const Model& model, const ElementRegistry& registry, int e) {
  const Element& element = model.elements[e];
  const TElement* formulation = registry.find(element.type);
  if (formulation == nullptr)
    throw InputError(element.where, "element " + std::to_string(element.id) + " has type " +
                                        element.type +
                                        ", which no loaded formulation describes: it cannot be "
                                        "written to the .frd");
  frd::FrdCell cell = frd::frd_cell(*formulation);
  for (int k : cell.nodes)
    if (k < 0 || k >= element.node_count) cell.type = 0;
  if (cell.type == 0)
    throw InputError(element.where, "element " + std::to_string(element.id) + " (" + element.type +
                                        ") has no .frd element (its VTK cell, "
                                        "TElement::vtk_cell(), names none): it cannot be written");
  return cell;
}

void write_elements(FrdStream& out, const Model& model, const ElementRegistry& registry) {
  out.text("    3C%18s%12d%37s%1d", "", model.element_count(), "", 1);
  out.end_line();
  for (int e = 0; e < model.element_count(); ++e) {
    const Element& element = model.elements[e];
    const frd::FrdCell cell = cell_of(model, registry, e);
    out.text(" -1%10lld%5d%5d%5d", static_cast<long long>(element.id), cell.type, 0,
             material_number(model, element));
    out.end_line();
    const int* nodes = model.element_nodes(e);
    for (std::size_t i = 0; i < cell.nodes.size(); ++i) {
      if (i % 10 == 0) {
        if (i > 0) out.end_line();
        out.text(" -2");
      }
      out.text("%10lld", static_cast<long long>(model.node_ids[nodes[cell.nodes[i]]]));
    }
    out.end_line();
  }
  out.text(" -3");
  out.end_line();
}

struct BlockLayout {
  const char* name;
  int type;  // 1 scalar, 2 vector, 4 tensor
  std::vector<const char*> components;
};

BlockLayout layout_of(FrdField field) {
  switch (field) {
    case FrdField::Displacement:
      return {"DISP", 2, {"D1", "D2", "D3"}};
    case FrdField::Force:
      return {"FORC", 2, {"F1", "F2", "F3"}};
    case FrdField::Stress:
      return {"STRESS", 4, {"SXX", "SYY", "SZZ", "SXY", "SYZ", "SZX"}};
    case FrdField::Strain:
      return {"TOSTRAIN", 4, {"EXX", "EYY", "EZZ", "EXY", "EYZ", "EZX"}};
    case FrdField::Temperature:
      return {"NDTEMP", 1, {"T"}};
    case FrdField::HeatFlux:
      return {"FLUX", 2, {"F1", "F2", "F3"}};
  }
  return {"", 0, {}};
}

// The values of `field` at node n, in the block's component order (tensors: xx, yy, zz, xy, yz,
// zx; Styk stores 11, 22, 33, 12, 13, 23).
std::vector<double> values_at(const IncrementResult& inc, FrdField field, int n) {
  auto tensor = [](const Tensor6& t) {
    return std::vector<double>{t[0], t[1], t[2], t[3], t[5], t[4]};
  };
  auto vector = [](const Vec3& v) { return std::vector<double>{v[0], v[1], v[2]}; };
  switch (field) {
    case FrdField::Displacement:
      return vector(inc.U.at(n));
    case FrdField::Force:
      return vector(inc.RF.at(n));
    case FrdField::Stress:
      return tensor(inc.S_nodal_I.at(n));
    case FrdField::Strain:
      return tensor(inc.E_nodal_I.at(n));
    case FrdField::Temperature:
      return {inc.scalar.value.at(n)};
    case FrdField::HeatFlux:
      return vector(inc.scalar.flux_nodal.at(n));
  }
  return {};
}

void write_block(FrdStream& out, const Model& model, const IncrementResult& inc,
                 const FrdFieldOutput& field, int block, int output_increment) {
  const BlockLayout layout = layout_of(field.field);
  const int count = field.all_nodes ? model.node_count() : static_cast<int>(field.nodes.size());
  out.text("    1PSTEP%26d%12d%12d", block, inc.increment, inc.step);
  out.end_line();
  out.text("  100CL%5d", 100 + output_increment);
  out.value(inc.total_time);
  out.text("%12d%20s%2d%5d%10s%2d", count, "", 0, output_increment, "", 1);
  out.end_line();
  out.text(" -4  %-8s%5d%5d", layout.name, static_cast<int>(layout.components.size()), 1);
  out.end_line();
  static const int kTensorIndex[6][2] = {{1, 1}, {2, 2}, {3, 3}, {1, 2}, {2, 3}, {3, 1}};
  for (std::size_t c = 0; c < layout.components.size(); ++c) {
    const int i = layout.type == 4 ? kTensorIndex[c][0] : layout.type == 2 ? int(c) + 1 : 0;
    const int j = layout.type == 4 ? kTensorIndex[c][1] : 0;
    out.text(" -5  %-8s%5d%5d%5d%5d", layout.components[c], 1, layout.type, i, j);
    out.end_line();
  }
  if (layout.type == 2) {  // a vector's magnitude, which the post-processor computes
    out.text(" -5  %-8s%5d%5d%5d%5d%5dALL", "ALL", 1, 2, 0, 0, 1);
    out.end_line();
  }
  for (int k = 0; k < count; ++k) {
    const int n = field.all_nodes ? k : field.nodes[k];
    out.text(" -1%10lld", static_cast<long long>(model.node_ids[n]));
    for (double x : values_at(inc, field.field, n)) out.value(x);
    out.end_line();
  }
  out.text(" -3");
  out.end_line();
}

void check_sizes(const Model& model, const FrdPlan& plan) {
  const std::size_t nodes = static_cast<std::size_t>(model.node_count());
  for (const FrdIncrement& inc : plan.increments)
    for (const FrdFieldOutput& field : inc.fields) {
      bool fits = true;
      switch (field.field) {
        case FrdField::Displacement:
          fits = inc.increment->U.size() == nodes;
          break;
        case FrdField::Force:
          fits = inc.increment->RF.size() == nodes;
          break;
        case FrdField::Stress:
          fits = inc.increment->S_nodal_I.size() == nodes;
          break;
        case FrdField::Strain:
          fits = inc.increment->E_nodal_I.size() == nodes;
          break;
        case FrdField::Temperature:
          fits = inc.increment->scalar.value.size() == nodes;
          break;
        case FrdField::HeatFlux:
          fits = inc.increment->scalar.flux_nodal.size() == nodes;
          break;
      }
      for (int n : field.nodes) fits = fits && n >= 0 && n < model.node_count();
      if (!fits)
        throw std::runtime_error(".frd output: the results of step " +
                                 std::to_string(inc.increment->step) +
                                 " do not match the model's " + std::to_string(nodes) + " nodes");
    }
}

}  // namespace

void write_frd(const std::string& path, const Model& model, const ElementRegistry& registry,
               const FrdPlan& plan, const std::string& job) {
  check_sizes(model, plan);
  io::TempFile temp(path);
  std::ofstream file(temp.temp_path(), std::ios::out | std::ios::trunc);
  if (!file) throw std::runtime_error("cannot write " + temp.temp_path());
  FrdStream out(file);
  write_header(out, model, job);
  write_nodes(out, model);
  write_elements(out, model, registry);
  int block = 0;
  int output_increment = 0;
  for (const FrdIncrement& inc : plan.increments) {
    ++output_increment;
    for (const FrdFieldOutput& field : inc.fields)
      write_block(out, model, *inc.increment, field, ++block, output_increment);
  }
  out.text(" 9999");
  out.end_line();
  file.flush();
  file.close();
  if (!file) {
    temp.throw_if_out_of_space("cannot write " + path, errno);
    throw std::runtime_error("cannot write " + path);
  }
  temp.commit();
}

}  // namespace styk
