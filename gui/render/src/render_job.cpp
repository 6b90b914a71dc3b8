#include "styk/render/render_job.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "styk/core/diagnostics.hpp"
#include "styk/render/visibility.hpp"

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
  check_options();
  typeface_ = std::make_unique<Typeface>();
  std::unique_ptr<ScalarField> section_field = revolve(section, registry);
  const Model& model = *model_;
  skin_ =
      std::make_unique<SkinModel>(model, registry, make_layers(model, options_), options_.filter);
  if (skin_->visible_nodes().empty())
    throw InputError({},
                     "nothing to draw: the shown layers and the element filter select no element");
  evaluate_fields(std::move(section_field));

  // A steady heat / electric-potential increment has no displacements: the automatic default
  // draws it undeformed (an explicit factor still asks for U and is refused below).
  const bool scalar_only = increment_ && increment_->U.empty() &&
                           increment_->scalar.kind != ScalarFieldResult::Kind::None;
  if (options_.deform.kind != DeformSpec::Kind::None && !options_.unroll &&
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
  if (options_.unroll) {
    build_map();
    return;
  }
  field_faces_only_ = options_.field_faces == FieldFaces::Only && field_ && field_->on_surfaces();
  if (options_.field_faces == FieldFaces::Only && field_ && !field_->defined.empty())
    field_faces_only_ = true;
  choose_field_faces();
}

RenderJob::~RenderJob() = default;

void RenderJob::check_options() const {
  const RenderOptions& o = options_;
  if (o.width < 16 || o.height < 16 || o.width > 16384 || o.height > 16384)
    throw InputError({}, "picture size " + std::to_string(o.width) + "x" +
                             std::to_string(o.height) + " is outside 16..16384 pixels");
  check_band_count(o.bands);
  check_view_name(o.view.name);
  if (!(o.view.zoom > 0)) throw InputError({}, "zoom must be > 0");
  if (o.samples < 1 || o.samples > 16)
    throw InputError({}, "samples per pixel must be 1..16, not " + std::to_string(o.samples));
  if (o.range && !(std::isfinite((*o.range)[0]) && std::isfinite((*o.range)[1]) &&
                   (*o.range)[0] < (*o.range)[1]))
    throw InputError({}, "the colour range needs MIN < MAX");
  if ((o.range || o.ip_values || o.unroll || !o.contact_pair.empty()) && o.field.empty())
    throw InputError({}, std::string(o.range       ? "--range"
                                     : o.ip_values ? "--ip-values"
                                     : o.unroll    ? "--unroll"
                                                   : "--contact-pair") +
                             " needs a field (--field)");
  if (o.unroll && o.ip_values)
    throw InputError({}, "--ip-values draws points in the 3D view, not on the unrolled map");
  if (o.unroll && (o.labels.nodes || o.labels.elements))
    throw InputError({}, "--labels are drawn in the 3D view, not on the unrolled map");
  if (o.unroll && o.mode != DisplayMode::Shaded && o.mode != DisplayMode::ShadedEdges)
    throw InputError({}, "the unrolled map is drawn shaded (--mode shaded or shaded-edges), not " +
                             display_mode_name(o.mode));
  if (o.unroll_axis && !o.unroll) throw InputError({}, "--unroll-axis needs --unroll");
}

