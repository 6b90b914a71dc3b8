#include "styk/render/render_job.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "styk/core/diagnostics.hpp"

namespace styk::render {
namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string base_name(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::vector<Layer> make_layers(const Model& model, const RenderOptions& options) {
  std::vector<Layer> layers = options.layers.empty() ? std::vector<Layer>{whole_model_layer(model)}
                                                     : layers_from_sets(model, options.layers);
  for (const std::string& hidden : options.hidden_layers) {
    const auto it = std::find_if(layers.begin(), layers.end(),
                                 [&](const Layer& l) { return l.name == to_upper(hidden); });
    if (it == layers.end()) {
      std::string known;
      for (const Layer& l : layers) known += (known.empty() ? "" : ", ") + l.name;
      throw InputError({}, "cannot hide layer '" + hidden + "': it is not shown; layers: " + known);
    }
    it->visible = false;
  }
  return layers;
}

void grow_bounds(std::array<float, 3>& lo, std::array<float, 3>& hi, const Vec3& p) {
  for (int k = 0; k < 3; ++k)
    lo[k] = std::min(lo[k], float(p[k])), hi[k] = std::max(hi[k], float(p[k]));
}

}  // namespace

DisplayMode parse_display_mode(const std::string& text) {
  const std::string t = lower(text);
  if (t == "points" || t == "nodes") return DisplayMode::Points;
  if (t == "wireframe" || t == "wire") return DisplayMode::Wireframe;
  if (t == "hidden" || t == "hidden-line") return DisplayMode::HiddenLine;
  if (t == "shaded") return DisplayMode::Shaded;
  if (t == "shaded-edges" || t == "edges") return DisplayMode::ShadedEdges;
  throw InputError({}, "unknown display mode '" + text +
                           "'; modes: points, wireframe, hidden, shaded, shaded-edges");
}

std::string display_mode_name(DisplayMode mode) {
  switch (mode) {
    case DisplayMode::Points:
      return "points";
    case DisplayMode::Wireframe:
      return "wireframe";
    case DisplayMode::HiddenLine:
      return "hidden";
    case DisplayMode::Shaded:
      return "shaded";
    case DisplayMode::ShadedEdges:
      return "shaded-edges";
  }
  return "?";
}

DeformSpec parse_deform(const std::string& text) {
  DeformSpec spec;
  const std::string t = lower(text);
  if (t == "auto") {
    spec.kind = DeformSpec::Kind::Auto;
    return spec;
  }
  if (t == "none" || t.empty()) return spec;
  errno = 0;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (*end != '\0' || errno == ERANGE || !std::isfinite(value) || value < 0)
    throw InputError({}, "bad deformation scale '" + text + "'; use auto, none or a number >= 0");
  if (value > 0) spec.kind = DeformSpec::Kind::Factor, spec.factor = value;
  return spec;
}

RenderJob::RenderJob(const Model& section, const ElementRegistry& registry,
                     const IncrementResult* increment, RenderOptions options)
    : model_(&section), increment_(increment), options_(std::move(options)) {
  if (options_.width < 16 || options_.height < 16 || options_.width > 16384 ||
      options_.height > 16384)
    throw InputError({}, "picture size " + std::to_string(options_.width) + "x" +
                             std::to_string(options_.height) + " is outside 16..16384 pixels");
  check_band_count(options_.bands);
  check_view_name(options_.view.name);
  if (!(options_.view.zoom > 0)) throw InputError({}, "zoom must be > 0");
  std::unique_ptr<ScalarField> section_field = revolve(section, registry);
  const Model& model = *model_;

  skin_ =
      std::make_unique<SkinModel>(model, registry, make_layers(model, options_), options_.filter);
  if (skin_->visible_nodes().empty())
    throw InputError({},
                     "nothing to draw: the shown layers and the element filter select no element");

  if (!options_.field.empty()) {
    if (!increment_)
      throw InputError({}, "field '" + options_.field +
                               "' needs a results file; this input is a "
                               "mesh only");
    field_ = section_field ? std::move(section_field)
                           : std::make_unique<ScalarField>(evaluate_field(
                                 model, *increment_, options_.field, options_.averaging));
    if (!field_->defined.empty()) {
      const std::vector<int> shown = skin_->visible_nodes();
      if (std::none_of(shown.begin(), shown.end(), [&](int n) { return field_->defined_at(n); }))
        throw InputError({}, "field '" + field_->name +
                                 "' has no value at the nodes shown (for contact output: the "
                                 "slave surfaces are hidden or filtered out)");
    }
    const std::array<double, 2> range = field_range(*skin_, *field_);
    colors_ = color_scale_for(*field_, range, options_.bands, options_.smooth);
  }

  // A steady heat / electric-potential increment has no displacements: the automatic default
  // draws it undeformed (an explicit factor still asks for U and is refused below).
  const bool scalar_only = increment_ && increment_->U.empty() &&
                           increment_->scalar.kind != ScalarFieldResult::Kind::None;
  if (options_.deform.kind != DeformSpec::Kind::None &&
      !(scalar_only && options_.deform.kind == DeformSpec::Kind::Auto)) {
    if (!increment_)
      throw InputError({}, "a deformed shape needs a results file; this input is a mesh only");
    if (increment_->U.size() != model.coords.size())
      throw InputError({}, "step " + std::to_string(increment_->step) + " increment " +
                               std::to_string(increment_->increment) +
                               " holds no displacements (U) to deform the shape with");
    if (options_.deform.kind == DeformSpec::Kind::Factor) {
      scale_ = options_.deform.factor;
    } else {
      const double largest = max_displacement(*increment_, skin_->visible_nodes());
      scale_ = largest > 0 ? options_.deform.auto_fraction * skin_->size() / largest : 0.0;
    }
  }

  OverlayContent content;
  content.title_lines = title_lines();
  if (field_) {
    content.colors = &colors_;
    content.legend_heading =
        field_->name +
        (field_->uses_averaging ? " (" + averaging_name(options_.averaging) + ")" : "");
  }
  overlay_ = build_overlay(content, options_.width, options_.height);

  // One camera for every fraction of the deformation: fit the undeformed and the full shape.
  const float big = std::numeric_limits<float>::max();
  std::array<float, 3> lo{big, big, big}, hi{-big, -big, -big};
  const Vec3 c = skin_->centre();
  const bool fit_field_faces = options_.only_field_faces && field_ && !field_->defined.empty();
  for (int n : skin_->visible_nodes()) {
    if (fit_field_faces && !field_->defined_at(n)) continue;  // only those faces are drawn
    const Vec3& x = model.coords[n];
    grow_bounds(lo, hi, Vec3{x[0] - c[0], x[1] - c[1], x[2] - c[2]});
    if (scale_ > 0) {
      const Vec3& u = increment_->U[n];
      grow_bounds(lo, hi,
                  Vec3{x[0] - c[0] + scale_ * u[0], x[1] - c[1] + scale_ * u[1],
                       x[2] - c[2] + scale_ * u[2]});
    }
  }
  camera_ = fit_camera(options_.view, lo, hi,
                       double(overlay_.model.width) / double(overlay_.model.height));
}

RenderJob::~RenderJob() = default;

std::unique_ptr<ScalarField> RenderJob::revolve(const Model& section,
                                                const ElementRegistry& registry) {
  if (!(options_.revolve_degrees > 0)) return nullptr;
  const ElementFilter all;
  if (!options_.layers.empty() || options_.filter.id_min != all.id_min ||
      options_.filter.id_max != all.id_max || !options_.filter.types.empty())
    throw InputError({}, "layers and element filters name the section's elements: they cannot "
                         "be combined with a revolved picture");
  // The field is evaluated on the section, with its own elements' stress recovery, then carried
  // round.
  std::unique_ptr<ScalarField> field;
  if (!options_.field.empty() && increment_)
    field = std::make_unique<ScalarField>(
        evaluate_field(section, *increment_, options_.field, options_.averaging));
  const int segments = options_.revolve_segments > 0
                           ? options_.revolve_segments
                           : std::max(1, static_cast<int>(std::ceil(options_.revolve_degrees / 15.0)));
  revolved_ = std::make_unique<RevolvedModel>(
      revolve_axisymmetric(section, registry, increment_, options_.revolve_degrees, segments));
  if (field) *field = revolve_field(*field, section, *revolved_);
  if (increment_) {
    revolved_increment_ = std::make_unique<IncrementResult>();
    revolved_increment_->step = increment_->step;
    revolved_increment_->increment = increment_->increment;
    revolved_increment_->step_time = increment_->step_time;
    revolved_increment_->total_time = increment_->total_time;
    revolved_increment_->U = revolved_->U;
    increment_ = revolved_increment_.get();
  }
  model_ = &revolved_->model;
  return field;
}

std::vector<std::string> RenderJob::title_lines() const {
  std::vector<std::string> lines;
  const std::string name = !options_.model_name.empty() ? options_.model_name
                           : !model_->source.empty()    ? base_name(model_->source)
                                                        : std::string("(unnamed model)");
  lines.push_back("Model: " + name);
  if (increment_) {
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, "Step %d  Increment %d  Step time %.4g  Total time %.4g",
                  increment_->step, increment_->increment, increment_->step_time,
                  increment_->total_time);
    lines.push_back(buffer);
  }
  if (field_ && !field_->categories.empty()) {
    // A discrete field: how many visible nodes are in each category.
    std::vector<int> counts(field_->categories.size(), 0);
    for (int n : skin_->visible_nodes())
      if (field_->defined_at(n)) {
        const auto k = static_cast<std::size_t>(field_->values[n]);
        if (k < counts.size()) ++counts[k];
      }
    std::string line = "Field: " + field_->name + "  Nodes:";
    for (std::size_t k = 0; k < counts.size(); ++k)
      line += " " + field_->categories[k] + " " + std::to_string(counts[k]);
    lines.push_back(line);
  } else if (field_) {
    lines.push_back("Field: " + field_->name +
                    (field_->uses_averaging ? "  Averaging: " + averaging_name(options_.averaging)
                                            : std::string()) +
                    "  Min: " + format_legend_value(colors_.min) +
                    "  Max: " + format_legend_value(colors_.max));
  } else {
    lines.push_back("Mesh: " + std::to_string(model_->elements.size()) + " elements, " +
                    std::to_string(model_->coords.size()) + " nodes");
  }
  if (options_.deform.kind != DeformSpec::Kind::None)
    lines.push_back("Deformation scale: " + format_legend_value(scale_) +
                    (options_.deform.kind == DeformSpec::Kind::Auto ? " (auto)" : ""));
  else if (increment_)
    lines.push_back("Undeformed shape");
  return lines;
}

Frame RenderJob::frame(double fraction) const {
  Frame frame;
  frame.width = options_.width;
  frame.height = options_.height;
  frame.mode = options_.mode;
  GeometryRequest request;
  const double scale = fraction * scale_;
  if (scale > 0) {
    request.displacement = &increment_->U;
    request.scale = scale;
    request.outline = options_.undeformed_outline;
  }
  request.field = field_.get();
  request.colors = field_ ? &colors_ : nullptr;
  request.hide_undefined_faces = options_.only_field_faces;
  request.points = options_.mode == DisplayMode::Points;
  frame.geometry = build_geometry(*skin_, request);
  frame.camera = camera_;
  frame.overlay = overlay_;
  frame.has_field = static_cast<bool>(field_);
  frame.colors = colors_;
  frame.point_size = float(std::max(2, text_scale_for(options_.height) + 1));
  frame.bar_width = frame.point_size + 1.0f;  // a bar stands out from the 1 px mesh lines
  return frame;
}

}  // namespace styk::render
