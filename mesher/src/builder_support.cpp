#include "builder_support.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <Eigen/Core>

#include "styk/mesher/convert.hpp"
#include "styk/mesher/split.hpp"

namespace styk::mesher::detail {

ParamDecl family_param(const std::string& default_family, const std::vector<std::string>& allowed) {
  std::string list;
  for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
  return {"element", default_family, "element family: " + list};
}

std::string family(const BuilderParams& params, const std::vector<std::string>& allowed) {
  std::vector<std::string> upper;
  for (const std::string& a : allowed) upper.push_back(to_upper(a));
  const std::string value = to_upper(params.text("element"));
  if (std::find(upper.begin(), upper.end(), value) == upper.end())
    params.choice("element", allowed);  // throws the listing message
  return value;
}

const std::vector<std::string> kAllHexFamilies = {"C3D8",  "C3D20", "C3D14",  "C3D21", "C3D28",
                                                  "C3D8R", "C3D8I", "C3D20R", "C3D27"};

namespace {

const TElement& family_element(const ElementRegistry& registry, const std::string& family) {
  const TElement* element = registry.find(family);
  if (!element)
    throw InputError({"styk mesh", 0},
                     "element type " + family + " is not registered (are the plug-ins loaded?)");
  return *element;
}

// Tetrahedra (4 corners) and wedges (6) are made by splitting bricks (mesher/split.hpp).
int split_corners(const TElement& element) {
  if (element.form() != ElementForm::Solid || element.conversion()) return 0;
  const std::size_t corners = corner_nodes(element).size();
  return corners == 4 || corners == 6 ? static_cast<int>(corners) : 0;
}

}  // namespace

std::string base_type(const ElementRegistry& registry, const std::string& family) {
  const TElement& element = family_element(registry, family);
  if (const std::optional<ElementConversion> how = element.conversion()) return to_upper(how->base);
  if (const int corners = split_corners(element))
    return element.node_count() > corners ? "C3D20" : "C3D8";
  return to_upper(family);
}

bool splits_bricks(const ElementRegistry& registry, const std::string& family) {
  return split_corners(family_element(registry, family)) != 0;
}

void apply_family(Mesh& mesh, const ElementRegistry& registry, const std::string& family,
                  const std::string& contact_surface) {
  const TElement& element = family_element(registry, family);
  if (element.conversion()) {
    convert_elements(mesh, registry, family,
                     converts_a_layer(registry, family) ? contact_surface : std::string());
    return;
  }
  const int corners = split_corners(element);
  if (corners == 4) split_to_tetrahedra(mesh, registry, family);
  if (corners == 6) split_to_wedges(mesh, registry, family);
}

BlockMap box_map(const Vec3& origin, const Vec3& size) {
  return [origin, size](const Vec3& xi) {
    return Vec3{origin[0] + size[0] * 0.5 * (xi[0] + 1), origin[1] + size[1] * 0.5 * (xi[1] + 1),
                origin[2] + size[2] * 0.5 * (xi[2] + 1)};
  };
}

std::vector<int> nodes_where(const Mesh& mesh, const std::function<bool(const Vec3&)>& inside) {
  std::vector<int> out;
  for (int n = 0; n < static_cast<int>(mesh.nodes.size()); ++n)
    if (inside(mesh.nodes[n])) out.push_back(n);
  return out;
}

NodalAreas equivalent_nodal_areas(const Model& model, const ElementRegistry& registry,
                                  const std::vector<FaceRef>& faces) {
  NodalAreas out;
  for (const FaceRef& f : faces) {
    const Element& element = model.elements[f.element];
    const TElement* formulation = registry.find(element.type);
    if (!formulation)
      throw InputError({model.source, 0}, "element type " + element.type +
                                              " is not registered (are the plug-ins loaded?)");
    ElementGeometry g;
    g.X.resize(element.node_count, 3);
    g.id = element.id;
    const int* nodes = model.element_nodes(f.element);
    for (int i = 0; i < element.node_count; ++i)
      for (int d = 0; d < 3; ++d) g.X(i, d) = model.coords[nodes[i]][d];
    Eigen::VectorXd a;
    formulation->nodal_areas(g, f.face, a);
    for (int i = 0; i < element.node_count; ++i)
      if (a(i) != 0.0) {
        out.area[nodes[i]] += a(i);
        out.sum += a(i);
      }
  }
  return out;
}

std::vector<ConcentratedLoad> traction_loads(const Model& model, const ElementRegistry& registry,
                                             const std::vector<FaceRef>& faces, const Vec3& total) {
  const NodalAreas areas = equivalent_nodal_areas(model, registry, faces);
  std::vector<ConcentratedLoad> loads;
  for (const auto& [node, a] : areas.area)
    for (int d = 0; d < 3; ++d)
      if (total[d] != 0.0) loads.push_back({node, d + 1, total[d] * a / areas.sum, {}});
  return loads;
}

std::vector<ConcentratedLoad> point_force(const Mesh& mesh, const std::vector<int>& candidates,
                                          const Vec3& target, const Vec3& force,
                                          std::vector<int>* loaded) {
  std::vector<std::pair<double, int>> by_distance;
  for (int n : candidates) {
    const Vec3& x = mesh.nodes[n];
    by_distance.push_back({std::sqrt((x[0] - target[0]) * (x[0] - target[0]) +
                                     (x[1] - target[1]) * (x[1] - target[1]) +
                                     (x[2] - target[2]) * (x[2] - target[2])),
                           n});
  }
  std::sort(by_distance.begin(), by_distance.end());
  std::vector<std::pair<int, double>> shares;
  if (by_distance.size() == 1 || by_distance[0].first < 1e-9 * mesh.size()) {
    shares.push_back({by_distance.at(0).second, 1.0});
  } else {
    const double d0 = by_distance[0].first, d1 = by_distance[1].first;
    shares.push_back({by_distance[0].second, d1 / (d0 + d1)});
    shares.push_back({by_distance[1].second, d0 / (d0 + d1)});
  }
  std::vector<ConcentratedLoad> loads;
  for (const auto& [node, share] : shares) {
    if (loaded) loaded->push_back(node);
    for (int d = 0; d < 3; ++d)
      if (force[d] != 0.0) loads.push_back({node, d + 1, share * force[d], {}});
  }
  return loads;
}

void fix(Model& model, const std::vector<int>& nodes, std::initializer_list<int> dofs) {
  for (int n : nodes)
    for (int dof : dofs) model.boundaries.push_back({n, dof, 0.0, {}});
}

void add_node_set(Model& model, const std::string& name, const std::vector<int>& nodes) {
  std::vector<int> sorted = nodes;
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  NodeSet& set = model.nsets[to_upper(name)];
  set.name = to_upper(name);
  set.nodes = std::move(sorted);
}

Step static_step() {
  Step step;
  step.name = "LOAD";
  step.has_procedure = true;
  return step;
}

OutputRequest print_request(OutputRequest::Kind kind, const std::string& set,
                            std::vector<std::string> vars, bool totals) {
  OutputRequest r;
  r.kind = kind;
  r.set = to_upper(set);
  r.vars = std::move(vars);
  r.totals = totals;
  return r;
}

}  // namespace styk::mesher::detail

namespace styk::mesher {

Model finish_model(const Mesh& mesh, const std::string& heading, double young, double poisson) {
  Model model = to_model(mesh);
  model.heading = heading;
  Material material;
  material.name = "MAT";
  material.young = young;
  material.poisson = poisson;
  model.materials.push_back(material);
  Section section;
  section.elset = "EALL";
  section.material = "MAT";
  section.material_index = 0;
  model.sections.push_back(section);
  for (Element& e : model.elements) e.section = 0;
  return model;
}

}  // namespace styk::mesher
