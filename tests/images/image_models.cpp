#include "image_models.hpp"

#include <cmath>
#include <stdexcept>

#include <Eigen/Core>

#include "contact_scene.hpp"
#include "styk/elements/element_setup.hpp"
#include "styk/mesher/box_mesh.hpp"

namespace styk::render_test {

ElementRegistry make_test_registry(PluginLibraries& libraries) {
  ElementRegistry registry;
  const auto diagnostics = setup_element_registry(registry, libraries, {build_plugin_directory()});
  if (!diagnostics.empty()) throw std::runtime_error(diagnostics.front().message);
  return registry;
}

Vec3 displacement_at(const Vec3& x) { return {0.01 * x[0], 0.0, -0.00125 * x[0] * x[0]}; }

Tensor6 stress_at(const Vec3& x) {
  return {200.0 * (1.0 - x[0] / 4.0) * (x[2] - 0.5), 10.0 * x[1], 0.0, 5.0 * x[2], 3.0, 0.0};
}

double element_jump(int e) { return e % 2 == 0 ? 20.0 : -20.0; }

namespace {

Tensor6 with_jump(Tensor6 s, int e) {
  s[0] += element_jump(e);
  return s;
}

Tensor6 scaled(const Tensor6& s, double f) {
  Tensor6 out{};
  for (int k = 0; k < 6; ++k) out[k] = s[k] * f;
  return out;
}

// A quarter ring: xi -> angle 0..90 deg, eta -> radius 2..3, zeta -> height 0..1.
Vec3 ring_point(double xi, double eta, double zeta) {
  const double angle = (xi + 1.0) * 0.25 * 3.14159265358979323846;
  const double radius = 2.5 + 0.5 * eta;
  return {radius * std::cos(angle), radius * std::sin(angle), 0.5 * (zeta + 1.0)};
}

// A flat plate: xi -> x 0..4, eta -> y 0..4, zeta -> z 0..1 (S1 faces at z = 0).
Vec3 plate_point(double xi, double eta, double zeta) {
  return {2.0 * (xi + 1.0), 2.0 * (eta + 1.0), 0.5 * (zeta + 1.0)};
}

template <class Shape>
void add_patch(Model& model, const TElement& element, int divisions, const Shape& shape) {
  // Elements over a divisions x divisions patch of (xi, eta), one layer in zeta. Nodes are merged
  // by position so neighbouring elements share them.
  const SourceLoc here{"render test", 0};
  const auto& natural = element.natural_nodes();
  for (int b = 0; b < divisions; ++b)
    for (int a = 0; a < divisions; ++a) {
      std::vector<int> conn;
      for (const Vec3& n : natural) {
        const double xi = -1.0 + (2.0 * a + n[0] + 1.0) / divisions;
        const double eta = -1.0 + (2.0 * b + n[1] + 1.0) / divisions;
        const Vec3 p = shape(xi, eta, n[2]);
        int found = -1;
        for (int k = 0; k < model.node_count() && found < 0; ++k) {
          const Vec3& q = model.coords[k];
          if (std::abs(q[0] - p[0]) + std::abs(q[1] - p[1]) + std::abs(q[2] - p[2]) < 1e-9)
            found = k;
        }
        if (found < 0) found = model.add_node(model.node_count() + 1, p, here);
        conn.push_back(found);
      }
      model.add_element(model.element_count() + 1, element.name(), conn, here);
    }
  ElementSet& all = model.elsets["EALL"];
  all.name = "EALL";
  for (int e = 0; e < model.element_count(); ++e) all.elements.push_back(e);
}

void add_ring(Model& model, const TElement& element, int divisions) {
  add_patch(model, element, divisions, ring_point);
}

}  // namespace

double plate_field(const Vec3& x) {
  const double u = 0.8 * x[0] + 0.6 * x[1];
  return u * u;
}

void fill_point_results(const Model& model, const ElementRegistry& registry, IncrementResult& inc) {
  inc.ip_offset.assign(1, 0);
  inc.S.clear();
  Eigen::VectorXd N;
  Eigen::MatrixXd dN;
  for (int e = 0; e < model.element_count(); ++e) {
    const TElement& element = *registry.find(model.elements[e].type);
    const int* conn = model.element_nodes(e);
    N.resize(element.node_count());
    dN.resize(element.node_count(), 3);
    for (const Vec3& xi : element.rule(RuleKind::Full).points) {
      element.der(xi, N, dN);
      Vec3 x{0, 0, 0};
      for (int a = 0; a < element.node_count(); ++a)
        for (int k = 0; k < 3; ++k) x[k] += N(a) * model.coords[conn[a]][k];
      inc.S.push_back(with_jump(stress_at(x), e));
    }
    inc.ip_offset.push_back(static_cast<int>(inc.S.size()));
  }
  for (const Tensor6& s : inc.S) inc.E.push_back(scaled(s, 1.0 / 2e5));
}

void fill_results(const Model& model, IncrementResult& inc) {
  const std::size_t nodes = model.coords.size(), elements = model.elements.size();
  inc.U.resize(nodes);
  inc.RF.assign(nodes, Vec3{0, 0, 0});
  for (std::size_t n = 0; n < nodes; ++n) {
    inc.U[n] = displacement_at(model.coords[n]);
    if (model.coords[n][0] == 0.0) inc.RF[n] = {-1.0, 0.0, 0.5 * model.coords[n][1]};
  }
  inc.S_element_nodes.resize(model.connectivity.size());
  inc.S_centroid.resize(elements);
  std::vector<Tensor6> sum_I(nodes, Tensor6{}), sum_II(nodes, Tensor6{});
  std::vector<int> count(nodes, 0);
  for (std::size_t e = 0; e < elements; ++e) {
    const Element& element = model.elements[e];
    const int* conn = model.element_nodes(static_cast<int>(e));
    Vec3 centre{0, 0, 0};
    for (int k = 0; k < 8; ++k)
      for (int d = 0; d < 3; ++d) centre[d] += model.coords[conn[k]][d] / 8.0;
    inc.S_centroid[e] = with_jump(stress_at(centre), static_cast<int>(e));
    for (int k = 0; k < element.node_count; ++k) {
      const Tensor6 s = with_jump(stress_at(model.coords[conn[k]]), static_cast<int>(e));
      inc.S_element_nodes[element.first_node + k] = s;
      for (int c = 0; c < 6; ++c)
        sum_I[conn[k]][c] += s[c], sum_II[conn[k]][c] += inc.S_centroid[e][c];
      ++count[conn[k]];
    }
  }
  inc.S_nodal_I.resize(nodes);
  inc.S_nodal_II.resize(nodes);
  for (std::size_t n = 0; n < nodes; ++n) {
    const double f = count[n] > 0 ? 1.0 / count[n] : 0.0;
    inc.S_nodal_I[n] = scaled(sum_I[n], f);
    inc.S_nodal_II[n] = scaled(sum_II[n], f);
  }
  const double compliance = 1.0 / 2e5;
  for (const Tensor6& s : inc.S_element_nodes) inc.E_element_nodes.push_back(scaled(s, compliance));
  for (const Tensor6& s : inc.S_centroid) inc.E_centroid.push_back(scaled(s, compliance));
  for (const Tensor6& s : inc.S_nodal_I) inc.E_nodal_I.push_back(scaled(s, compliance));
  for (const Tensor6& s : inc.S_nodal_II) inc.E_nodal_II.push_back(scaled(s, compliance));
}

TestScene make_scene(const std::string& name, const ElementRegistry& registry) {
  TestScene scene;
  Model& model = scene.model;
  if (name == "box" || name == "box_mesh") {
    mesher::BoxSpec spec;
    spec.type = "C3D20";
    spec.size = {4.0, 1.0, 1.0};
    spec.divisions = {4, 2, 2};
    mesher::BoxMesh box(spec, model);
    ElementSet& left = model.elsets["LEFT"];
    ElementSet& right = model.elsets["RIGHT"];
    left.name = "LEFT", right.name = "RIGHT";
    for (int e = 0; e < model.element_count(); ++e) {
      const double x = model.coords[model.element_nodes(e)[0]][0];
      (x < 2.0 ? left : right).elements.push_back(e);
    }
    model.source = "box.inp";
    scene.has_results = name == "box";
  } else if (name == "c3d21" || name == "c3d28") {
    const TElement* element = registry.find(name == "c3d21" ? "C3D21" : "C3D28");
    if (!element) throw std::invalid_argument("plug-in element missing for scene " + name);
    add_ring(model, *element, 2);
    model.source = name + "-ring.inp";
    scene.has_results = true;
  } else if (name == "plate_c3d20" || name == "plate_c3d21" || name == "plate_c3d28") {
    const std::string type = name == "plate_c3d20"   ? "C3D20"
                             : name == "plate_c3d21" ? "C3D21"
                                                     : "C3D28";
    const TElement* element = registry.find(type);
    if (!element) throw std::invalid_argument("element " + type + " missing for scene " + name);
    add_patch(model, *element, 2, plate_point);
    model.source = name + ".inp";
    fill_results(model, scene.increment);
    for (std::size_t n = 0; n < model.coords.size(); ++n)
      scene.increment.U[n] = {plate_field(model.coords[n]), 0.0, 0.0};
    scene.has_results = true;
    return scene;
  } else if (name == "cylinders_c3d21") {
    model = cylinders_model(registry);
    scene.increment = solve_model(model, registry);
    scene.has_results = true;
    return scene;
  } else if (name == "contact_block") {
    model = contact_block_model();
    scene.increment = solve_contact_block(model, registry);
    scene.has_results = true;
    return scene;  // solved, not synthetic
  } else {
    throw std::invalid_argument("unknown test scene " + name);
  }
  if (scene.has_results) {
    fill_results(model, scene.increment);
    fill_point_results(model, registry, scene.increment);
  }
  return scene;
}

}  // namespace styk::render_test
