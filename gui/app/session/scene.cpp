#include "session/scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "session/highlight.hpp"
#include "styk/core/diagnostics.hpp"
#include "styk/render/annotations.hpp"
#include "styk/render/camera.hpp"
#include "styk/render/overlay.hpp"

namespace styk::gui {
namespace {

std::string base_name(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

void Scene::clear() {
  skin_.reset();
  field_.reset();
  point_field_.reset();
  unrolled_.reset();
  map_ = render::FrameGeometry{};
  increment_ = nullptr;
  model_ = nullptr;
  scale_ = 0.0;
  field_faces_only_ = false;
  faces_decided_ = true;
  note_.clear();
  visible_nodes_.clear();
  frame_ = render::Frame{};
  ++geometry_revision_;
}

void Scene::rebuild(const Document& document, const DisplaySettings& settings) {
  clear();
  const Model& model = document.model();
  if (model.elements.empty()) return;
  render::check_band_count(settings.bands);
  const Results* results = document.results();
  const IncrementResult* increment = nullptr;
  if (results && !results->increments.empty()) {
    const int n = static_cast<int>(results->increments.size());
    const int index = settings.increment < 0 ? n - 1 : settings.increment;
    if (index >= n)
      throw InputError({}, "increment " + std::to_string(index + 1) +
                               " does not exist; the "
                               "results hold " +
                               std::to_string(n));
    increment = &results->increments[index];
  }
  auto skin = std::make_unique<render::SkinModel>(
      model, document.registry(), filter_layers(model, document.layers().layers(), settings.filter),
      render::ElementFilter{});
  if (skin->visible_nodes().empty()) return;  // everything hidden: an empty view, no error

  std::optional<render::ScalarField> field;
  std::optional<render::PointField> point_field;
  render::ColorScale colors;
  if (!settings.field.empty()) {
    if (!increment)
      throw InputError({}, "the field " + settings.field +
                               " needs results: solve "
                               "the model or open a results file");
    std::array<double, 2> range{};
    if (settings.ip_values) {
      point_field = render::evaluate_point_field(model, *increment, settings.field);
      range = render::point_field_range(*skin, *point_field);
      colors = render::ColorScale{range[0], range[1], settings.bands, settings.smooth};
    } else {
      field = render::evaluate_field(model, *increment, settings.field, settings.averaging);
      field->shell_fibre = settings.shell_fibre;
      range = render::field_range(*skin, *field);
      colors = render::color_scale_for(*field, range, settings.bands, settings.smooth);
    }
    if (settings.range && colors.labels.empty()) range = *settings.range;
    colors.min = colors.labels.empty() ? range[0] : colors.min;
    colors.max = colors.labels.empty() ? range[1] : colors.max;
  }
  if (settings.unrolled && !(field && field->on_surfaces()))
    throw InputError({},
                     "the unrolled map lays out a field that lives on surfaces (contact "
                     "output: CPRESS, CSHEAR, CSLIP, CGAP, CSTATUS)");
  double scale = 0.0;
  if (increment && settings.deformed && !settings.unrolled &&
      increment->U.size() == model.coords.size()) {
    if (settings.auto_scale) {
      const double largest = render::max_displacement(*increment, skin->visible_nodes());
      scale = largest > 0 ? 0.1 * skin->size() / largest : 0.0;
    } else {
      scale = std::max(0.0, settings.scale);
    }
  }

  request_ = render::GeometryRequest{};
  request_.outline = scale > 0 && settings.outline;
  request_.points = settings.mode == render::DisplayMode::Points;
  // Integration points are seen through the mesh: its edges only.
  frame_.mode = point_field && settings.mode != render::DisplayMode::Points
                    ? render::DisplayMode::Wireframe
                    : settings.mode;
  frame_.has_field = field.has_value() || point_field.has_value();
  frame_.colors = colors;
  frame_.samples = settings.samples;

  settings_ = settings;
  registry_ = &document.registry();
  model_ = &model;
  increment_ = increment;
  visible_nodes_ = skin->visible_nodes();
  skin_ = std::move(skin);
  field_ = std::move(field);
  point_field_ = std::move(point_field);
  colors_ = colors;
  scale_ = scale;
  fraction_ = 1.0;
  model_name_ = document.path().empty() ? "(new model)" : base_name(document.path());
  // The pointers into the scene's own field and colours, now that they have their final place.
  request_.field = field_ ? &*field_ : nullptr;
  request_.colors = field_ ? &colors_ : nullptr;
  field_faces_only_ = field_ && field_->on_surfaces() &&
                      (settings.field_faces == render::FieldFaces::Only || settings.unrolled);
  request_.hide_undefined_faces = field_faces_only_;
  faces_decided_ = !(field_ && field_->on_surfaces() && !settings.unrolled &&
                     settings.field_faces == render::FieldFaces::Auto);
  update_title();
  if (settings.unrolled) {
    build_map();
    return;
  }
  build_geometry();
  fit_camera_box();
  if (settings.camera_box) camera_box_ = *settings.camera_box;
}

// The camera fits the undeformed and the fully deformed shape, so animation frames share it.
void Scene::fit_camera_box() {
  camera_box_ = {frame_.geometry.lower, frame_.geometry.upper};
  if (scale_ > 0)
    for (int n : visible_nodes_) {
      if (field_faces_only_ && !field_->defined_at(n)) continue;
      const Vec3& x = model_->coords[n];
      for (int k = 0; k < 3; ++k) {
        const float p = float(x[k] - frame_.geometry.origin[k]);
        camera_box_[0][k] = std::min(camera_box_[0][k], p);
        camera_box_[1][k] = std::max(camera_box_[1][k], p);
      }
    }
}

void Scene::update_title() {
  title_lines_.clear();
  title_lines_.push_back("Model: " + model_name_);
  if (increment_) {
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, "Step %d  Increment %d  Total time %.4g", increment_->step,
                  increment_->increment, increment_->total_time);
    title_lines_.push_back(buffer);
  }
  legend_heading_.clear();
  if (field_ || point_field_) {
    const std::array<double, 2> range = point_field_
                                            ? render::point_field_range(*skin_, *point_field_)
                                            : render::field_range(*skin_, *field_);
    const render::NumberFormat format = render::number_format(colors_);
    const std::string name = point_field_ ? point_field_->name : field_->name;
    const bool averaged = field_ && field_->uses_averaging;
    // Shells coloured by their fibre tensors name the fibre.
    bool shells = false;
    for (const render::SkinModel::LayerSkin& layer : skin_->layers())
      shells = shells || !layer.shells.empty();
    const std::string fibre =
        shells && field_ && field_->tensor_value && !field_->station_values
            ? "shells: " + render::shell_fibre_name(settings_.shell_fibre) + " fibre"
            : std::string();
    if (field_ && !field_->categories.empty()) {
      title_lines_.push_back("Field: " + name);
    } else {
      title_lines_.push_back(
          "Field: " + name +
          (point_field_
               ? "  at " + std::to_string(render::visible_point_count(*skin_, *point_field_)) +
                     " integration points"
           : averaged ? "  Averaging: " + render::averaging_name(settings_.averaging)
                      : std::string()) +
          (fibre.empty() ? "" : "  (" + fibre + ")") + "  Min: " + format(range[0]) +
          "  Max: " + format(range[1]));
    }
    legend_heading_ = point_field_ ? name + " (integration points)"
                      : averaged   ? name + " (" + render::averaging_name(settings_.averaging) +
                                       (fibre.empty() ? "" : ", " + fibre) + ")"
                                 : name;
  } else {
    title_lines_.push_back("Mesh: " + std::to_string(model_->elements.size()) + " elements, " +
                           std::to_string(model_->coords.size()) + " nodes");
  }
  if (settings_.filter.active())
    title_lines_.push_back(
        "Filter: " + std::to_string(filtered_elements(*model_, settings_.filter).size()) + " of " +
        std::to_string(model_->elements.size()) + " elements");
  if (unrolled_) {
    char buffer[200];
    const render::UnrolledSurface& u = *unrolled_;
    if (u.kind == render::UnrolledSurface::Kind::Revolved)
      std::snprintf(buffer, sizeof buffer,
                    "Unrolled about the axis through (%.4g, %.4g, %.4g) along (%.4g, %.4g, %.4g), "
                    "radius %.4g",
                    u.axis.point[0], u.axis.point[1], u.axis.point[2], u.axis.direction[0],
                    u.axis.direction[1], u.axis.direction[2], u.radius);
    else
      std::snprintf(buffer, sizeof buffer,
                    "Flat: the plane through (%.4g, %.4g, %.4g), normal "
                    "(%.4g, %.4g, %.4g)",
                    u.axis.point[0], u.axis.point[1], u.axis.point[2], u.axis.direction[0],
                    u.axis.direction[1], u.axis.direction[2]);
    title_lines_.push_back(buffer);
  } else if (scale_ > 0) {
    title_lines_.push_back("Deformation scale: " + render::format_legend_value(drawn_scale()));
  }
  if (!note_.empty()) title_lines_.push_back(note_);
}

void Scene::build_geometry() {
  render::GeometryRequest request = request_;
  const double drawn = drawn_scale();
  if (drawn > 0) {
    request.displacement = &increment_->U;
    request.scale = drawn;
    if (!increment_->UR.empty()) request.rotation = &increment_->UR;  // beams turn their sections
  }
  frame_.geometry = render::build_geometry(*skin_, request);
  if (point_field_)
    render::add_integration_points(*skin_, *point_field_, colors_, request, frame_.geometry);
  ++geometry_revision_;
}

// The unrolled map: the field's faces, undeformed, laid flat; its camera looks at it square-on.
void Scene::build_map() {
  render::GeometryRequest faces = request_;
  faces.outline = false;
  faces.points = false;
  faces.hide_undefined_faces = true;
  const render::FrameGeometry on_faces = render::build_geometry(*skin_, faces);
  unrolled_ = render::fit_unrolled_surface(on_faces, skin_->centre(), std::nullopt);
  map_ = render::unroll_geometry(on_faces, skin_->centre(), *unrolled_);
  frame_.geometry = map_;
  camera_box_ = {map_.lower, map_.upper};
  update_title();
  ++geometry_revision_;
}

// FieldFaces::Auto: a surface field whose faces are hidden in this view (the slave surface under
// its master body) is drawn on its faces alone, with a note in the title block. Decided once per
// rebuild, with the first frame's view: orbiting afterwards never switches the drawing.
void Scene::choose_field_faces(const render::Camera& camera, double aspect) {
  faces_decided_ = true;
  const double seen = render::field_faces_seen(frame_.geometry, camera, aspect);
  if (seen >= render::kHiddenFieldFaces) return;
  field_faces_only_ = true;
  request_.hide_undefined_faces = true;
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "%s on its faces alone: hidden in this view (%.0f %% seen)",
                field_->name.c_str(), 100.0 * seen);
  note_ = buffer;
  build_geometry();
  fit_camera_box();
  update_title();
}

void Scene::set_deformation_fraction(double fraction) {
  if (!skin_ || unrolled_) return;
  fraction_ = std::clamp(fraction, 0.0, 1.0);
  build_geometry();
  update_title();
}

const render::Frame& Scene::frame(int width, int height, const ViewState& view) {
  frame_.width = std::max(16, width);
  frame_.height = std::max(16, height);
  if (!typeface_) typeface_ = std::make_unique<render::Typeface>();
  const auto overlay = [&] {
    render::OverlayContent content;
    content.title_lines = title_lines_;
    if (field_ || point_field_) {
      content.colors = &colors_;
      content.legend_heading = legend_heading_;
    }
    content.label_glyphs = settings_.labels.nodes || settings_.labels.elements;
    frame_.overlay = render::build_overlay(content, frame_.width, frame_.height, *typeface_);
  };
  overlay();
  frame_.point_size = float(std::max(2, render::pixel_scale_for(frame_.height) + 1)) +
                      (frame_.samples > 1 ? 1.0f : 0.0f);
  frame_.ip_point_size = float(3 * render::pixel_scale_for(frame_.height) + 4);
  if (!skin_) return frame_;
  if (unrolled_) render::reserve_map_area(frame_.overlay, *typeface_, *unrolled_, frame_.height);
  const auto fit = [&] {
    const render::PixelRect& area = frame_.overlay.model;
    render::ViewSpec spec = view.spec;
    if (unrolled_) spec = render::ViewSpec{"+z", 0.0, 0.0, view.spec.zoom, false};
    frame_.camera = render::fit_camera(spec, camera_box_[0], camera_box_[1],
                                       double(std::max(1, area.width)) / std::max(1, area.height));
    // Pan: a translation in the eye frame, i.e. added to the view matrix's translation column.
    const float size = unrolled_ ? float(std::hypot(camera_box_[1][0] - camera_box_[0][0],
                                                    camera_box_[1][1] - camera_box_[0][1]))
                                 : float(skin_->size());
    frame_.camera.view[12] += float(view.pan_right) * size;
    frame_.camera.view[13] += float(view.pan_up) * size;
  };
  fit();
  if (!faces_decided_) {
    const render::PixelRect& area = frame_.overlay.model;
    choose_field_faces(frame_.camera, double(std::max(1, area.width)) / std::max(1, area.height));
    if (field_faces_only_) {
      overlay();
      fit();
    }
  }
  if (unrolled_) {
    render::add_map_axes(frame_.overlay, *typeface_, frame_.camera, *unrolled_, frame_.height);
    return frame_;
  }
  if (settings_.labels.nodes || settings_.labels.elements) {
    render::LabelRequest labels = settings_.labels;
    if (settings_.labels_of_selection) {
      labels.only_nodes = selection_.nodes();
      labels.only_elements = selection_.elements();
      for (const SurfaceFace& f : selection_.faces()) labels.only_elements.push_back(f.element);
      std::sort(labels.only_elements.begin(), labels.only_elements.end());
      if (selection_.empty()) labels.nodes = labels.elements = false;
      if (labels.only_nodes.empty() && !labels.only_elements.empty()) labels.nodes = false;
      if (labels.only_elements.empty() && !labels.only_nodes.empty()) labels.elements = false;
    }
    render::GeometryRequest placed = request_;
    if (drawn_scale() > 0) placed.displacement = &increment_->U, placed.scale = drawn_scale();
    frame_.overlay.labels = render::scene_labels(*skin_, placed, frame_.camera, labels);
  }
  if (!selection_.empty()) append_highlight(*this, selection_, frame_.overlay.triangles);
  return frame_;
}

Vec3 Scene::placed(int node) const {
  const Vec3& x = model_->coords[node];
  const Vec3& o = frame_.geometry.origin;
  Vec3 p{x[0] - o[0], x[1] - o[1], x[2] - o[2]};
  const double drawn = drawn_scale();
  if (drawn > 0 && increment_)
    for (int k = 0; k < 3; ++k) p[k] += drawn * increment_->U[node][k];
  return p;
}

std::array<double, 3> Scene::screen_position(int node) const {
  const render::PixelRect& area = frame_.overlay.model;
  const Vec3 p = placed(node);
  const std::array<float, 3> ndc =
      render::project(frame_.camera, {float(p[0]), float(p[1]), float(p[2])});
  return {area.x + (ndc[0] + 1.0) * 0.5 * area.width, area.y + (1.0 - ndc[1]) * 0.5 * area.height,
          double(ndc[2])};
}

std::optional<ProbeResult> Scene::probe(int x, int y, int radius) const {
  if (!skin_) return std::nullopt;
  int best = -1;
  float best_depth = std::numeric_limits<float>::max();
  for (int n : visible_nodes_) {
    const std::array<double, 3> s = screen_position(n);
    const double d = std::hypot(s[0] - x, s[1] - y);
    if (d > radius) continue;
    if (s[2] < best_depth) best_depth = float(s[2]), best = n;
  }
  if (best < 0) return std::nullopt;
  ProbeResult result;
  result.node = best;
  result.node_id = model_->node_ids[best];
  result.position = model_->coords[best];
  result.value = value_at_node(best);
  if (field_) result.field = field_->name;
  return result;
}

std::optional<ElementProbe> Scene::element_probe(int element) const {
  if (!point_field_ || !skin_ || element < 0 || element >= int(model_->elements.size()))
    return std::nullopt;
  ElementProbe probe;
  probe.element = element;
  probe.element_id = model_->elements[element].id;
  probe.type = model_->elements[element].type;
  probe.field = point_field_->name;
  probe.points = render::element_point_values(*model_, *skin_->formulations()[element],
                                              *point_field_, element);
  return probe;
}

std::optional<double> Scene::value_at_node(int node) const {
  if (!field_ || !skin_ || node < 0 || node >= model_->node_count()) return std::nullopt;
  if (field_->location == render::FieldLocation::Node) return field_->values[node];
  double sum = 0.0;
  int count = 0;
  for (const render::SkinModel::LayerSkin& layer : skin_->layers())
    for (int e : layer.elements) {
      const Element& el = model_->elements[e];
      const int* nodes = model_->element_nodes(e);
      for (int k = 0; k < el.node_count; ++k)
        if (nodes[k] == node) {
          sum += field_->location == render::FieldLocation::Element
                     ? field_->values[e]
                     : field_->values[el.first_node + k];
          ++count;
        }
    }
  if (count == 0) return std::nullopt;
  return sum / count;
}

}  // namespace styk::gui
