// The .dat report in CalculiX's layout. Each block is: an empty line, the header
// " <what> for set <SET> and time <E14.7>", an empty line, then one row per node (I10 then
// 1P,3(1X,E13.6)) or per integration point (I10,1X,I3 then 1P,6(1X,E13.6)); a force total is
// (6X,1P,3(1X,E13.6)). Verified against ccx 2.20 output (tests/unit/io/dat_writer_test.cpp).
#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dat_contact.hpp"
#include "dat_extras.hpp"
#include "dat_scalar.hpp"
#include "fortran_format.hpp"
#include "styk/core/local_axes.hpp"
#include "styk/core/output_requests.hpp"
#include "styk/io/dat_writer.hpp"

namespace styk {

namespace {

constexpr const char* kWholeModel = "ALL";

std::string increment_label(const IncrementResult& inc) {
  return "step " + std::to_string(inc.step) + ", increment " + std::to_string(inc.increment);
}

class DatPrinter {
 public:
  DatPrinter(std::ostream& out, const Model& model) : out_(out), model_(model) {}

  // Prints the requests in effect in the increment's step (CalculiX: a step without requests of
  // a kind repeats the previous step's), when FREQUENCY says the increment is due; `last` when
  // it ends its step.
  void print(const IncrementResult& inc, bool last) {
    if (inc.step < 1 || inc.step > static_cast<int>(model_.steps.size()))
      throw std::runtime_error("results of " + increment_label(inc) + " name step " +
                               std::to_string(inc.step) + " but the model has " +
                               std::to_string(model_.steps.size()) + " steps");
    const std::size_t step = static_cast<std::size_t>(inc.step - 1);
    if (!output_due(model_, step, inc.increment, last)) return;
    for (const OutputRequest* each : effective_outputs(model_, step)) {
      const OutputRequest& request = *each;
      const bool printed = request.kind == OutputRequest::Kind::NodePrint ||
                           request.kind == OutputRequest::Kind::ElementPrint;
      if (printed && inc.scalar.kind != ScalarFieldResult::Kind::None)
        io::print_scalar(out_, model_, request, inc);  // heat / electric steps
      else if (request.kind == OutputRequest::Kind::NodePrint)
        print_nodes(request, inc);
      else if (request.kind == OutputRequest::Kind::ElementPrint)
        print_elements(request, inc);
      else if (request.kind == OutputRequest::Kind::ContactPrint)
        io::print_contact(out_, model_, request, inc);
      else if (request.kind == OutputRequest::Kind::SectionPrint)
        io::print_section(out_, request, inc);
    }
  }

 private:
  // The local axes of node n when a *TRANSFORM names it, else nullptr (built on first use).
  const Eigen::Matrix3d* local_axes(int n) {
    if (!transforms_ready_) {
      transforms_ready_ = true;
      axes_of_node_.assign(model_.coords.size(), -1);
      for (const Transform& transform : model_.transforms) {
        const NodeSet* set = model_.find_nset(transform.nset);
        if (set == nullptr) continue;  // the solver refuses such a deck before anything is printed
        for (int node : set->nodes) {
          Eigen::Matrix3d R;
          if (!local_axes_at(transform.axes, model_.coords[node], R)) continue;
          axes_of_node_[node] = static_cast<int>(axes_.size());
          axes_.push_back(R);
        }
      }
    }
    const int k = axes_of_node_[n];
    return k < 0 ? nullptr : &axes_[k];
  }

  void header(const std::string& what, const std::string& set, double time) {
    out_ << "\n " << what << " for set " << set << " and time " << io::fortran_e14_7(time)
         << "\n\n";
  }

  // The nodal vector fields *NODE PRINT takes: U and RF as ccx prints them, UR and RM (nodes
  // with rotations, beams) in the same layout.
  struct NodalVector {
    const char* name;
    const char* header;
    const char* total_header;  // nullptr: no TOTALS line (ccx sums forces only)
    const std::vector<Vec3> IncrementResult::*member;
  };
  static const NodalVector* nodal_vector(const std::string& var) {
    static const NodalVector kVectors[] = {
        {"U", "displacements (vx,vy,vz)", nullptr, &IncrementResult::U},
        {"RF", "forces (fx,fy,fz)", "total force (fx,fy,fz)", &IncrementResult::RF},
        {"UR", "rotations (rx,ry,rz)", nullptr, &IncrementResult::UR},
        {"RM", "moments (mx,my,mz)", "total moment (mx,my,mz)", &IncrementResult::RM},
    };
    for (const NodalVector& v : kVectors)
      if (var == v.name) return &v;
    return nullptr;
  }

