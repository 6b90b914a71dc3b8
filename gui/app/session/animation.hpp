// The results animation (issue 7): the deformation grown from 0 to the drawn scale in N frames
// (the field of the increment stays as it is), or the load history played increment by increment
// at one deformation scale, one colour range and one camera, so the frames compare. The scene
// shows a frame; the view grabs it (PNG sequence, APNG).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "session/scene.hpp"

namespace styk::gui {

enum class AnimationKind { Scale, Increments };

constexpr int kMinAnimationFrames = 2;
constexpr int kMaxAnimationFrames = 500;

// Fractions of the deformation scale of the Scale animation: 0, 1/(N-1), ..., 1. Throws
// InputError for N outside kMinAnimationFrames..kMaxAnimationFrames.
std::vector<double> animation_fractions(int frames);

// "DIR/STEM_0007.png": the numbered frame files of an export.
std::string animation_frame_path(const std::string& directory, const std::string& stem, int index);

class SceneAnimation {
 public:
  // `settings`: what the view shows now. Scale: `frames` frames of its increment. Increments: one
  // frame per increment of the results (frames is ignored). Throws InputError without results
  // (or with fewer than 2 increments for Increments), and for a frame count out of range.
  SceneAnimation(const Document& document, DisplaySettings settings, AnimationKind kind,
                 int frames);

  int frame_count() const {
    return kind_ == AnimationKind::Scale ? int(fractions_.size()) : increments_;
  }
  // Puts frame `index` into the scene. The first call (and every call of an Increments animation)
  // rebuilds the scene; then a Scale animation only redraws the deformation.
  void show(Scene& scene, int index);
  // "scale 0.5 of 123.4" or the increment's label, for the status bar.
  std::string frame_label(int index) const;

 private:
  const Document& document_;
  DisplaySettings settings_;
  AnimationKind kind_;
  std::vector<double> fractions_;
  int increments_ = 0;
  bool scale_ready_ = false;
  double scale_ = 0.0;
};

}  // namespace styk::gui
