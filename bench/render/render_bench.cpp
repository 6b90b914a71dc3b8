// Renderer scale benchmark (bench/render/README.md): skin extraction and a full headless
// 1600x1200 render of C3D20 block models, timed separately, and `styk render` end to end on a
// results file (read the HDF5 file, load the plug-ins, skin, draw, write the PNG).
//   styk_render_bench [N ...]   N = elements per edge of an N x N x N block (default 22 46 100)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "render_args.hpp"
#include "styk/elements/builtin.hpp"
#include "styk/io/results_file.hpp"
#include "styk/mesher/box_mesh.hpp"
#include "styk/render/image.hpp"
#include "styk/render/osmesa_renderer.hpp"
#include "styk/render/render_job.hpp"
#include "styk/render/skin.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  using namespace styk;
  std::vector<int> sizes;
  for (int i = 1; i < argc; ++i) sizes.push_back(std::atoi(argv[i]));
  if (sizes.empty()) sizes = {22, 46, 100};

  ElementRegistry registry;
  register_builtin_elements(registry);
  std::printf(
      "elements,nodes,skin_faces,mesh_s,skin_s,job_s,geometry_s,draw_read_s,png_s,"
      "render_total_s,triangles,results_file_s,styk_render_s\n");
  for (int n : sizes) {
    auto start = Clock::now();
    Model model;
    mesher::BoxSpec spec;
    spec.type = "C3D20";
    spec.size = {1.0, 1.0, 1.0};
    spec.divisions = {n, n, n};
    mesher::BoxMesh mesh(spec, model);
    // A displacement field for the contour and the deformed shape (bending about y).
    IncrementResult inc;
    inc.U.resize(model.coords.size());
    for (std::size_t i = 0; i < model.coords.size(); ++i) {
      const Vec3& x = model.coords[i];
      inc.U[i] = {0.001 * x[2], 0.0002 * x[1], -0.002 * x[0] * x[0]};
    }
    const double mesh_s = seconds_since(start);

    // Skin extraction alone, on every element.
    start = Clock::now();
    const auto formulations = render::element_formulations(model, registry);
    std::vector<int> all(model.elements.size());
    for (std::size_t e = 0; e < all.size(); ++e) all[e] = static_cast<int>(e);
    const auto skin = render::extract_skin(model, formulations, all);
    const double skin_s = seconds_since(start);

    // The full headless render: job (skin, field, camera, overlay), geometry, GL draw and
    // read-back, PNG file.
    const auto render_start = Clock::now();
    render::RenderOptions options;  // 1600 x 1200, shaded, iso
    options.field = "U.mag";
    options.deform = render::parse_deform("auto");
    const render::RenderJob job(model, registry, &inc, options);
    const double job_s = seconds_since(render_start);
    start = Clock::now();
    const render::Frame frame = job.frame(1.0);
    const double geometry_s = seconds_since(start);
    start = Clock::now();
    render::OsmesaRenderer renderer(options.width, options.height);
    const render::Image image = renderer.render(frame);
    const double draw_s = seconds_since(start);
    start = Clock::now();
    const std::string png = "render_bench_" + std::to_string(model.elements.size()) + ".png";
    render::write_png(png, image);
    const double png_s = seconds_since(start);
    const double total_s = seconds_since(render_start);

    // `styk render RESULTS --field U.mag --deform auto` end to end (the command body).
    start = Clock::now();
    const std::string results =
        "render_bench_" + std::to_string(model.elements.size()) + ".styk.h5";
    inc.RF.assign(model.coords.size(), Vec3{0, 0, 0});
    Results all_results;
    all_results.increments.push_back(inc);
    write_results_file(results, model, all_results);
    const double write_s = seconds_since(start);
    start = Clock::now();
    cli::RenderArgs args;
    args.input = results;
    args.field = "U.mag";
    args.output = "render_bench_cli_" + std::to_string(model.elements.size()) + ".png";
    cli::render_command(args);
    const double cli_s = seconds_since(start);
    std::printf("%zu,%zu,%zu,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%zu,%.3f,%.3f\n",
                model.elements.size(), model.coords.size(), skin.size(), mesh_s, skin_s, job_s,
                geometry_s, draw_s, png_s, total_s, frame.geometry.triangles.size() / 3, write_s,
                cli_s);
    std::fflush(stdout);
  }
  return 0;
}
