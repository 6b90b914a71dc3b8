#include "session/animation.hpp"

#include <algorithm>
#include <cstdio>

#include "session/results_navigation.hpp"
#include "styk/core/diagnostics.hpp"

namespace styk::gui {

std::vector<double> animation_fractions(int frames) {
  if (frames < kMinAnimationFrames || frames > kMaxAnimationFrames)
    throw InputError({}, "an animation has " + std::to_string(kMinAnimationFrames) + " to " +
                             std::to_string(kMaxAnimationFrames) + " frames, not " +
                             std::to_string(frames));
  std::vector<double> fractions;
  for (int k = 0; k < frames; ++k) fractions.push_back(double(k) / (frames - 1));
  return fractions;
}

std::string animation_frame_path(const std::string& directory, const std::string& stem, int index) {
  char number[16];
  std::snprintf(number, sizeof number, "_%04d.png", index);
  return directory + "/" + stem + number;
}

SceneAnimation::SceneAnimation(const Document& document, DisplaySettings settings,
                               AnimationKind kind, int frames)
    : document_(document), settings_(std::move(settings)), kind_(kind) {
  const Results* results = document.results();
  if (!results || results->increments.empty())
    throw InputError({}, "an animation needs results: solve the model or open a results file");
  if (kind == AnimationKind::Scale) {
    fractions_ = animation_fractions(frames);
    return;
  }
  increments_ = int(results->increments.size());
  if (increments_ < 2)
    throw InputError({}, "the results hold one increment: animate the deformation scale instead");
  // One deformation scale (the view's, on the last increment), and the colour range and camera
  // box over every increment, so nothing but the results changes from frame to frame.
  Scene probe;
  DisplaySettings last = settings_;
  last.increment = increments_ - 1;
  probe.rebuild(document, last);
  settings_.auto_scale = false;
  settings_.scale = probe.deformation_scale();
  settings_.deformed = settings_.deformed && settings_.scale > 0;
  std::array<double, 2> range{0, 0};
  std::array<std::array<float, 3>, 2> box = probe.camera_box();
  bool first = true;
  for (int i = 0; i < increments_; ++i) {
    DisplaySettings s = settings_;
    s.increment = i;
    try {
      probe.rebuild(document, s);
    } catch (const InputError&) {
      continue;  // an increment without the field (e.g. before contact): drawn without it
    }
    if (probe.empty()) continue;
    for (int k = 0; k < 3; ++k) {
      box[0][k] = std::min(box[0][k], probe.camera_box()[0][k]);
      box[1][k] = std::max(box[1][k], probe.camera_box()[1][k]);
    }
    if (!probe.field()) continue;
    if (first) range = {probe.colors().min, probe.colors().max}, first = false;
    range = {std::min(range[0], probe.colors().min), std::max(range[1], probe.colors().max)};
  }
  if (!first) settings_.range = range;
  settings_.camera_box = box;
}

void SceneAnimation::show(Scene& scene, int index) {
  index = std::clamp(index, 0, frame_count() - 1);
  if (kind_ == AnimationKind::Scale) {
    if (!scale_ready_) {
      scene.rebuild(document_, settings_);
      scale_ = scene.deformation_scale();
      scale_ready_ = true;
    }
    scene.set_deformation_fraction(fractions_[index]);
    return;
  }
  DisplaySettings s = settings_;
  s.increment = index;
  try {
    scene.rebuild(document_, s);
  } catch (const InputError&) {
    s.field.clear();  // this increment lacks the field: its shape without colours
    scene.rebuild(document_, s);
  }
}

std::string SceneAnimation::frame_label(int index) const {
  index = std::clamp(index, 0, frame_count() - 1);
  if (kind_ == AnimationKind::Increments)
    return increment_label(document_.results()->increments[index]);
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "frame %d of %d: deformation scale %.4g", index + 1,
                frame_count(), fractions_[index] * scale_);
  return buffer;
}

}  // namespace styk::gui
