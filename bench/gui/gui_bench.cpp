// styk-gui benchmark (bench/gui/README.md): opening a C3D20 results file and showing the first
// Mises contour, and frames per second while orbiting, drawn by the desktop program's GL view
// (run under xvfb-run: Mesa llvmpipe). The results are made up from the coordinates (a solve of
// 100k C3D20 is not what is measured here) and written with the real results writer.
// Usage: styk_gui_bench [ELEMENTS...]   (default 10000 100000)
#include <QApplication>
#include <QElapsedTimer>
#include <QSurfaceFormat>
#include <cmath>
#include <cstdio>
#include <string>

#include "gl_view.hpp"
#include "session/document.hpp"
#include "session/scene.hpp"
#include "styk/elements/element_setup.hpp"
#include "styk/io/results_file.hpp"
#include "styk/mesher/block_mesh.hpp"
#include "styk/mesher/geometry_maps.hpp"

using namespace styk;

namespace {

// A C3D20 box of about `elements` elements (4 : 2 : 1 proportions of the divisions).
std::string write_results(int elements) {
  const int nz = std::max(1, int(std::lround(std::cbrt(elements / 8.0))));
  const int nx = 4 * nz, ny = std::max(1, elements / (nx * nz));
  mesher::Mesh mesh;
  mesher::BlockSpec spec;
  spec.divisions = {nx, ny, nz};
  spec.elset = "BOX";
  mesher::mesh_block(
      mesh,
      mesher::hex_map(
          {{0, 0, 0}, {4, 0, 0}, {4, 2, 0}, {0, 2, 0}, {0, 0, 1}, {4, 0, 1}, {4, 2, 1}, {0, 2, 1}}),
      spec);
  const Model model = mesher::to_model(mesh, "bench");
  IncrementResult inc;
  for (const Vec3& x : model.coords) {
    inc.U.push_back({0.0, 0.0, -1e-3 * x[0] * x[0]});
    inc.RF.push_back({0, 0, 0});
    inc.S_nodal_II.push_back({100 * (x[2] - 0.5) * (4 - x[0]), 0, 0, 5 * x[1], 0, 0});
  }
  Results results;
  results.increments.push_back(inc);
  const std::string path =
      "/tmp/styk-gui-bench-" + std::to_string(model.element_count()) + ".styk.h5";
  write_results_file(path, model, results);
  std::printf("%d elements (%d x %d x %d), %d nodes: %s\n", model.element_count(), nx, ny, nz,
              model.node_count(), path.c_str());
  return path;
}

}  // namespace

int main(int argc, char** argv) {
  QSurfaceFormat format;
  format.setVersion(3, 3);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  QSurfaceFormat::setDefaultFormat(format);
  QApplication app(argc, argv);
  PluginLibraries libraries;
  ElementRegistry registry;
  styk::setup_element_registry(registry, libraries, {styk::build_plugin_directory()});
  std::vector<int> sizes;
  for (int i = 1; i < argc; ++i) sizes.push_back(std::atoi(argv[i]));
  if (sizes.empty()) sizes = {10000, 100000};

  for (int size : sizes) {
    const std::string path = write_results(size);
    gui::GlView view;
    view.resize(1024, 768);
    view.show();
    QApplication::processEvents();

    QElapsedTimer timer;
    timer.start();
    gui::Document document(registry);
    document.open_results(path);
    const double t_read = timer.nsecsElapsed() * 1e-9;
    gui::DisplaySettings settings;
    settings.field = "S.mises";
    view.scene().rebuild(document, settings);
    const double t_scene = timer.nsecsElapsed() * 1e-9;
    view.repaint();       // paints synchronously
    view.grab_picture();  // waits for the GL to finish the frame
    const double t_first = timer.nsecsElapsed() * 1e-9;
    std::printf(
        "  open + first Mises contour: %.2f s (read %.2f s, scene %.2f s, first frame %.2f s); %zu "
        "triangles\n",
        t_first, t_read, t_scene - t_read, t_first - t_scene, view.scene().triangle_count());

    const int frames = 60;
    const long drawn_before = view.frames_drawn();
    timer.restart();
    for (int f = 0; f < frames; ++f) {
      view.view().spec.azimuth += 3.0;
      // grabFramebuffer() runs paintGL and reads the pixels back: every frame is really drawn
      // (repaint() may be coalesced by the window system), so this is a conservative figure.
      view.grab_picture();
    }
    const double seconds = timer.nsecsElapsed() * 1e-9;
    const long drawn = view.frames_drawn() - drawn_before;
    std::printf("  orbit: %ld frames drawn in %.2f s = %.1f frames/s (1024 x 768)\n", drawn,
                seconds, drawn / seconds);
    std::fflush(stdout);
  }
  return 0;
}