void RenderJob::evaluate_fields(std::unique_ptr<ScalarField> revolved) {
  if (options_.field.empty()) return;
  if (!increment_)
    throw InputError({}, "field '" + options_.field +
                             "' needs a results file; this input is a "
                             "mesh only");
  std::array<double, 2> range{};
  if (options_.ip_values) {
    if (!options_.contact_pair.empty())
      throw InputError({}, "--contact-pair applies to contact fields, not to --ip-values");
    point_field_ =
        std::make_unique<PointField>(evaluate_point_field(*model_, *increment_, options_.field));
    range = point_field_range(*skin_, *point_field_);
    colors_ = ColorScale{range[0], range[1], options_.bands, options_.smooth};
  } else {
    field_ =
        revolved
            ? std::move(revolved)
            : std::make_unique<ScalarField>(evaluate_field(
                  *model_, *increment_, options_.field, options_.averaging, options_.contact_pair));
    if (!options_.contact_pair.empty() && field_->defined.empty())
      throw InputError({},
                       "--contact-pair applies to contact fields (CPRESS, CSHEAR, CSLIP, "
                       "CGAP, CSTATUS), not to " +
                           field_->name);
    if (!field_->defined.empty()) {
      const std::vector<int> shown = skin_->visible_nodes();
      if (std::none_of(shown.begin(), shown.end(), [&](int n) { return field_->defined_at(n); }))
        throw InputError({}, "field '" + field_->name +
                                 "' has no value at the nodes shown (for contact output: the "
                                 "slave surfaces are hidden or filtered out)");
    }
    if (options_.unroll && field_->defined.empty())
      throw InputError({},
                       "--unroll lays out a field that lives on surfaces (contact output: "
                       "CPRESS, CSHEAR, CSLIP, CGAP, CSTATUS), not " +
                           field_->name);
    field_->shell_fibre = options_.shell_fibre;
    range = field_range(*skin_, *field_);
    colors_ = color_scale_for(*field_, range, options_.bands, options_.smooth);
  }
  field_min_max_ = range;
  if (options_.range && colors_.labels.empty()) {
    colors_.min = (*options_.range)[0];
    colors_.max = (*options_.range)[1];
  }
}

GeometryRequest RenderJob::request(double fraction) const {
  GeometryRequest request;
  const double scale = fraction * scale_;
  if (scale > 0) {
    request.displacement = &increment_->U;
    request.scale = scale;
    request.outline = options_.undeformed_outline;
    if (!increment_->UR.empty()) request.rotation = &increment_->UR;  // beams turn their sections
  }
  request.field = field_.get();
  request.colors = field_ ? &colors_ : nullptr;
  request.hide_undefined_faces = field_faces_only_;
  request.points = options_.mode == DisplayMode::Points;
  return request;
}

// The camera for the model area: it fits the undeformed and the fully deformed shape of the
// visible nodes (only those where the field has a value when only its faces are drawn).
Camera RenderJob::fit(const PixelRect& area) const {
  const float big = std::numeric_limits<float>::max();
  std::array<float, 3> lo{big, big, big}, hi{-big, -big, -big};
  const Vec3 c = skin_->centre();
  for (int n : skin_->visible_nodes()) {
    if (field_faces_only_ && !field_->defined_at(n)) continue;  // only those faces are drawn
    const Vec3& x = model_->coords[n];
    grow_bounds(lo, hi, Vec3{x[0] - c[0], x[1] - c[1], x[2] - c[2]});
    if (scale_ > 0) {
      const Vec3& u = increment_->U[n];
      grow_bounds(lo, hi,
                  Vec3{x[0] - c[0] + scale_ * u[0], x[1] - c[1] + scale_ * u[1],
                       x[2] - c[2] + scale_ * u[2]});
    }
  }
  return fit_camera(options_.view, lo, hi, double(area.width) / double(area.height));
}

// With FieldFaces::Auto, a field on surfaces whose faces cannot be seen in this view (under the
// other body of a fit) is drawn on its faces alone, with a note in the title block.
void RenderJob::choose_field_faces() {
  OverlayContent content;
  const auto overlay = [&] {
    content.title_lines = title_lines();
    if (field_ || point_field_) {
      content.colors = &colors_;
      content.legend_heading = legend_heading();
    }
    content.label_glyphs = options_.labels.nodes || options_.labels.elements;
    overlay_ = build_overlay(content, options_.width, options_.height, *typeface_);
    camera_ = fit(overlay_.model);
  };
  overlay();
  if (options_.field_faces != FieldFaces::Auto || !field_ || !field_->on_surfaces()) return;
  const FrameGeometry whole = build_geometry(*skin_, request(1.0));
  const double seen =
      field_faces_seen(whole, camera_, double(overlay_.model.width) / overlay_.model.height);
  if (seen >= kHiddenFieldFaces) return;
  field_faces_only_ = true;
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "%s on its faces alone: hidden in this view (%.0f %% seen)",
                field_->name.c_str(), 100.0 * seen);
  note_ = buffer;
  overlay();
}

