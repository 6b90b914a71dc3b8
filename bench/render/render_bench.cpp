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
#include "styk/render/camera.hpp"
#include "styk/render/image.hpp"
#include "styk/render/osmesa_renderer.hpp"
#include "styk/render/overlay.hpp"
#include "styk/render/render_job.hpp"
#include "styk/render/skin.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Frames per second while orbiting (the azimuth turned 3 deg per frame), each frame drawn and
// read back, four ways: uploading the geometry with every frame (render; "old" = also without
// back-face culling, which is what GlRenderer did before it kept the geometry) or drawing the
// retained geometry (render_view), each with and without culling. The ways take turns in blocks
// so that a change in the machine's load hits them alike. Then the retained orbit in a small
// picture, and fixed_ms: the per-frame cost without any model (clear, overlay, read-back).
// What multisampling and the refined contours cost, each against its absence in the same run
// (blocks taking turns, so a change of load hits both): frame time with 4 samples / 1 sample
// (retained geometry, drawn and read back), tessellation time with the refined grids / the base
// grids, and the triangles each gives.
struct FeatureCosts {
  double msaa_ratio = 0, refine_ratio = 0;
  std::size_t base_triangles = 0, refined_triangles = 0;
};

FeatureCosts time_features(const styk::render::RenderJob& job, const styk::render::Frame& frame,
                           styk::render::OsmesaRenderer& renderer,
                           const styk::render::GeometryRequest& request) {
  using namespace styk::render;
  FeatureCosts costs;
  Frame one = frame, four = frame;
  one.samples = 1, four.samples = 4;
  renderer.set_geometry(frame.geometry);
  double draw[2] = {}, build[2] = {};
  GeometryRequest base = request;
  base.refine = false;
  for (int block = 0; block < 3; ++block)
    for (int way = 0; way < 2; ++way) {
      auto start = Clock::now();
      for (int k = 0; k < 5; ++k) renderer.render_view(way == 0 ? one : four);
      draw[way] += seconds_since(start);
      start = Clock::now();
      const FrameGeometry g = build_geometry(job.skin(), way == 0 ? base : request);
      build[way] += seconds_since(start);
      (way == 0 ? costs.base_triangles : costs.refined_triangles) = g.triangles.size() / 3;
    }
  costs.msaa_ratio = draw[1] / draw[0];
  costs.refine_ratio = build[1] / build[0];
  return costs;
}

struct OrbitTimes {
  double old_fps = 0, upload_fps = 0, retained_no_cull_fps = 0, retained_fps = 0,
         retained_small_fps = 0, fixed_ms = 0;
};

OrbitTimes time_orbit(const styk::render::Frame& frame, styk::render::OsmesaRenderer& renderer) {
  using namespace styk::render;
  const double aspect = double(frame.overlay.model.width) / frame.overlay.model.height;
  ViewSpec spec;
  Frame culled = frame, open = frame;
  open.geometry.closed = false;  // never culled
  const auto turn = [&] {
    spec.azimuth += 3.0;
    culled.camera = open.camera =
        fit_camera(spec, frame.geometry.lower, frame.geometry.upper, aspect);
  };
  const int blocks = 3, per_block = 5;
  double seconds[4] = {};
  for (int b = 0; b < blocks; ++b)
    for (int way = 0; way < 4; ++way) {
      const Frame& f = way % 2 == 0 ? open : culled;
      if (way >= 2) renderer.set_geometry(f.geometry);
      const auto start = Clock::now();
      for (int k = 0; k < per_block; ++k) {
        turn();
        if (way < 2)
          renderer.render(f);
        else
          renderer.render_view(f);
      }
      seconds[way] += seconds_since(start);
    }
  const double frames = blocks * per_block;
  // The same orbit in a 400 x 300 picture (1/16 of the pixels, the same triangles): what is
  // left is the per-vertex and per-triangle work.
  Frame small = culled;
  small.width = 400, small.height = 300;
  Typeface typeface;
  small.overlay = build_overlay(OverlayContent{}, small.width, small.height, typeface);
  auto start = Clock::now();
  for (int k = 0; k < blocks * per_block; ++k)
    turn(), small.camera = culled.camera, renderer.render_view(small);
  const double small_s = seconds_since(start);
  renderer.set_geometry(FrameGeometry{});
  start = Clock::now();
  for (int k = 0; k < blocks * per_block; ++k) renderer.render_view(culled);
  const double fixed_s = seconds_since(start);
  return {frames / seconds[0], frames / seconds[1], frames / seconds[2],
          frames / seconds[3], frames / small_s,    1e3 * fixed_s / frames};
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
      "render_total_s,triangles,results_file_s,styk_render_s,closed,orbit_old_fps,"
      "orbit_upload_fps,orbit_retained_no_cull_fps,orbit_retained_fps,orbit_retained_400x300_fps,"
      "frame_fixed_ms,msaa_ratio,refine_ratio,base_triangles,refined_triangles\n");
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
    const OrbitTimes orbit = time_orbit(frame, renderer);
    render::GeometryRequest request;  // the job's own: the field, deformed, undeformed outline
    request.displacement = &inc.U;
    request.scale = job.deformation_scale();
    request.outline = true;
    request.points = false;
    request.field = job.field();
    request.colors = &job.colors();
    const FeatureCosts costs = time_features(job, frame, renderer, request);
    std::printf(
        "%zu,%zu,%zu,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%zu,%.3f,%.3f,%d,%.2f,%.2f,%.2f,%.2f,"
        "%.2f,%.1f,%.2f,%.2f,%zu,%zu\n",
        model.elements.size(), model.coords.size(), skin.size(), mesh_s, skin_s, job_s, geometry_s,
        draw_s, png_s, total_s, frame.geometry.triangles.size() / 3, write_s, cli_s,
        int(frame.geometry.closed), orbit.old_fps, orbit.upload_fps, orbit.retained_no_cull_fps,
        orbit.retained_fps, orbit.retained_small_fps, orbit.fixed_ms, costs.msaa_ratio,
        costs.refine_ratio, costs.base_triangles, costs.refined_triangles);
    std::fflush(stdout);
  }
  return 0;
}
