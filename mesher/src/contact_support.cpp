#include "contact_support.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <stdexcept>

#include "builder_support.hpp"
#include "styk/mesher/convert.hpp"
#include "styk/mesher/hex_topology.hpp"
#include "styk/mesher/interface.hpp"

namespace styk::mesher::detail {

Model contact_model(const Mesh& mesh, const std::string& heading,
                    const std::vector<BodyMaterial>& bodies) {
  Model model = to_model(mesh);
  model.heading = heading;
  for (const BodyMaterial& body : bodies) {
    Material material;
    material.name = body.material;
    material.young = body.young;
    material.poisson = body.poisson;
    material.expansion = body.expansion;
    model.materials.push_back(material);
    Section section;
    section.elset = body.elset;
    section.material = body.material;
    section.material_index = static_cast<int>(model.materials.size()) - 1;
    model.sections.push_back(section);
    const int index = static_cast<int>(model.sections.size()) - 1;
    for (int e : mesh.element_sets.at(body.elset)) {
      if (model.elements[e].section >= 0)
        throw std::logic_error("contact_model: element " + std::to_string(e + 1) +
                               " is in two bodies");
      model.elements[e].section = index;
    }
  }
  for (const Element& e : model.elements)
    if (e.section < 0)
      throw std::logic_error("contact_model: element " + std::to_string(e.id) + " has no body");
  return model;
}

void convert_contact_layers(Mesh& mesh, const ElementRegistry& registry, const std::string& family,
                            const std::vector<std::string>& contact_surfaces) {
  const TElement* element = registry.find(family);
  if (!element || !element->conversion()) return;
  if (!converts_a_layer(registry, family)) {
    convert_elements(mesh, registry, family);
    return;
  }
  // The conversion rewrites the surface it converts (a closed C3D28 layer may be larger than the
  // contact face); a working copy keeps the named surface to its own faces, which follow the
  // renumbering like every surface.
  const std::string work = "__LAYER";
  for (const std::string& name : contact_surfaces) {
    mesh.surfaces[work] = mesh.surfaces.at(to_upper(name));
    convert_elements(mesh, registry, family, work);
    mesh.surfaces.erase(work);
  }
}

void add_surfaces(Model& model, const Mesh& mesh, const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    Surface surface;
    surface.name = to_upper(name);
    surface.kind = Surface::Kind::ElementFaces;
    for (const FaceRef& f : mesh.surfaces.at(surface.name))
      surface.faces.push_back({f.element, f.face + 1});
    model.surfaces[surface.name] = surface;
  }
}

std::optional<Friction> friction_parameter(const BuilderParams& params, const std::string& name) {
  return friction_value(params, name, params.text(name));
}

std::optional<Friction> friction_value(const BuilderParams& params, const std::string& name,
                                       const std::string& value) {
  Friction friction;
  if (to_upper(value) == "ROUGH") {
    friction.kind = Friction::Kind::Rough;
    return friction;
  }
  char* end = nullptr;
  const double mu = std::strtod(value.c_str(), &end);
  if (value.empty() || *end != '\0' || !std::isfinite(mu) || mu < 0)
    params.fail("--" + name + ": expected a coefficient >= 0 or 'rough', not '" + value + "'");
  if (mu == 0) return std::nullopt;
  friction.kind = Friction::Kind::Isotropic;
  friction.mu = mu;
  return friction;
}

void add_contact(Model& model, const std::string& name, const std::string& slave,
                 const std::string& master, const std::optional<Friction>& friction,
                 std::optional<double> clearance) {
  SurfaceInteraction interaction;
  interaction.name = to_upper(name);
  interaction.friction = friction;
  model.surface_interactions[interaction.name] = interaction;
  ContactPair pair;
  pair.type = ContactPair::Type::NodeToSurface;
  pair.slave = to_upper(slave);
  pair.master = to_upper(master);
  pair.interaction = interaction.name;
  pair.clearance = clearance;
  model.contact_pairs.push_back(pair);
}

OutputRequest contact_print(const std::string& family) {
  OutputRequest r;
  r.kind = OutputRequest::Kind::ContactPrint;
  r.vars = {"CSTR", "CDIS"};
  // CalculiX runs decks of its own element types; the others get the contact status too.
  if (family != "C3D8" && family != "C3D20" && family != "C3D8R" && family != "C3D8I" &&
      family != "C3D20R")
    r.vars.push_back("CSTATUS");
  return r;
}

