#include "styk/mesher/cantilever.hpp"

#include <algorithm>

#include "styk/mesher/face_traction.hpp"

namespace styk::mesher {
namespace {

void add_node_set(Model& model, const std::string& name, std::vector<int> nodes) {
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  NodeSet& set = model.nsets[name];
  set.name = name;
  set.nodes = std::move(nodes);
}

// Nodes carrying a point force at the middle of the top edge of the free end: the mid-edge node
// when there is one, else the two nodes either side of the middle, each with half the force.
std::vector<std::pair<int, double>> top_edge_midpoint(const BoxMesh& box) {
  const auto g = box.grid_size();
  const int i = g[0] - 1, k = g[2] - 1;
  if (g[1] % 2 == 1 && box.node_at(i, g[1] / 2, k) >= 0)
    return {{box.node_at(i, g[1] / 2, k), 1.0}};
  const int j_lo = (g[1] - 1) / 2, j_hi = g[1] / 2;
  return {{box.node_at(i, j_lo, k), 0.5}, {box.node_at(i, j_hi, k), 0.5}};
}

}  // namespace

Model make_cantilever(const CantileverSpec& spec) {
  Model model;
  model.source = "cantilever";
  model.heading = "Block cantilever " + spec.box.type;
  BoxMesh box(spec.box, model);

  std::vector<int> all(model.node_count());
  for (int n = 0; n < model.node_count(); ++n) all[n] = n;
  add_node_set(model, "NALL", all);
  add_node_set(model, "ROOT", box.face_nodes(0, 0));
  add_node_set(model, "TIP", box.face_nodes(0, 1));

  Material steel;
  steel.name = "MAT";
  steel.young = spec.young;
  steel.poisson = spec.poisson;
  model.materials.push_back(steel);
  Section section;
  section.elset = "EALL";
  section.material = "MAT";
  section.material_index = 0;
  model.sections.push_back(section);
  for (Element& e : model.elements) e.section = 0;

  for (int n : model.nsets["ROOT"].nodes)
    for (int dof = 1; dof <= 3; ++dof) model.boundaries.push_back({n, dof, 0.0, {}});

  Step step;
  step.name = "LOAD";
  step.has_procedure = true;
  if (spec.load == CantileverSpec::Load::EndTraction) {
    step.cloads = uniform_traction_loads(box, 0, 1, spec.force);
  } else {
    std::vector<int> loaded;
    for (const auto& [node, share] : top_edge_midpoint(box)) {
      loaded.push_back(node);
      for (int dof = 0; dof < 3; ++dof)
        if (spec.force[dof] != 0.0)
          step.cloads.push_back({node, dof + 1, share * spec.force[dof], {}});
    }
    add_node_set(model, "TIPMID", loaded);
  }
  OutputRequest print_u;
  print_u.kind = OutputRequest::Kind::NodePrint;
  print_u.set = spec.print_all_displacements ? "NALL" : "TIP";
  print_u.vars = {"U"};
  OutputRequest print_rf;
  print_rf.kind = OutputRequest::Kind::NodePrint;
  print_rf.set = "ROOT";
  print_rf.vars = {"RF"};
  print_rf.totals = true;
  step.outputs = {print_u, print_rf};
  model.steps.push_back(step);
  return model;
}

}  // namespace styk::mesher