std::string RenderJob::legend_heading() const {
  if (point_field_) return point_field_->name + " (integration points)";
  const std::string fibre = shell_fibre_text();
  return field_->name + (field_->uses_averaging ? " (" + averaging_name(options_.averaging) +
                                                      (fibre.empty() ? "" : ", " + fibre) + ")"
                                                : "");
}

std::string RenderJob::shell_fibre_text() const {
  if (!field_ || !field_->tensor_value || field_->point_offset.empty() || field_->station_values)
    return "";
  for (const SkinModel::LayerSkin& layer : skin_->layers())
    if (!layer.shells.empty()) return "shells: " + shell_fibre_name(field_->shell_fibre) + " fibre";
  return "";
}

void RenderJob::build_map() {
  GeometryRequest faces_request;
  faces_request.field = field_.get();
  faces_request.colors = &colors_;
  faces_request.hide_undefined_faces = true;
  faces_request.points = false;
  const FrameGeometry faces = build_geometry(*skin_, faces_request);
  unrolled_ = fit_unrolled_surface(faces, skin_->centre(), options_.unroll_axis);
  map_ = unroll_geometry(faces, skin_->centre(), *unrolled_);
  field_faces_only_ = true;
  OverlayContent content;
  content.title_lines = title_lines();
  content.colors = &colors_;
  content.legend_heading = legend_heading();
  overlay_ = build_overlay(content, options_.width, options_.height, *typeface_);
  reserve_map_area(overlay_, *typeface_, *unrolled_, options_.height);
  ViewSpec view;
  view.name = "+z";
  camera_ = fit_camera(view, map_.lower, map_.upper,
                       double(overlay_.model.width) / double(overlay_.model.height));
  add_map_axes(overlay_, *typeface_, camera_, *unrolled_, options_.height);
}

