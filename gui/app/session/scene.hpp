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
#include "session/element_filter.hpp"
#include "session/selection.hpp"
#include "styk/render/font.hpp"
#include "styk/render/frame.hpp"
#include "styk/render/geometry.hpp"
#include "styk/render/point_field.hpp"
#include "styk/render/render_job.hpp"
#include "styk/render/unroll.hpp"
#include "styk/render/visibility.hpp"

namespace styk::gui {

struct DisplaySettings {
  render::DisplayMode mode = render::DisplayMode::Shaded;
  int increment = -1;  // index into Results::increments; -1 = the last
  std::string field;   // "" = layer colours; else a render::field_names() entry, e.g. "S.mises"
  render::Averaging averaging = render::Averaging::MethodII;
  // The fibre whose stress / strain colours the shells (docs/render.md "Shells").
  render::ShellFibre shell_fibre = render::ShellFibre::Top;
  int bands = render::kDefaultBands;
  bool smooth = false;
  bool deformed = true;    // with results
  bool auto_scale = true;  // largest displacement = 0.1 of the model size
  double scale = 1.0;      // when !auto_scale
  bool outline = true;     // the undeformed outline under a deformed shape
  // Animation over the increments: one colour range and one camera box for every frame, so the
  // pictures compare. Empty: the field's range over the visible elements; the shape's bounds.
  std::optional<std::array<double, 2>> range;
  std::optional<std::array<std::array<float, 3>, 2>> camera_box;  // lower, upper (frame origin)
  // View > Filter: only the passing elements of each visible layer are drawn (element_filter.hpp).
  ElementDisplayFilter filter;
  // A field that lives on surfaces (contact output): which faces show it. Auto draws its faces
  // alone, with a note in the title block, when they are hidden in the view of the first frame
  // drawn after the rebuild (the slave surface under its master body).
  render::FieldFaces field_faces = render::FieldFaces::Auto;
  bool ip_values = false;  // the field at the integration points (S.*, E.*, HFL.*, ECD.*)
  bool unrolled = false;   // the unrolled map of a surface field instead of the 3D view
  // Node / element numbers of the seen entities, or of the selected ones only.
  render::LabelRequest labels;
  bool labels_of_selection = false;
  // Multisampling of the model's edges (1 = none). Off by default in the view: with llvmpipe 4
  // samples make a frame 2.7 to 3.9 times slower (bench/render, msaa_ratio); View > Smooth edges.
  int samples = 1;
};

// The camera as the mouse moves it: a named view turned by azimuth/elevation, zoomed, and panned
// in the screen plane (pan in fractions of the model size).
struct ViewState {
  render::ViewSpec spec;
  double pan_right = 0.0;
  double pan_up = 0.0;
};

struct ProbeResult {
  int node = -1;  // node index
  Id node_id = 0;
  Vec3 position{};              // undeformed coordinates
  std::optional<double> value;  // the contour field at the node, when a field is shown
  std::string field;
};

// The integration-point values of the element under the cursor (integration-point display).
struct ElementProbe {
  int element = -1;
  Id element_id = 0;
  std::string type;
  std::string field;
  std::vector<render::PointValue> points;
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

  // The scale of the results' deformation, and the one drawn now (an animation frame draws a
  // fraction of it, set_deformation_fraction()).
  double deformation_scale() const { return scale_; }
  double drawn_scale() const { return fraction_ * scale_; }
  // Redraws the deformed shape at `fraction` (0..1) of deformation_scale() without rebuilding the
  // skin or the field; the camera box stays the one of the whole deformation.
  void set_deformation_fraction(double fraction);
  // The box the camera fits: the undeformed and the fully deformed shape, relative to the origin.
  const std::array<std::array<float, 3>, 2>& camera_box() const { return camera_box_; }

  // What is selected, drawn as markers over the model (overlay triangles, see highlight.hpp).
  void set_selection(Selection selection) { selection_ = std::move(selection); }
  const Selection& selection() const { return selection_; }

  // For picking and highlighting: the drawn skin, the model, where a node is drawn.
  const render::SkinModel* skin() const { return skin_.get(); }
  const Model* model() const { return model_; }
  const render::Frame& last_frame() const { return frame_; }
  // Increases whenever the vertex arrays change (rebuild, deformation fraction): a view that
  // keeps the geometry in GL buffers uploads it again when this moves.
  long geometry_revision() const { return geometry_revision_; }
  // Deformed position relative to the geometry origin, at the drawn scale.
  Vec3 placed(int node) const;
  // Pixel position (top-left origin, continuous: pixel (i, j) spans [i, i+1) x [j, j+1)) and
  // normalised depth (-1 near .. 1 far) of a node in the last frame().
  std::array<double, 3> screen_position(int node) const;
  const render::ScalarField* field() const { return field_ ? &*field_ : nullptr; }
  const render::PointField* point_field() const { return point_field_ ? &*point_field_ : nullptr; }
  // The unrolled map shown instead of the 3D view (DisplaySettings::unrolled), if any.
  const render::UnrolledSurface* unrolled() const { return unrolled_ ? &*unrolled_ : nullptr; }
  // Whether only the faces carrying a surface field are drawn, and the title block's note when
  // that was chosen because they were hidden.
  bool field_faces_only() const { return field_faces_only_; }
  const std::string& note() const { return note_; }
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
  // With integration-point values shown: those of element `element` (index), numbered as the
  // rule orders them; empty otherwise.
  std::optional<ElementProbe> element_probe(int element) const;

 private:
  void build_geometry();
  void build_map();
  void choose_field_faces(const render::Camera& camera, double aspect);
  void update_title();
  void fit_camera_box();

  const Model* model_ = nullptr;
  const IncrementResult* increment_ = nullptr;
  std::unique_ptr<render::SkinModel> skin_;
  std::optional<render::ScalarField> field_;
  std::optional<render::PointField> point_field_;
  render::ColorScale colors_;
  DisplaySettings settings_;
  const ElementRegistry* registry_ = nullptr;
  bool field_faces_only_ = false;
  bool faces_decided_ = true;  // the Auto choice is made on the first frame after a rebuild
  std::string note_;
  std::optional<render::UnrolledSurface> unrolled_;
  render::FrameGeometry map_;
  double scale_ = 0.0;
  double fraction_ = 1.0;
  long geometry_revision_ = 0;
  render::GeometryRequest request_;  // without displacement and scale (set per build)
  std::array<std::array<float, 3>, 2> camera_box_{};
  Selection selection_;
  std::vector<std::string> title_lines_;
  std::string model_name_;
  std::string legend_heading_;
  std::vector<int> visible_nodes_;
  render::Frame frame_;
  std::unique_ptr<render::Typeface> typeface_;  // the overlay's font, loaded on the first frame
};

}  // namespace styk::gui
