#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Inventor/nodes/SoSeparator.h>

#include "scenegraph/label_placement.h"
#include "scenegraph/node_ref.h"

class SoText2;

namespace caliper3d::scenegraph {

// What a view says about itself, drawn over the scene in the bottom-left corner at a fixed
// size in pixels: a north arrow that turns as the camera turns (north red with its "N",
// south, east and west grey with an "E", in the horizontal plane seen from the camera) and caption
// lines beside it (the radial exaggeration). Main thread only.
//
//   root: SoSeparator
//     SoCallback (keeps the rotation of the camera above it: the scene's camera)
//     SoOrthographicCamera, SoDepthBuffer (no test: over the scene), SoLightModel
//     caption: SoSeparator { SoCallback (pixels from the corner), outline, SoText2 }
//     arrow:   SoSeparator { SoCallback (corner, pixel scale, the scene camera's rotation), ... }
//
// Put root() after the scene, under the scene's camera (the last child of a render root or
// of a viewer's scene graph), and outside what is framed: it draws in pixels, not metres.
// The callbacks read this object: root() must not be drawn after it is destroyed.
class ViewOverlay {
public:
    ViewOverlay();
    ~ViewOverlay();
    ViewOverlay(const ViewOverlay&) = delete;
    ViewOverlay& operator=(const ViewOverlay&) = delete;

    SoSeparator* root() const { return m_root.get(); }
    void setCaption(const std::vector<std::string>& lines);
    std::vector<std::string> caption() const;
    // What the overlay covers in a picture `height` pixels high (from its top-left corner):
    // the arrow with its letters, and the caption. Labels keep clear of it.
    std::vector<ScreenBox> occupied(int height) const;

    // Where the arrow's centre is, in pixels from the picture's bottom-left corner, and its
    // length (north arm).
    static constexpr float kArrowCentre_px = 62.0f;
    static constexpr float kArrowLength_px = 32.0f;
    static constexpr float kCaptionLeft_px = 2.0f * kArrowCentre_px + 8.0f;

private:
    struct SceneCamera;
    std::unique_ptr<SceneCamera> m_camera;
    NodeRef<SoSeparator> m_root;
    SoText2* m_caption = nullptr;
};

// "radii x 300", or "radii to scale" for a factor of 1.
std::string exaggerationCaption(double radialExaggeration);

}  // namespace caliper3d::scenegraph
