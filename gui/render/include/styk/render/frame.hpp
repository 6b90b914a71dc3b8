// One picture, ready to draw: geometry, camera, overlay and how to draw them. Built on the CPU by
// RenderJob (or the desktop program's Scene); drawn by GlRenderer (OSMesa or the Qt widget).
#pragma once

#include <string>
#include <vector>

#include "styk/render/camera.hpp"
#include "styk/render/color_scale.hpp"
#include "styk/render/geometry.hpp"
#include "styk/render/overlay.hpp"

namespace styk::render {

// SPEC §5 display modes.
enum class DisplayMode {
  Points,       // the nodes of the visible elements
  Wireframe,    // every skin edge, see-through
  HiddenLine,   // skin edges, hidden ones removed
  Shaded,       // lit faces with feature lines
  ShadedEdges,  // lit faces with every skin edge
};

// "points", "wireframe", "hidden", "shaded", "shaded-edges"; InputError otherwise.
DisplayMode parse_display_mode(const std::string& text);
std::string display_mode_name(DisplayMode mode);

// How a picture looks at one moment: everything that changes when the user orbits, pans, zooms
// or resizes (camera, overlay, picture size) plus the cheap drawing state (mode, colour scale:
// uniforms, not vertex data). GlRenderer::draw_view draws the retained geometry with it.
struct FrameView {
  int width = 0;
  int height = 0;
  DisplayMode mode = DisplayMode::Shaded;
  Camera camera;
  Overlay overlay;
  bool has_field = false;
  ColorScale colors;  // meaningful when has_field
  float point_size = 3.0f;
  float bar_width = 3.0f;      // pixels across a drawn line element (truss)
  float ip_point_size = 7.0f;  // pixels across a drawn integration point (round)
  // Samples per pixel of the scene (edges smoothed by multisampling; 1 = none). The overlay is
  // drawn afterwards, on whole pixels.
  int samples = 1;
};

// One complete picture: the view and the geometry (the vertex arrays; expensive to build and to
// upload, so the desktop view uploads them once per change, see GlRenderer::set_geometry).
struct Frame : FrameView {
  FrameGeometry geometry;
};

}  // namespace styk::render
