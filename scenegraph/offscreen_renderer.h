#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

class SoNode;

namespace caliper3d::scenegraph {

// RGBA pixels, top row first.
struct RenderedImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;
    // Nodes the render action entered to draw it: of each SoLOD only the child it picks, and
    // nothing below a separator culled outside the view (counted by the action's abort
    // callback, which Coin asks before each child it traverses).
    std::size_t nodesVisited = 0;

    // Pixels whose colour differs from the top-left (background) pixel.
    std::size_t nonBackgroundPixels() const;
};

// Renders a scene into an image without a window or an X server: a Mesa EGL
// surfaceless context and a framebuffer object, drawn by SoGLRenderAction.
// (Coin's own SoOffscreenRenderer cannot make a context with Debian's Coin 4.0.0.)
// The scene must contain its camera and lights. Main thread only.
class OffscreenRenderer {
public:
    OffscreenRenderer();
    ~OffscreenRenderer();
    OffscreenRenderer(const OffscreenRenderer&) = delete;
    OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

    // Throws std::runtime_error saying what failed (no EGL, no context, ...).
    RenderedImage render(SoNode* scene, int width, int height, const float background[3]);
    // Renders the picture as render() does, then draws it `frames` more times into the same
    // framebuffer (no read-back) and returns the mean time of one of those frames, in ms.
    double timeFrames(SoNode* scene, int width, int height, const float background[3], int frames);

private:
    RenderedImage draw(SoNode* scene, int width, int height, const float background[3],
                       int timedFrames, double* frameMs);
    struct Context;
    std::unique_ptr<Context> m_context;
};

}  // namespace caliper3d::scenegraph
