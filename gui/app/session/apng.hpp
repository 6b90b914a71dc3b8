// A small animated-PNG (APNG) writer for the deformation animation: every frame full size, RGBA8,
// shown `delay_ms` each, looping. Written here because no encoder is installed (no ffmpeg); the
// format is PNG plus three chunk types (acTL, fcTL, fdAT), compressed with zlib. A viewer without
// APNG support shows the first frame as an ordinary PNG.
#pragma once

#include <string>
#include <vector>

#include "styk/render/image.hpp"

namespace styk::gui {

// Throws std::invalid_argument for no frames or frames of different sizes, std::runtime_error
// naming the file when it cannot be written.
void write_apng(const std::string& path, const std::vector<render::Image>& frames, int delay_ms);

}  // namespace styk::gui