  void print_nodes(const OutputRequest& request, const IncrementResult& inc) {
    const std::vector<int> nodes = node_rows(request);
    const std::string set = request.set.empty() ? kWholeModel : request.set;
    for (const std::string& var : request.vars) {
      const NodalVector* vector = nodal_vector(var);
      if (vector == nullptr)
        throw InputError(request.where, "*NODE PRINT: variable " + var +
                                            " cannot be printed to the .dat file (Styk prints U, "
                                            "RF, UR and RM)");
      const std::vector<Vec3>& field = inc.*vector->member;
      if (field.size() != model_.node_ids.size()) {
        if (var == "UR" || var == "RM")
          throw InputError(request.where, "*NODE PRINT: " + var +
                                              " needs nodes with rotations (beam elements); "
                                              "the model has none");
        throw std::runtime_error("*NODE PRINT asks for " + var + " but the results of " +
                                 increment_label(inc) + " hold no " + var + " for every node");
      }
      // TOTALS=ONLY: the sum alone (ccx prints totals of forces only).
      if (!request.totals_only) header(vector->header, set, inc.total_time);
      // GLOBAL=YES: global components everywhere; otherwise a *TRANSFORM node's local ones.
      const bool global = request.global.value_or(false);
      Vec3 total{0.0, 0.0, 0.0};  // global components, as ccx sums them
      for (const int n : nodes) {
        if (request.totals_only) {
          for (int k = 0; k < 3; ++k) total[k] += field[n][k];
          continue;
        }
        write_id(model_.node_ids[n]);
        const Eigen::Matrix3d* R = global ? nullptr : local_axes(n);
        Vec3 shown = field[n];
        // A *TRANSFORM node: local components (rotations turn like displacements), marked " L"
        // as ccx does.
        if (R != nullptr)
          for (int k = 0; k < 3; ++k)
            shown[k] = R->col(k).dot(Eigen::Vector3d(field[n][0], field[n][1], field[n][2]));
        for (int k = 0; k < 3; ++k) {
          out_ << ' ' << io::fortran_e13_6(shown[k]);
          total[k] += field[n][k];
        }
        out_ << (R != nullptr ? " L\n" : "\n");
      }
      // ccx prints totals for forces only, whatever TOTALS= says for other variables.
      if (request.totals && vector->total_header != nullptr) {
        header(vector->total_header, set, inc.total_time);
        out_ << "      ";
        for (int k = 0; k < 3; ++k) out_ << ' ' << io::fortran_e13_6(total[k]);
        out_ << '\n';
      }
    }
  }

  void print_elements(const OutputRequest& request, const IncrementResult& inc) {
    const std::vector<int> elements = element_rows(request);
    const std::string set = request.set.empty() ? kWholeModel : request.set;
    for (const std::string& var : request.vars) {
      if (var == "SF" || var == "SM") {
        print_stations(request, var, set, elements, inc);
        continue;
      }
      if (io::is_element_extra(var)) {
        io::print_element_extra(out_, model_, request, var, set, elements, inc);
        continue;
      }
      if (var != "S" && var != "E")
        throw InputError(request.where, "*EL PRINT: variable " + var +
                                            " cannot be printed to the .dat file (Styk prints S, "
                                            "E, SF, SM, ENER, ELSE, EVOL and CENT)");
      if (request.totals_only) continue;  // S and E have no totals
      const bool stress = var == "S";
      if (request.position == OutputRequest::Position::Centroidal) {
        print_centroids(var, set, elements, stress ? inc.S_centroid : inc.E_centroid, inc);
        continue;
      }
      if (request.position == OutputRequest::Position::AveragedAtNodes) {
        print_averaged(var, set, elements, stress ? inc.S_nodal_I : inc.E_nodal_I, inc);
        continue;
      }
      const std::vector<Tensor6>& field = stress ? inc.S : inc.E;
      if (inc.ip_offset.size() != model_.elements.size() + 1 ||
          field.size() != static_cast<std::size_t>(inc.ip_offset.back()))
        throw std::runtime_error("*EL PRINT asks for " + var + " but the results of " +
                                 increment_label(inc) + " hold no " + var +
                                 " at the integration points");
      header(stress ? "stresses (elem, integ.pnt.,sxx,syy,szz,sxy,sxz,syz)"
                    : "strains (elem, integ.pnt.,exx,eyy,ezz,exy,exz,eyz)",
             set, inc.total_time);
      // GLOBAL=NO (the default): an element with an *ORIENTATION prints in its material axes,
      // the orientation's name (10 characters, padded to 20) ending the row, as ccx does.
      const bool global = request.global.value_or(false);
      for (const int e : elements) {
        const Orientation* orientation = global ? nullptr : orientation_of(e);
        for (int p = inc.ip_offset[e]; p < inc.ip_offset[e + 1]; ++p) {
          write_id(model_.elements[e].id);
          char point[16];
          std::snprintf(point, sizeof point, " %3d", p - inc.ip_offset[e] + 1);
          out_ << point;
          const Tensor6 shown =
              orientation ? in_material_axes(*orientation, field[p], inc, p) : field[p];
          for (const double v : shown) out_ << ' ' << io::fortran_e13_6(v);
          if (orientation) {
            char name[32];
            std::snprintf(name, sizeof name, " %-20s", orientation->name.substr(0, 10).c_str());
            out_ << name;
          }
          out_ << '\n';
        }
      }
    }
  }

