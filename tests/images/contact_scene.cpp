#include "contact_scene.hpp"

#include "contact_model_kit.hpp"  // tests/verification
#include "styk/mesher/builders.hpp"
#include "styk/solver/analysis.hpp"

namespace styk::render_test {

Model contact_block_model() {
  mesher::Mesh mesh;
  const mesher::Block slab = test::add_box(mesh, {0, 0, -1}, {4, 4, 0}, {8, 8, 2}, "C3D8", "SLAB");
  const mesher::Block block = test::add_box(mesh, {1, 1, 0}, {3, 3, 2}, {4, 4, 4}, "C3D8", "BLOCK");
  mesh.add_to_surface("SLAB_TOP", slab.side_faces(2, 1));
  mesh.add_to_surface("BLOCK_BOTTOM", block.side_faces(2, -1));
  mesh.add_to_surface("BLOCK_TOP", block.side_faces(2, 1));
  Model model = test::contact_model(mesh, {{"SLAB", 1000.0, 0.3}, {"BLOCK", 1000.0, 0.3}});
  model.source = "contact-block.inp";
  test::add_contact_pair(model, "BLOCK_BOTTOM", "SLAB_TOP", "PAD", test::coulomb(0.3));
  test::fix(model, test::nodes_where(model, [](const Vec3& x) { return x[2] < -1 + 1e-9; }),
            {1, 2, 3});
  Step& step = model.steps[0];
  for (const SurfaceFace& f : model.surfaces.at("BLOCK_TOP").faces)
    step.dloads.push_back({f.element, f.face, 1.0, {}});
  const std::vector<int> top =
      test::nodes_where(model, [](const Vec3& x) { return x[2] > 2 - 1e-9; });
  for (int n : top) step.cloads.push_back({n, 1, 1.0 / top.size(), {}});
  return model;
}

IncrementResult solve_contact_block(const Model& model, const ElementRegistry& registry) {
  return solve_model(model, registry);
}

Model cylinders_model(const ElementRegistry& registry) {
  Model model = mesher::run_builder("cylinders", {{"element", "C3D21"}}, registry).model;
  model.source = "spec-3.2.2-cylinders-c3d21.inp";
  return model;
}

IncrementResult solve_model(const Model& model, const ElementRegistry& registry) {
  Results results = run_static_analysis(model, registry, SolveOptions{}, nullptr, nullptr);
  return std::move(results.increments.back());
}

}  // namespace styk::render_test