std::vector<FaceRef> faces_where(const Mesh& mesh, const std::vector<int>& elements,
                                 const std::function<bool(const Vec3&)>& on_side) {
  std::vector<FaceRef> out;
  for (int e : elements)
    for (int f = 0; f < 6; ++f) {
      bool all = true;
      for (int local : face_corner_nodes(f))
        all = all && on_side(mesh.nodes[mesh.elements[e].nodes[local]]);
      if (all) out.push_back({e, f});
    }
  return out;
}

void pressure_on(Step& step, const Mesh& mesh, const std::string& surface, double p) {
  for (const FaceRef& f : mesh.surfaces.at(to_upper(surface)))
    step.dloads.push_back({f.element, f.face + 1, p, {}});
}

std::string fmt_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

double continuing_grading(double first, double length, int n) {
  if (n == 1) return 1.0;
  // Sum of first * r^k, k < n, equals length: bisection on r (monotonic).
  auto total = [&](double r) {
    double sum = 0.0, h = first;
    for (int k = 0; k < n; ++k, h *= r) sum += h;
    return sum;
  };
  double lo = 1e-3, hi = 1e3;
  for (int it = 0; it < 200; ++it) {
    const double mid = std::sqrt(lo * hi);
    (total(mid) < length ? lo : hi) = mid;
  }
  return std::pow(std::sqrt(lo * hi), n - 1);
}

int split_bodies(Mesh& mesh, const std::string& body_a, const std::string& surface_a,
                 const std::string& surface_b) {
  const std::string name = "__SPLIT";
  split_interface(mesh, body_a, name);
  Interface& split = mesh.interfaces.back();
  mesh.surfaces[to_upper(surface_a)] = mesh.surfaces.at(split.surface_a);
  mesh.surfaces[to_upper(surface_b)] = mesh.surfaces.at(split.surface_b);
  mesh.surfaces.erase(split.surface_a);
  mesh.surfaces.erase(split.surface_b);
  split.name = to_upper(surface_a) + "/" + to_upper(surface_b);
  split.surface_a = to_upper(surface_a);
  split.surface_b = to_upper(surface_b);
  return static_cast<int>(split.pairs.size());
}

std::vector<SectionPatch> quarter_o_grid(double c) {
  return sector_o_grid(c, 0.5 * 3.14159265358979323846);
}

std::vector<SectionPatch> sector_o_grid(double c, double angle) {
  const double half = 0.5 * angle, m = c / std::cos(half);
  const Vec3 A{c, 0, 0}, M{m * std::cos(half), m * std::sin(half), 0};
  const Vec3 B{c * std::cos(angle), c * std::sin(angle), 0};
  const auto blend = [](const Vec3& in, const Vec3& out, double s) {
    return Vec3{in[0] + s * (out[0] - in[0]), in[1] + s * (out[1] - in[1]), 0};
  };
  return {
      [=](double s, double t) {  // bilinear in O, A, M, B
        return Vec3{s * (1 - t) * A[0] + s * t * M[0] + (1 - s) * t * B[0],
                    s * (1 - t) * A[1] + s * t * M[1] + (1 - s) * t * B[1], 0};
      },
      [=](double s, double t) {
        return blend(blend(A, M, t), {std::cos(half * t), std::sin(half * t), 0}, s);
      },
      [=](double s, double t) {
        return blend(blend(M, B, t), {std::cos(half * (1 + t)), std::sin(half * (1 + t)), 0}, s);
      }};
}

BlockMap prism(const SectionPatch& section, double z0, double z1,
               const std::function<double(double)>& radius, double angle) {
  const double c = std::cos(angle), sn = std::sin(angle);
  return [=](const Vec3& xi) {
    const double z = z0 + (z1 - z0) * 0.5 * (xi[2] + 1);
    const Vec3 p = section(0.5 * (xi[0] + 1), 0.5 * (xi[1] + 1));
    const double r = radius(z);
    return Vec3{r * (c * p[0] - sn * p[1]), r * (sn * p[0] + c * p[1]), z};
  };
}

}  // namespace styk::mesher::detail