std::unique_ptr<ScalarField> RenderJob::revolve(const Model& section,
                                                const ElementRegistry& registry) {
  if (!(options_.revolve_degrees > 0)) return nullptr;
  const ElementFilter all;
  if (!options_.layers.empty() || options_.filter.id_min != all.id_min ||
      options_.filter.id_max != all.id_max || !options_.filter.types.empty())
    throw InputError({},
                     "layers and element filters name the section's elements: they cannot "
                     "be combined with a revolved picture");
  if (options_.unroll || options_.ip_values || !options_.contact_pair.empty())
    throw InputError({},
                     "--unroll, --ip-values and --contact-pair draw the section's own "
                     "elements: they cannot be combined with a revolved picture");
  // The field is evaluated on the section, with its own elements' stress recovery, then carried
  // round.
  std::unique_ptr<ScalarField> field;
  if (!options_.field.empty() && increment_)
    field = std::make_unique<ScalarField>(
        evaluate_field(section, *increment_, options_.field, options_.averaging));
  const int segments =
      options_.revolve_segments > 0
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
  const std::string pair =
      options_.contact_pair.empty() ? "" : "  Pair: " + to_upper(options_.contact_pair);
  if (field_ && !field_->categories.empty()) {
    // A discrete field: how many visible nodes are in each category.
    std::vector<int> counts(field_->categories.size(), 0);
    for (int n : skin_->visible_nodes())
      if (field_->defined_at(n)) {
        const auto k = static_cast<std::size_t>(field_->values[n]);
        if (k < counts.size()) ++counts[k];
      }
    std::string line = "Field: " + field_->name + pair + "  Nodes:";
    for (std::size_t k = 0; k < counts.size(); ++k)
      line += " " + field_->categories[k] + " " + std::to_string(counts[k]);
    lines.push_back(line);
  } else if (field_ || point_field_) {
    const NumberFormat format = number_format(colors_);
    const std::string where =
        point_field_ ? "  at " + std::to_string(visible_point_count(*skin_, *point_field_)) +
                           " integration points"
        : field_->uses_averaging ? "  Averaging: " + averaging_name(options_.averaging)
                                 : std::string();
    const std::string fibre = shell_fibre_text();
    lines.push_back("Field: " + (point_field_ ? point_field_->name : field_->name) + where +
                    (fibre.empty() ? "" : "  (" + fibre + ")") + pair +
                    "  Min: " + format(field_min_max_[0]) + "  Max: " + format(field_min_max_[1]) +
                    (options_.range
                         ? "  (scale " + format(colors_.min) + " to " + format(colors_.max) + ")"
                         : std::string()));
  } else {
    lines.push_back("Mesh: " + std::to_string(model_->elements.size()) + " elements, " +
                    std::to_string(model_->coords.size()) + " nodes");
  }
  if (unrolled_) {
    char buffer[200];
    const UnrolledSurface& u = *unrolled_;
    if (u.kind == UnrolledSurface::Kind::Revolved)
      std::snprintf(buffer, sizeof buffer,
                    "Unrolled about the axis through (%.4g, %.4g, %.4g) along (%.4g, %.4g, %.4g)"
                    "%s, radius %.4g",
                    u.axis.point[0], u.axis.point[1], u.axis.point[2], u.axis.direction[0],
                    u.axis.direction[1], u.axis.direction[2], u.axis_given ? " (given)" : "",
                    u.radius);
    else
      std::snprintf(buffer, sizeof buffer,
                    "Flat: the plane through (%.4g, %.4g, %.4g), normal (%.4g, %.4g, %.4g)",
                    u.axis.point[0], u.axis.point[1], u.axis.point[2], u.axis.direction[0],
                    u.axis.direction[1], u.axis.direction[2]);
    lines.push_back(buffer);
  } else if (options_.deform.kind != DeformSpec::Kind::None && scale_ > 0) {
    lines.push_back("Deformation scale: " + format_legend_value(scale_) +
                    (options_.deform.kind == DeformSpec::Kind::Auto ? " (auto)" : ""));
  } else if (increment_) {
    lines.push_back("Undeformed shape");
  }
  if (!note_.empty()) lines.push_back(note_);
  return lines;
}

Frame RenderJob::frame(double fraction) const {
  Frame frame;
  frame.width = options_.width;
  frame.height = options_.height;
  frame.mode = options_.mode;
  frame.samples = options_.samples;
  frame.camera = camera_;
  frame.overlay = overlay_;
  frame.has_field = has_field();
  frame.colors = colors_;
  const float unit = float(std::max(2, pixel_scale_for(options_.height) + 1));
  frame.bar_width = unit + 1.0f;  // a bar stands out from the 1 px mesh lines
  // Multisampled points spread over the pixels they touch: one pixel more keeps them dark.
  frame.point_size = unit + (options_.samples > 1 ? 1.0f : 0.0f);
  frame.ip_point_size = float(3 * pixel_scale_for(options_.height) + 4);
  if (unrolled_) {
    frame.geometry = map_;
    return frame;
  }
  const GeometryRequest rq = request(fraction);
  frame.geometry = build_geometry(*skin_, rq);
  if (point_field_) {
    // The points are seen through the mesh: its edges only, in the layer colours.
    if (frame.mode != DisplayMode::Points) frame.mode = DisplayMode::Wireframe;
    add_integration_points(*skin_, *point_field_, colors_, rq, frame.geometry);
  }
  if (options_.labels.nodes || options_.labels.elements)
    frame.overlay.labels = scene_labels(*skin_, rq, camera_, options_.labels);
  return frame;
}

}  // namespace styk::render