  // SF / SM: the section forces or moments of the set's beam elements at their stations (the
  // layout of the stress block with three values; elements without stations print nothing).
  void print_stations(const OutputRequest& request, const std::string& var, const std::string& set,
                      const std::vector<int>& elements, const IncrementResult& inc) {
    const bool forces = var == "SF";
    const std::vector<Vec3>& field = forces ? inc.SF : inc.SM;
    if (inc.station_offset.size() != model_.elements.size() + 1 ||
        field.size() != static_cast<std::size_t>(inc.station_offset.back()))
      throw InputError(request.where, "*EL PRINT: " + var +
                                          " (section forces and moments) needs beam elements; "
                                          "the results hold none");
    header(forces ? "section forces (elem, integ.pnt.,sf1,sf2,sf3)"
                  : "section moments (elem, integ.pnt.,sm1,sm2,sm3)",
           set, inc.total_time);
    print_station_rows(elements, inc, field);
    if (forces) print_transverse_shear(set, elements, inc);
  }

  // One row per station of `elements`: element id, 1-based station, the station's values.
  template <typename Row>
  void print_station_rows(const std::vector<int>& elements, const IncrementResult& inc,
                          const std::vector<Row>& field) {
    for (const int e : elements)
      for (int p = inc.station_offset[e]; p < inc.station_offset[e + 1]; ++p) {
        write_id(model_.elements[e].id);
        char point[16];
        std::snprintf(point, sizeof point, " %3d", p - inc.station_offset[e] + 1);
        out_ << point;
        for (const double v : field[p]) out_ << ' ' << io::fortran_e13_6(v);
        out_ << '\n';
      }
  }

  // The shells' transverse shear forces Q13, Q23 (Abaqus' SF4, SF5; Styk's block: ccx prints no
  // section forces) after the SF block, for the set's shell elements, in the SF block's layout
  // with two values.
  void print_transverse_shear(const std::string& set, const std::vector<int>& elements,
                              const IncrementResult& inc) {
    std::vector<int> shells;
    for (const int e : elements) {
      const int section = model_.elements[e].section;
      if (section >= 0 && section < static_cast<int>(model_.sections.size()) &&
          model_.sections[section].shell && inc.station_offset[e + 1] > inc.station_offset[e])
        shells.push_back(e);
    }
    if (shells.empty() || inc.SFQ.size() != static_cast<std::size_t>(inc.station_offset.back()))
      return;
    header("transverse shear forces (elem, integ.pnt.,sf4,sf5)", set, inc.total_time);
    print_station_rows(shells, inc, inc.SFQ);
  }

  // POSITION=CENTROIDAL: one row per element, no integration-point column.
  void print_centroids(const std::string& var, const std::string& set,
                       const std::vector<int>& elements, const std::vector<Tensor6>& field,
                       const IncrementResult& inc) {
    if (field.size() != model_.elements.size())
      throw std::runtime_error("*EL PRINT, POSITION=CENTROIDAL asks for " + var +
                               " but the results of " + increment_label(inc) +
                               " hold no centroid values of " + var);
    header(var == "S" ? "stresses at centroids (elem,sxx,syy,szz,sxy,sxz,syz)"
                      : "strains at centroids (elem,exx,eyy,ezz,exy,exz,eyz)",
           set, inc.total_time);
    for (const int e : elements) write_tensor_row(model_.elements[e].id, field[e]);
  }

