#include "session/scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "session/highlight.hpp"
#include "styk/core/diagnostics.hpp"
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
  increment_ = nullptr;
  model_ = nullptr;
  scale_ = 0.0;
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
  render::ColorScale colors;
  if (!settings.field.empty()) {
    if (!increment)
      throw InputError({}, "the field " + settings.field +
                               " needs results: solve "
                               "the model or open a results file");
    field = render::evaluate_field(model, *increment, settings.field, settings.averaging);
    const std::array<double, 2> range =
        settings.range ? *settings.range : render::field_range(*skin, *field);
    colors = render::color_scale_for(*field, range, settings.bands, settings.smooth);
  }
  double scale = 0.0;
  if (increment && settings.deformed && increment->U.size() == model.coords.size()) {
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
  frame_.mode = settings.mode;
  frame_.has_field = field.has_value();
  frame_.colors = colors;

  title_lines_.clear();
  const std::string name = document.path().empty() ? "(new model)" : base_name(document.path());
  title_lines_.push_back("Model: " + name);
  if (increment) {
    char buffer[160];
    std::snprintf(buffer, sizeof buffer, "Step %d  Increment %d  Total time %.4g", increment->step,
                  increment->increment, increment->total_time);
    title_lines_.push_back(buffer);
  }
  if (field) {
    title_lines_.push_back("Field: " + field->name +
                           (field->uses_averaging
                                ? "  Averaging: " + render::averaging_name(settings.averaging)
                                : std::string()) +
                           "  Min: " + render::format_legend_value(colors.min) +
                           "  Max: " + render::format_legend_value(colors.max));
    legend_heading_ = field->name + (field->uses_averaging
                                         ? " (" + render::averaging_name(settings.averaging) + ")"
                                         : std::string());
  } else {
    title_lines_.push_back("Mesh: " + std::to_string(model.elements.size()) + " elements, " +
                           std::to_string(model.coords.size()) + " nodes");
  }
  if (settings.filter.active())
    title_lines_.push_back("Filter: " + std::to_string(filtered_elements(model, settings.filter).size()) +
                           " of " + std::to_string(model.elements.size()) + " elements");
  if (scale > 0) title_lines_.push_back("Deformation scale: " + render::format_legend_value(scale));

  model_ = &model;
  increment_ = increment;
  visible_nodes_ = skin->visible_nodes();
  skin_ = std::move(skin);
  field_ = std::move(field);
  colors_ = colors;
  scale_ = scale;
  fraction_ = 1.0;
  // The pointers into the scene's own field and colours, now that they have their final place.
  request_.field = field_ ? &*field_ : nullptr;
  request_.colors = field_ ? &colors_ : nullptr;
  build_geometry();
  // The camera fits the undeformed and the fully deformed shape, so animation frames share it.
  camera_box_ = {frame_.geometry.lower, frame_.geometry.upper};
  if (scale_ > 0)
    for (int n : visible_nodes_) {
      const Vec3& x = model.coords[n];
      for (int k = 0; k < 3; ++k) {
        const float p = float(x[k] - frame_.geometry.origin[k]);
        camera_box_[0][k] = std::min(camera_box_[0][k], p);
        camera_box_[1][k] = std::max(camera_box_[1][k], p);
      }
    }
  if (settings.camera_box) camera_box_ = *settings.camera_box;
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
  ++geometry_revision_;
}

void Scene::set_deformation_fraction(double fraction) {
  if (!skin_) return;
  fraction_ = std::clamp(fraction, 0.0, 1.0);
  build_geometry();
  if (scale_ > 0 && !title_lines_.empty())
    title_lines_.back() = "Deformation scale: " + render::format_legend_value(drawn_scale());
}

const render::Frame& Scene::frame(int width, int height, const ViewState& view) {
  frame_.width = std::max(16, width);
  frame_.height = std::max(16, height);
  render::OverlayContent content;
  content.title_lines = title_lines_;
  if (field_) {
    content.colors = &colors_;
    content.legend_heading = legend_heading_;
  }
  frame_.overlay = render::build_overlay(content, frame_.width, frame_.height);
  frame_.point_size = float(std::max(2, render::text_scale_for(frame_.height) + 1));
  if (!skin_) return frame_;
  const render::PixelRect& area = frame_.overlay.model;
  frame_.camera = render::fit_camera(view.spec, camera_box_[0], camera_box_[1],
                                     double(std::max(1, area.width)) / std::max(1, area.height));
  // Pan: a translation in the eye frame, i.e. added to the view matrix's translation column.
  const float size = float(skin_->size());
  frame_.camera.view[12] += float(view.pan_right) * size;
  frame_.camera.view[13] += float(view.pan_up) * size;
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
