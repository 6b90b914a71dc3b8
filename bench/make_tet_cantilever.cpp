// Writes the tetrahedral cantilever deck of the Styk-vs-CalculiX series (bench/README.md): the
// block of PERFORMANCE.md (10 x 1 x 1, E = 210 000, nu = 0.3, clamped at x = 0) meshed NX x NY x NZ
// bricks, each split into 6 tetrahedra (mesher/split.hpp), and a unit tip shear along z as the
// consistent nodal forces of a uniform traction on x = 10 (TElement::nodal_areas of the tip faces).
//   make_tet_cantilever NX NY NZ OUT.inp [--type C3D10|C3D4]
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <string>

#include <Eigen/Core>

#include "styk/core/element_registry.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/inp/writer.hpp"
#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/split.hpp"

namespace {

using namespace styk;

// Consistent nodal forces of a unit resultant traction along z on the faces of `surface`.
std::map<int, double> tip_forces(const mesher::Mesh& mesh, const ElementRegistry& registry) {
  std::map<int, double> area;
  double total = 0.0;
  for (const mesher::FaceRef& f : mesh.surfaces.at("TIP")) {
    const mesher::MeshElement& e = mesh.elements[f.element];
    const TElement& formulation = *registry.find(e.type);
    ElementGeometry g;
    g.X.resize(formulation.node_count(), 3);
    for (int a = 0; a < formulation.node_count(); ++a)
      for (int d = 0; d < 3; ++d) g.X(a, d) = mesh.nodes[e.nodes[a]][d];
    Eigen::VectorXd a;
    formulation.nodal_areas(g, f.face, a);
    for (int k = 0; k < formulation.node_count(); ++k)
      if (a[k] != 0.0) area[e.nodes[k]] += a[k], total += a[k];
  }
  for (auto& [node, value] : area) value /= total;
  return area;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 5) {
    std::cerr << "usage: make_tet_cantilever NX NY NZ OUT.inp [--type C3D10|C3D4]\n";
    return 1;
  }
  std::string type = "C3D10";
  for (int a = 5; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--type" && a + 1 < argc) {
      type = argv[++a];
    } else {
      std::cerr << "make_tet_cantilever: unknown argument " << arg << "\n";
      return 1;
    }
  }
  ElementRegistry registry;
  register_builtin_elements(registry);
  mesher::Mesh mesh;
  const mesher::Block block =
      mesher::mesh_block(mesh,
                         [](const Vec3& xi) {
                           return Vec3{5.0 * (xi[0] + 1), 0.5 * (xi[1] + 1), 0.5 * (xi[2] + 1)};
                         },
                         {type == "C3D4" ? "C3D8" : "C3D20",
                          {std::atoi(argv[1]), std::atoi(argv[2]), std::atoi(argv[3])},
                          {1, 1, 1},
                          "EALL"});
  mesh.add_to_surface("TIP", block.side_faces(0, +1));
  mesher::split_to_tetrahedra(mesh, registry, type);
  Model model = mesher::to_model(mesh);
  Material steel;
  steel.name = "STEEL";
  steel.young = 210000.0;
  steel.poisson = 0.3;
  model.materials.push_back(steel);
  Section section;
  section.elset = "EALL";
  section.material = "STEEL";
  section.material_index = 0;
  model.sections.push_back(section);
  for (Element& e : model.elements) e.section = 0;
  NodeSet& root = model.nsets["ROOT"];
  NodeSet& tip = model.nsets["TIP"];
  root.name = "ROOT";
  tip.name = "TIP";
  for (int n = 0; n < model.node_count(); ++n) {
    if (model.coords[n][0] < 1e-9) root.nodes.push_back(n);
    if (model.coords[n][0] > 10 - 1e-9) tip.nodes.push_back(n);
  }
  for (int n : root.nodes)
    for (int dof = 1; dof <= 3; ++dof) model.boundaries.push_back({n, dof, 0.0, {}});
  Step step;
  step.name = "LOAD";
  step.has_procedure = true;
  for (const auto& [node, share] : tip_forces(mesh, registry))
    step.cloads.push_back({node, 3, share, {}});
  OutputRequest print;
  print.kind = OutputRequest::Kind::NodePrint;
  print.set = "TIP";
  print.vars = {"U"};
  step.outputs.push_back(print);
  model.steps.push_back(step);
  std::ofstream out(argv[4]);
  write_inp(model, out);
  if (!out) {
    std::cerr << "make_tet_cantilever: cannot write " << argv[4] << "\n";
    return 1;
  }
  std::cerr << "make_tet_cantilever: " << model.element_count() << " " << type << ", "
            << model.node_count() << " nodes, " << 3 * model.node_count() << " dofs\n";
  return 0;
}
