#include "app/desktop/picture_renderer.h"

#include <gtest/gtest.h>

#include <Inventor/nodes/SoCube.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include "desk_test_support.h"
#include "scenegraph/camera_setup.h"
#include "scenegraph/node_ref.h"

using namespace caliper3d;

namespace {
// Pixels of `image` that are not the scene's background.
int drawnPixels(const QImage& image) {
    const QColor background =
        QColor::fromRgbF(scenegraph::kBackgroundColour[0], scenegraph::kBackgroundColour[1],
                         scenegraph::kBackgroundColour[2]);
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            count += std::abs(c.red() - background.red()) +
                         std::abs(c.green() - background.green()) +
                         std::abs(c.blue() - background.blue()) >
                     6;
        }
    return count;
}
}  // namespace

TEST(PictureRendererTest, DrawsTheViewAtTheSizeAskedWithTheLegend) {
    CALIPER3D_REQUIRE_GUI();
    scenegraph::NodeRef<SoSeparator> scene(new SoSeparator);
    scene->addChild(new SoCube);  // 2 m wide, at the origin
    scenegraph::NodeRef<SoPerspectiveCamera> camera(new SoPerspectiveCamera);
    camera->position.setValue(0.0f, 0.0f, 10.0f);  // looking down -z at the cube
    camera->nearDistance = 1.0f;
    camera->farDistance = 100.0f;
    camera->heightAngle = 0.5f;

    QImage image;
    try {
        image = app::renderPicture(scene.get(), *camera.get(), nullptr, QSize(320, 200));
    } catch (const std::exception& e) {
        GTEST_SKIP() << "no offscreen context: " << e.what();
    }
    ASSERT_EQ(image.size(), QSize(320, 200));
    // The cube's face seen head-on: 2 m at 10 m with a 0.5 rad view is about 2 / (2 * 10 *
    // tan 0.25) = 39 % of the height, 78 px of 200, and as wide: about 6,100 pixels.
    const int cube = drawnPixels(image);
    EXPECT_GT(cube, 4500);
    EXPECT_LT(cube, 8000);
    EXPECT_NE(image.pixelColor(160, 100), image.pixelColor(2, 2));

    reconstruction::ColourLegend legend;
    legend.title = "radius - bit radius";
    legend.unit = "mm";
    legend.lo = -25.0;
    legend.hi = 25.0;
    const QImage withLegend =
        app::renderPicture(scene.get(), *camera.get(), &legend, QSize(320, 200));
    EXPECT_GT(drawnPixels(withLegend), cube + 500) << "no legend drawn";
}
