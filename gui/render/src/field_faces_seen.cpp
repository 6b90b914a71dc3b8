#include "styk/render/visibility.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace styk::render {
namespace {

struct ScreenPoint {
  double x, y, z;  // raster pixels (x right, y down), NDC depth
};

// Fills the triangle into `depth` (and `owner` = whether the field owns the front-most pixel).
// Culls triangles that turn the back to the eye when `cull` (front faces run clockwise on screen
// with y down, as FrameGeometry winds them seen from outside).
void rasterise(const std::array<ScreenPoint, 3>& p, bool field, bool cull, int w, int h,
               std::vector<float>& depth, std::vector<char>* owner) {
  const double area = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
  if (area == 0.0) return;
  // Clockwise on the screen (y up, GL_CW) is a positive signed area with the raster's y down.
  if (cull && area < 0) return;
  const int x0 = std::max(0, int(std::floor(std::min({p[0].x, p[1].x, p[2].x}))));
  const int x1 = std::min(w - 1, int(std::ceil(std::max({p[0].x, p[1].x, p[2].x}))));
  const int y0 = std::max(0, int(std::floor(std::min({p[0].y, p[1].y, p[2].y}))));
  const int y1 = std::min(h - 1, int(std::ceil(std::max({p[0].y, p[1].y, p[2].y}))));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const double px = x + 0.5, py = y + 0.5;
      const double w0 = ((p[1].x - px) * (p[2].y - py) - (p[2].x - px) * (p[1].y - py)) / area;
      const double w1 = ((p[2].x - px) * (p[0].y - py) - (p[0].x - px) * (p[2].y - py)) / area;
      const double w2 = 1.0 - w0 - w1;
      if (w0 < 0 || w1 < 0 || w2 < 0) continue;
      const float z = float(w0 * p[0].z + w1 * p[1].z + w2 * p[2].z);
      float& d = depth[std::size_t(y) * w + x];
      if (z < d) {
        d = z;
        if (owner) (*owner)[std::size_t(y) * w + x] = field;
      }
    }
}

}  // namespace

double field_faces_seen(const FrameGeometry& g, const Camera& camera, double aspect, int columns) {
  const int w = std::max(8, columns);
  const int h = std::max(8, int(std::lround(w / std::max(1e-3, aspect))));
  std::vector<ScreenPoint> screen(g.face_vertices.size());
  for (std::size_t i = 0; i < screen.size(); ++i) {
    const float* q = g.face_vertices[i].position;
    const std::array<float, 3> ndc = project(camera, {q[0], q[1], q[2]});
    screen[i] = {(ndc[0] + 1.0) * 0.5 * w, (1.0 - ndc[1]) * 0.5 * h, ndc[2]};
  }
  const float far = std::numeric_limits<float>::max();
  std::vector<float> all(std::size_t(w) * h, far), alone(std::size_t(w) * h, far);
  std::vector<char> owner(std::size_t(w) * h, 0);
  for (std::size_t t = 0; t + 2 < g.triangles.size(); t += 3) {
    const std::array<ScreenPoint, 3> p = {screen[g.triangles[t]], screen[g.triangles[t + 1]],
                                          screen[g.triangles[t + 2]]};
    const bool field = g.face_vertices[g.triangles[t]].t >= 0 &&
                       g.face_vertices[g.triangles[t + 1]].t >= 0 &&
                       g.face_vertices[g.triangles[t + 2]].t >= 0;
    rasterise(p, field, g.closed, w, h, all, &owner);
    if (field) rasterise(p, true, g.closed, w, h, alone, nullptr);
  }
  long covered = 0, seen = 0;
  for (std::size_t k = 0; k < alone.size(); ++k) {
    if (alone[k] == far) continue;
    ++covered;
    seen += owner[k] != 0;
  }
  return covered > 0 ? double(seen) / double(covered) : 0.0;
}

}  // namespace styk::render
