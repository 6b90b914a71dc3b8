// Where a model point lands in a rendered frame, and which colour band a pixel shows: the probes
// the beam and shell render tests read their pictures with.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "styk/core/vec3.hpp"
#include "styk/render/camera.hpp"
#include "styk/render/color.hpp"
#include "styk/render/color_scale.hpp"
#include "styk/render/image.hpp"
#include "styk/render/render_job.hpp"

namespace styk::render_test {

// The pixel (column, row) of model point x in the frame's model area.
inline std::array<int, 2> pixel_of(const render::Frame& frame, const Vec3& x) {
  const Vec3& o = frame.geometry.origin;
  const std::array<float, 3> ndc =
      render::project(frame.camera, {float(x[0] - o[0]), float(x[1] - o[1]), float(x[2] - o[2])});
  const render::PixelRect& area = frame.overlay.model;
  return {area.x + int(std::floor((ndc[0] + 1.0) * 0.5 * area.width)),
          area.y + int(std::floor((1.0 - ndc[1]) * 0.5 * area.height))};
}

// The band whose colour the pixel has (+-1 per channel), or -1 (also outside the picture).
inline int band_at(const render::Image& image, std::array<int, 2> at,
                   const render::ColorScale& scale) {
  if (at[0] < 0 || at[1] < 0 || at[0] >= image.width || at[1] >= image.height) return -1;
  const std::uint8_t* p = image.pixel(at[0], at[1]);
  for (int b = 0; b < scale.bands; ++b) {
    const render::Rgb c = scale.band_color(b);
    if (std::abs(p[0] - render::to_byte(c.r)) <= 1 && std::abs(p[1] - render::to_byte(c.g)) <= 1 &&
        std::abs(p[2] - render::to_byte(c.b)) <= 1)
      return b;
  }
  return -1;
}

}  // namespace styk::render_test
