#pragma once

#include <string>

#include "scenegraph/camera_setup.h"
#include "scenegraph/offscreen_renderer.h"

class QImage;
class SoNode;

namespace caliper3d::app {

// Renders `scene` offscreen from `view` and saves a PNG. Throws
// std::runtime_error naming the file or the rendering failure.
scenegraph::RenderedImage renderToPng(SoNode* scene, const std::string& path, int width, int height,
                                      scenegraph::ViewDirection view);
scenegraph::RenderedImage renderToPng(SoNode* scene, const std::string& path, int width, int height,
                                      const scenegraph::CameraPose& pose);

// Saves an image as PNG, whole or not at all (io/atomic_output.h: a failed or killed run
// leaves the previous picture); throws std::runtime_error naming the file.
void savePng(const scenegraph::RenderedImage& image, const std::string& path);
void savePng(const QImage& image, const std::string& path);

namespace detail {
scenegraph::RenderedImage renderRootToPng(SoNode* root, const std::string& path, int width,
                                          int height);
}

}  // namespace caliper3d::app
