// The renderer's front door: a model (and optionally one increment of results) plus the options
// of `styk render`, validated once, then turned into frames (one, or a deformation animation).
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"
#include "styk/core/results.hpp"
#include "styk/render/annotations.hpp"
#include "styk/render/camera.hpp"
#include "styk/render/field.hpp"
#include "styk/render/font.hpp"
#include "styk/render/frame.hpp"
#include "styk/render/geometry.hpp"
#include "styk/render/layers.hpp"
#include "styk/render/point_field.hpp"
#include "styk/render/revolve.hpp"
#include "styk/render/unroll.hpp"

namespace styk::render {

struct DeformSpec {
  enum class Kind { None, Auto, Factor };
  Kind kind = Kind::None;
  double factor = 1.0;         // Kind::Factor
  double auto_fraction = 0.1;  // Kind::Auto: largest displacement = this fraction of the model size
};

// "auto", "none", "0" or a number; InputError otherwise.
DeformSpec parse_deform(const std::string& text);

// Which faces a field that lives on surfaces (contact output) is drawn with.
enum class FieldFaces {
  Auto,  // all faces, those that do not carry it grey; when the faces that carry it are hidden
         // in the view (a slave surface under its master body), those faces alone, with a note
         // in the title block
  Only,  // the faces that carry it alone (--contact-only)
  All,   // all faces, whether or not the field's faces can be seen (--all-faces)
};

struct RenderOptions {
  int width = 1600;
  int height = 1200;
  DisplayMode mode = DisplayMode::Shaded;
  std::string field;  // empty: no contour (layer colours)
  Averaging averaging = Averaging::MethodII;
  int bands = kDefaultBands;
  bool smooth = false;
  // The colour scale's ends; empty: the field's minimum and maximum over the visible elements.
  std::optional<std::array<double, 2>> range;
  FieldFaces field_faces = FieldFaces::Auto;
  std::string contact_pair;  // a slave surface: that *CONTACT PAIR's output only (contact fields)
  bool ip_values = false;    // the field at the integration points, as coloured points
  LabelRequest labels;       // node / element numbers
  // Unrolled contact map instead of the 3D view (a field on surfaces); the axis fitted or given.
  bool unroll = false;
  std::optional<UnrollAxis> unroll_axis;
  DeformSpec deform;
  bool undeformed_outline = true;  // with a deformed shape, draw the undeformed outline
  ViewSpec view;
  std::vector<std::string> layers;         // element set names; empty: the whole model, one layer
  std::vector<std::string> hidden_layers;  // among `layers`: built but not shown
  ElementFilter filter;
  std::string model_name;  // title block; empty: the model's source file name
  int samples = 4;         // multisampling of the scene's edges, 1..16 (1 = none)
  // The fibre whose stress / strain colours the shells (docs/render.md "Shells").
  ShellFibre shell_fibre = ShellFibre::Top;
  // > 0: draw the axisymmetric elements as the body they stand for, swept about the y axis
  // through this many degrees (revolve.hpp); segments 0 = one per 15 degrees.
  double revolve_degrees = 0.0;
  int revolve_segments = 0;
};

class RenderJob {
 public:
  // `increment` may be null (mesh only: asking for a field or a deformation is then an error).
  // Everything the options name (field, layers, view, bands, range, pair, axis) is checked here:
  // InputError. model, registry and increment must outlive the job.
  RenderJob(const Model& model, const ElementRegistry& registry, const IncrementResult* increment,
            RenderOptions options);
  ~RenderJob();

  // The picture at `fraction` of the deformation scale (1 = the full scale; an animation runs
  // 0..1). The camera is the same for every fraction: it fits the undeformed and the fully
  // deformed shape. An unrolled map is the same at every fraction.
  Frame frame(double fraction = 1.0) const;

  double deformation_scale() const { return scale_; }
  bool has_field() const { return static_cast<bool>(field_) || static_cast<bool>(point_field_); }
  const ColorScale& colors() const { return colors_; }
  const ScalarField* field() const { return field_.get(); }
  const PointField* point_field() const { return point_field_.get(); }
  const SkinModel& skin() const { return *skin_; }
  const RenderOptions& options() const { return options_; }
  // Whether only the faces that carry the field are drawn (asked for, or chosen because they
  // were hidden in the view), and the note the title block then carries.
  bool field_faces_only() const { return field_faces_only_; }
  const std::string& note() const { return note_; }
  // The unrolled surface (options().unroll).
  const UnrolledSurface* unrolled() const { return unrolled_ ? &*unrolled_ : nullptr; }

 private:
  void check_options() const;
  // The field asked for; `revolved` is the field already evaluated on a revolved section.
  void evaluate_fields(std::unique_ptr<ScalarField> revolved);
  void choose_field_faces();
  std::vector<std::string> title_lines() const;
  std::string legend_heading() const;
  // "top fibre" etc. when the field colours shells by their fibre tensors; "" otherwise.
  std::string shell_fibre_text() const;
  GeometryRequest request(double fraction) const;
  Camera fit(const PixelRect& area) const;
  void build_map();
  // With RenderOptions::revolve_degrees: sweeps the section into its body (model_, increment_
  // then point at the revolved ones) and returns the field evaluated on the section and carried
  // round (null without a field); null and nothing changed otherwise.
  std::unique_ptr<ScalarField> revolve(const Model& section, const ElementRegistry& registry);

  const Model* model_;  // the model drawn: the given one, or its revolved body
  const IncrementResult* increment_;
  std::unique_ptr<RevolvedModel> revolved_;
  std::unique_ptr<IncrementResult> revolved_increment_;
  RenderOptions options_;
  std::unique_ptr<Typeface> typeface_;
  std::unique_ptr<SkinModel> skin_;
  std::unique_ptr<ScalarField> field_;
  std::unique_ptr<PointField> point_field_;
  ColorScale colors_;
  std::array<double, 2> field_min_max_{};  // of the field over the visible elements
  double scale_ = 0.0;
  bool field_faces_only_ = false;
  std::string note_;
  Camera camera_;
  Overlay overlay_;
  std::optional<UnrolledSurface> unrolled_;
  FrameGeometry map_;  // the unrolled map's geometry
};

}  // namespace styk::render
