// The renderer's front door: a model (and optionally one increment of results) plus the options
// of `styk render`, validated once, then turned into frames (one, or a deformation animation).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "styk/core/element_registry.hpp"
#include "styk/core/model.hpp"
#include "styk/core/results.hpp"
#include "styk/render/camera.hpp"
#include "styk/render/field.hpp"
#include "styk/render/frame.hpp"
#include "styk/render/geometry.hpp"
#include "styk/render/layers.hpp"
#include "styk/render/revolve.hpp"

namespace styk::render {

struct DeformSpec {
  enum class Kind { None, Auto, Factor };
  Kind kind = Kind::None;
  double factor = 1.0;         // Kind::Factor
  double auto_fraction = 0.1;  // Kind::Auto: largest displacement = this fraction of the model size
};

// "auto", "none", "0" or a number; InputError otherwise.
DeformSpec parse_deform(const std::string& text);

struct RenderOptions {
  int width = 1600;
  int height = 1200;
  DisplayMode mode = DisplayMode::Shaded;
  std::string field;  // empty: no contour (layer colours)
  Averaging averaging = Averaging::MethodII;
  int bands = kDefaultBands;
  bool smooth = false;
  // A field with values at some nodes only (contact fields: the slave nodes) colours the faces it
  // covers; the other faces are drawn neutral grey, or not at all when this is set.
  bool only_field_faces = false;
  DeformSpec deform;
  bool undeformed_outline = true;  // with a deformed shape, draw the undeformed outline
  ViewSpec view;
  std::vector<std::string> layers;         // element set names; empty: the whole model, one layer
  std::vector<std::string> hidden_layers;  // among `layers`: built but not shown
  ElementFilter filter;
  std::string model_name;  // title block; empty: the model's source file name
  // > 0: draw the axisymmetric elements as the body they stand for, swept about the y axis
  // through this many degrees (revolve.hpp); segments 0 = one per 15 degrees.
  double revolve_degrees = 0.0;
  int revolve_segments = 0;
};

class RenderJob {
 public:
  // `increment` may be null (mesh only: asking for a field or a deformation is then an error).
  // Everything the options name (field, layers, view, bands) is checked here: InputError.
  // model, registry and increment must outlive the job.
  RenderJob(const Model& model, const ElementRegistry& registry, const IncrementResult* increment,
            RenderOptions options);
  ~RenderJob();

  // The picture at `fraction` of the deformation scale (1 = the full scale; an animation runs
  // 0..1). The camera is the same for every fraction: it fits the undeformed and the fully
  // deformed shape.
  Frame frame(double fraction = 1.0) const;

  double deformation_scale() const { return scale_; }
  bool has_field() const { return static_cast<bool>(field_); }
  const ColorScale& colors() const { return colors_; }
  const ScalarField* field() const { return field_.get(); }
  const SkinModel& skin() const { return *skin_; }
  const RenderOptions& options() const { return options_; }

 private:
  std::vector<std::string> title_lines() const;
  // With RenderOptions::revolve_degrees: sweeps the section into its body (model_, increment_
  // then point at the revolved ones) and returns the field evaluated on the section and carried
  // round (null without a field); null and nothing changed otherwise.
  std::unique_ptr<ScalarField> revolve(const Model& section, const ElementRegistry& registry);

  const Model* model_;  // the model drawn: the given one, or its revolved body
  const IncrementResult* increment_;
  std::unique_ptr<RevolvedModel> revolved_;
  std::unique_ptr<IncrementResult> revolved_increment_;
  RenderOptions options_;
  std::unique_ptr<SkinModel> skin_;
  std::unique_ptr<ScalarField> field_;
  ColorScale colors_;
  double scale_ = 0.0;
  Camera camera_;
  Overlay overlay_;
};

}  // namespace styk::render
