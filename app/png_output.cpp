#include "app/png_output.h"

#include <stdexcept>

#include <Inventor/nodes/SoSeparator.h>
#include <QFile>
#include <QImage>

#include "io/atomic_output.h"
#include "scenegraph/node_ref.h"

namespace caliper3d::app {

void savePng(const QImage& image, const std::string& path) {
    io::AtomicOutput output(path);
    if (!image.save(QFile::decodeName(output.path().c_str()), "PNG"))
        throw std::runtime_error(path + ": cannot write the PNG file");
    output.commit();
}

void savePng(const scenegraph::RenderedImage& image, const std::string& path) {
    const QImage picture(image.rgba.data(), image.width, image.height, image.width * 4,
                         QImage::Format_RGBA8888);
    savePng(picture, path);
}

namespace detail {
scenegraph::RenderedImage renderRootToPng(SoNode* root, const std::string& path, int width,
                                          int height) {
    scenegraph::OffscreenRenderer renderer;
    scenegraph::RenderedImage image =
        renderer.render(root, width, height, scenegraph::kBackgroundColour);
    savePng(image, path);
    return image;
}
}  // namespace detail

scenegraph::RenderedImage renderToPng(SoNode* scene, const std::string& path, int width, int height,
                                      scenegraph::ViewDirection view) {
    auto root = scenegraph::makeRef(scenegraph::makeRenderRoot(scene, view, width, height));
    return detail::renderRootToPng(root.get(), path, width, height);
}

scenegraph::RenderedImage renderToPng(SoNode* scene, const std::string& path, int width, int height,
                                      const scenegraph::CameraPose& pose) {
    auto root = scenegraph::makeRef(scenegraph::makeRenderRoot(scene, pose));
    return detail::renderRootToPng(root.get(), path, width, height);
}

}  // namespace caliper3d::app
