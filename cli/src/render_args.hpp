// Options of `styk render` (parsed by CLI11 in main.cpp; the command body is command_render.cpp).
#pragma once

#include <string>

namespace styk::cli {

struct RenderArgs {
  std::string input;             // results file (.styk.h5) or deck (.inp, mesh only)
  std::string output;            // .png or .bmp (or .gif / .mp4 with --animate and ffmpeg);
                                 // default: input name with .png
  int step = 0;                  // 0 = last step
  int increment = 0;             // 0 = last increment of the step
  std::string field;             // e.g. S.mises, U, U.z, RF.mag, S.p1, E.11; empty = mesh colours
  std::string averaging = "II";  // none | I | II | centroid (stress and strain fields)
  std::string fibre = "top";     // bottom | middle | top: the shells' stress / strain fibre
  int bands = 12;                // 2..24 contour colours
  bool smooth = false;           // continuous colours instead of bands
  bool contact_only = false;     // with a contact field: draw only the faces carrying it
  bool all_faces = false;        // ... every face, even where those faces are hidden
  std::string contact_pair;      // a slave surface: that pair's contact output only
  std::string range;             // MIN,MAX of the colour scale; empty = the field's range
  bool ip_values = false;        // the field at the integration points, as coloured points
  std::string labels;            // nodes, elements or nodes,elements
  bool unroll = false;           // unrolled map of a contact field
  std::string unroll_axis;       // PX,PY,PZ,DX,DY,DZ; empty = fitted
  int samples = 4;               // multisampling, 1..16
  std::string deform;            // auto | none | factor; empty = auto for results, none for a deck
  bool no_outline = false;       // no undeformed outline under a deformed shape
  std::string mode = "shaded";   // points | wireframe | hidden | shaded | shaded-edges
  std::string view = "iso";      // iso | +x | -x | +y | -y | +z | -z
  double azimuth = 0.0;          // degrees, after the named view
  double elevation = 0.0;        // degrees, after the named view
  double zoom = 1.0;
  bool perspective = false;
  std::string layers;       // comma-separated element sets; empty = whole model
  std::string hide_layers;  // comma-separated, among `layers`
  std::string elements;     // element id range FIRST-LAST
  std::string types;        // comma-separated element types
  std::string size = "1600x1200";
  int animate = 0;           // > 0: that many frames of the deformation from 0 to the scale
  double revolve = 0.0;      // > 0: axisymmetric elements drawn swept through this many degrees
  int revolve_segments = 0;  // sectors of the sweep; 0 = one per 15 degrees
};

int render_command(const RenderArgs& args);

}  // namespace styk::cli
