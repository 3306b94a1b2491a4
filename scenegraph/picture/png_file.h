#pragma once

#include <string>

#include "scenegraph/offscreen_renderer.h"

namespace caliper3d::scenegraph {

// Writes `image` as an 8-bit RGBA PNG (libpng), whole or not at all (io::AtomicOutput: a
// killed or failed write leaves the previous file). Throws std::runtime_error naming the file.
void writePng(const RenderedImage& image, const std::string& path);

// Reads a PNG written by writePng (or any 8-bit RGB or RGBA PNG) back into RGBA pixels, top
// row first. Throws std::runtime_error naming the file.
RenderedImage readPng(const std::string& path);

}  // namespace caliper3d::scenegraph
