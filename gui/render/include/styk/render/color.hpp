// Colours of the renderer: linear 0..1 RGB, converted to bytes only when pixels are written.
#pragma once

#include <cstdint>

namespace styk::render {

struct Rgb {
  float r = 0.0f;
  float g = 0.0f;
  float b = 0.0f;
};

inline std::uint8_t to_byte(float c) {
  const float clamped = c < 0.0f ? 0.0f : (c > 1.0f ? 1.0f : c);
  return static_cast<std::uint8_t>(clamped * 255.0f + 0.5f);
}

// Fixed colours of the picture (white paper, black ink) shared by the scene and the overlay.
constexpr Rgb kBackground{1.0f, 1.0f, 1.0f};
constexpr Rgb kInk{0.0f, 0.0f, 0.0f};
constexpr Rgb kOutline{0.55f, 0.55f, 0.55f};  // undeformed outline overlay

}  // namespace styk::render
