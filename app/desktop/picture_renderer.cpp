#include "app/desktop/picture_renderer.h"

#include <cstring>

#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoDirectionalLight.h>
#include <Inventor/nodes/SoSeparator.h>

#include "scenegraph/camera_setup.h"
#include "scenegraph/colour_legend.h"
#include "scenegraph/node_ref.h"
#include "scenegraph/offscreen_renderer.h"

namespace caliper3d::app {

QImage renderPicture(SoNode* viewRoot, const SoCamera& camera,
                     const reconstruction::ColourLegend* legend, QSize size) {
    scenegraph::NodeRef<SoSeparator> root(new SoSeparator);
    auto* copy = static_cast<SoCamera*>(camera.copy());
    // The viewer keeps the camera's aspect to its window; the picture's may differ.
    copy->aspectRatio = static_cast<float>(size.width()) / static_cast<float>(size.height());
    root->addChild(copy);
    // The examiner viewer's headlight: a light along the view.
    SbVec3f look;
    copy->orientation.getValue().multVec(SbVec3f(0.0f, 0.0f, -1.0f), look);
    auto* light = new SoDirectionalLight;
    light->direction = look;
    root->addChild(light);
    root->addChild(viewRoot);
    if (legend) root->addChild(scenegraph::makeColourLegend(*legend));
    scenegraph::OffscreenRenderer renderer;
    const scenegraph::RenderedImage image =
        renderer.render(root.get(), size.width(), size.height(), scenegraph::kBackgroundColour);
    QImage out(image.width, image.height, QImage::Format_RGBA8888);
    for (int y = 0; y < image.height; ++y)
        std::memcpy(out.scanLine(y),
                    image.rgba.data() + static_cast<std::size_t>(y) * image.width * 4,
                    static_cast<std::size_t>(image.width) * 4);
    return out;
}

}  // namespace caliper3d::app
