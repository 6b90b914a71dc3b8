// What the 3D view shows, built on the CPU from the Document (no Qt, no GL): the skin of the
// visible layers, the contour field of the chosen increment, the deformed shape, and per view
// change only the camera and the overlay (orbit, pan and zoom never rebuild the geometry).
// The main window's GL widget draws frame() with render::GlRenderer.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "session/document.hpp"
#include "styk/render/frame.hpp"
#include "styk/render/geometry.hpp"
#include "styk/render/render_job.hpp"

namespace styk::gui {

struct DisplaySettings {
  render::DisplayMode mode = render::DisplayMode::Shaded;
  int increment = -1;  // index into Results::increments; -1 = the last
  std::string field;   // "" = layer colours; else a render::field_names() entry, e.g. "S.mises"
  render::Averaging averaging = render::Averaging::MethodII;
  int bands = render::kDefaultBands;
  bool smooth = false;
  bool deformed = true;     // with results
  bool auto_scale = true;   // largest displacement = 0.1 of the model size
  double scale = 1.0;       // when !auto_scale
  bool outline = true;      // the undeformed outline under a deformed shape
};

// The camera as the mouse moves it: a named view turned by azimuth/elevation, zoomed, and panned
// in the screen plane (pan in fractions of the model size).
struct ViewState {
  render::ViewSpec spec;
  double pan_right = 0.0;
  double pan_up = 0.0;
};

struct ProbeResult {
  int node = -1;            // node index
  Id node_id = 0;
  Vec3 position{};          // undeformed coordinates
  std::optional<double> value;  // the contour field at the node, when a field is shown
  std::string field;
};

class Scene {
 public:
  // Builds skin, field and geometry. Throws InputError for a field the increment does not hold
  // (the message names what it holds) and when nothing is visible; the scene is then empty.
  void rebuild(const Document& document, const DisplaySettings& settings);
  void clear();
  bool empty() const { return !skin_; }

  // Camera and overlay for a viewport of width x height pixels. Cheap: call per paint.
  const render::Frame& frame(int width, int height, const ViewState& view);

  double deformation_scale() const { return scale_; }
  const render::ScalarField* field() const { return field_ ? &*field_ : nullptr; }
  const render::ColorScale& colors() const { return colors_; }
  const IncrementResult* increment() const { return increment_; }
  std::size_t triangle_count() const { return frame_.geometry.triangles.size() / 3; }

  // The visible skin node drawn nearest to pixel (x, y) (top-left origin) of the last frame(),
  // within `radius` pixels; nearer the eye wins among equally near ones.
  std::optional<ProbeResult> probe(int x, int y, int radius = 8) const;
  // The field value at a node: node fields directly, element-node and element fields as the
  // mean over the visible elements around the node. Empty without a field or for a node no
  // visible element uses.
  std::optional<double> value_at_node(int node) const;

 private:
  Vec3 placed(int node) const;  // deformed position relative to the geometry origin

  const Model* model_ = nullptr;
  const IncrementResult* increment_ = nullptr;
  std::unique_ptr<render::SkinModel> skin_;
  std::optional<render::ScalarField> field_;
  render::ColorScale colors_;
  double scale_ = 0.0;
  std::vector<std::string> title_lines_;
  std::string legend_heading_;
  std::vector<int> visible_nodes_;
  render::Frame frame_;
};

}  // namespace styk::gui