  // POSITION=AVERAGED AT NODES: nodal method I (SPEC §5) at every node of the set's elements,
  // averaged over all elements sharing the node (not only those of the set).
  void print_averaged(const std::string& var, const std::string& set,
                      const std::vector<int>& elements, const std::vector<Tensor6>& field,
                      const IncrementResult& inc) {
    if (field.size() != model_.node_ids.size())
      throw std::runtime_error("*EL PRINT, POSITION=AVERAGED AT NODES asks for " + var +
                               " but the results of " + increment_label(inc) +
                               " hold no nodal averages of " + var);
    std::vector<int> nodes;
    for (const int e : elements) {
      const int* first = model_.element_nodes(e);
      nodes.insert(nodes.end(), first, first + model_.elements[e].node_count);
    }
    std::sort(nodes.begin(), nodes.end(),
              [&](int a, int b) { return model_.node_ids[a] < model_.node_ids[b]; });
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    header(var == "S" ? "stresses averaged at nodes (node,sxx,syy,szz,sxy,sxz,syz)"
                      : "strains averaged at nodes (node,exx,eyy,ezz,exy,exz,eyz)",
           set, inc.total_time);
    for (const int n : nodes) write_tensor_row(model_.node_ids[n], field[n]);
  }

  // The *ORIENTATION of element e's section, or nullptr.
  const Orientation* orientation_of(int e) const {
    const int section = model_.elements[e].section;
    if (section < 0 || section >= static_cast<int>(model_.sections.size())) return nullptr;
    const auto it = model_.orientations.find(model_.sections[section].orientation);
    return it == model_.orientations.end() ? nullptr : &it->second;
  }

  // A stress or strain tensor in the orientation's axes at integration point p.
  Tensor6 in_material_axes(const Orientation& orientation, const Tensor6& t,
                           const IncrementResult& inc, int p) const {
    const Vec3 at = p < static_cast<int>(inc.ip_position.size()) ? inc.ip_position[p] : Vec3{};
    Eigen::Matrix3d R;
    if (!local_axes_at(orientation.axes, at, R))
      throw std::runtime_error("the material axes of orientation " + orientation.name +
                               " are undefined at an integration point");
    Eigen::Matrix3d g;
    g << t[0], t[3], t[4], t[3], t[1], t[5], t[4], t[5], t[2];
    const Eigen::Matrix3d l = R.transpose() * g * R;
    return {l(0, 0), l(1, 1), l(2, 2), l(0, 1), l(0, 2), l(1, 2)};
  }

  void write_tensor_row(Id id, const Tensor6& values) {
    write_id(id);
    for (const double v : values) out_ << ' ' << io::fortran_e13_6(v);
    out_ << '\n';
  }

  void write_id(Id id) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%10" PRId64, static_cast<std::int64_t>(id));
    out_ << buffer;
  }

  // ccx keeps its sets sorted by number, so its rows come in id order; so do ours.
  std::vector<int> node_rows(const OutputRequest& request) const {
    std::vector<int> nodes;
    if (request.set.empty()) {
      nodes.resize(model_.node_ids.size());
      for (std::size_t i = 0; i < nodes.size(); ++i) nodes[i] = static_cast<int>(i);
    } else {
      const NodeSet* set = model_.find_nset(request.set);
      if (set == nullptr)
        throw InputError(request.where, "*NODE PRINT: node set " + request.set + " is not defined");
      nodes = set->nodes;
    }
    std::sort(nodes.begin(), nodes.end(),
              [&](int a, int b) { return model_.node_ids[a] < model_.node_ids[b]; });
    return nodes;
  }

  std::vector<int> element_rows(const OutputRequest& request) const {
    std::vector<int> elements;
    if (request.set.empty()) {
      elements.resize(model_.elements.size());
      for (std::size_t i = 0; i < elements.size(); ++i) elements[i] = static_cast<int>(i);
    } else {
      const ElementSet* set = model_.find_elset(request.set);
      if (set == nullptr)
        throw InputError(request.where,
                         "*EL PRINT: element set " + request.set + " is not defined");
      elements = set->elements;
    }
    std::sort(elements.begin(), elements.end(),
              [&](int a, int b) { return model_.elements[a].id < model_.elements[b].id; });
    return elements;
  }

  std::ostream& out_;
  const Model& model_;
  bool transforms_ready_ = false;
  std::vector<int> axes_of_node_;  // index into axes_, -1: global
  std::vector<Eigen::Matrix3d> axes_;
};

}  // namespace

void write_dat(std::ostream& out, const Model& model, const Results& results) {
  DatPrinter printer(out, model);
  const std::vector<IncrementResult>& increments = results.increments;
  for (std::size_t i = 0; i < increments.size(); ++i) {
    const bool last = i + 1 == increments.size() || increments[i + 1].step != increments[i].step;
    printer.print(increments[i], last);
  }
}

}  // namespace styk
