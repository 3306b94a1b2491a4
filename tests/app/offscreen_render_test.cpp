#include <algorithm>
#include <cstdlib>
#include <memory>

#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoDirectionalLight.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>
#include <QImage>

#include "reconstruction/synthetic/synthetic_well.h"
#include "reconstruction/well_geometry.h"
#include "scenegraph/camera_setup.h"
#include "scenegraph/label_style.h"
#include "scenegraph/main_thread.h"
#include "scenegraph/node_ref.h"
#include "scenegraph/offscreen_renderer.h"
#include "scenegraph/picture/png_file.h"
#include "scenegraph/render_stats.h"
#include "scenegraph/view_overlay.h"
#include "scenegraph/well_annotations.h"
#include "scenegraph/well_scene.h"
#include "test_support.h"

using namespace caliper3d;

namespace {
// `scene` framed whole from `view`, drawn offscreen and written to a PNG at `path`.
scenegraph::RenderedImage renderToPng(SoNode* scene, const std::string& path, int width, int height,
                                      scenegraph::ViewDirection view) {
    auto root = scenegraph::makeRef(scenegraph::makeRenderRoot(scene, view, width, height));
    scenegraph::OffscreenRenderer renderer;
    scenegraph::RenderedImage image =
        renderer.render(root.get(), width, height, scenegraph::kBackgroundColour);
    scenegraph::writePng(image, path);
    return image;
}
}  // namespace

TEST(OffscreenRenderTest, WellRendersToAPngWithoutAWindow) {
    scenegraph::initCoin();
    auto table = std::make_shared<io::SectionTable>(
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile("example", 30.0, 0.1)));
    table->bitSize_mm.assign(table->rowCount(), 215.9);
    reconstruction::WellGeometry geometry(table, reconstruction::GeometryOptions{});
    scenegraph::WellScene scene;
    scene.buildAll(geometry);
    const auto path = test::scratch("offscreen.png");
    scenegraph::RenderedImage image;
    try {
        image = renderToPng(scene.root(), path.string(), 320, 240, scenegraph::ViewDirection::East);
    } catch (const std::runtime_error& e) {
        FAIL() << e.what();
    }
    // The well (a thin 30 m line framed whole) is drawn, and the PNG holds the same pixels.
    EXPECT_GT(image.nonBackgroundPixels(), 200u);
    QImage png(QString::fromStdString(path.string()));
    ASSERT_FALSE(png.isNull());
    EXPECT_EQ(png.width(), 320);
    EXPECT_EQ(png.height(), 240);
    const QRgb corner = png.pixel(0, 0);
    EXPECT_EQ(qRed(corner), image.rgba[0]);
    // Framed whole: nothing touches the top or bottom edge.
    for (int x = 0; x < png.width(); ++x) {
        EXPECT_EQ(png.pixel(x, 0), corner) << "top edge, x " << x;
        EXPECT_EQ(png.pixel(x, png.height() - 1), corner) << "bottom edge, x " << x;
    }
}

namespace {
// Pixels of `image` within `tolerance` (0-255) of `colour` (0-1), in the rectangle
// [x0, x1) x [y0, y1) (rows from the top).
std::size_t pixelsOfColour(const scenegraph::RenderedImage& image, const float colour[3],
                           int x0 = 0, int y0 = 0, int x1 = 1 << 20, int y1 = 1 << 20) {
    std::size_t count = 0;
    for (int y = std::max(y0, 0); y < std::min(y1, image.height); ++y)
        for (int x = std::max(x0, 0); x < std::min(x1, image.width); ++x) {
            const std::uint8_t* p =
                &image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4];
            bool close = true;
            for (int c = 0; c < 3; ++c)
                close = close && std::abs(int(p[c]) - int(colour[c] * 255.0f + 0.5f)) <= 8;
            count += close ? 1 : 0;
        }
    return count;
}
}  // namespace

TEST(OffscreenRenderTest, LabelsNameAndNorthArrowDrawIntoThePicture) {
    scenegraph::initCoin();
    auto table = std::make_shared<io::SectionTable>(
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile("circle", 100.0, 0.1)));
    table->wellName = "LABEL-1";
    reconstruction::GeometryOptions options;
    options.radialExaggeration = 20.0;
    const reconstruction::WellGeometry geometry(table, options);
    scenegraph::WellScene scene;
    scene.buildAll(geometry);
    auto root = scenegraph::makeRef(
        scenegraph::makeRenderRoot(scene.root(), scenegraph::ViewDirection::Iso, 640, 480));
    scenegraph::OffscreenRenderer renderer;
    scenegraph::RenderedImage bare, annotated;
    try {
        bare = renderer.render(root.get(), 640, 480, scenegraph::kBackgroundColour);
        const SoCamera* camera = scenegraph::findCamera(root.get());
        ASSERT_NE(camera, nullptr);
        scenegraph::AnnotationView view =
            scenegraph::pictureAnnotationView(*camera, 640, 480, 0.0, 1.0e300);
        view.radialExaggeration = 20.0;
        root->addChild(scenegraph::makeWellAnnotations(geometry, view));
        scenegraph::ViewOverlay overlay;
        overlay.setCaption({"radii x 20"});
        root->addChild(overlay.root());
        annotated = renderer.render(root.get(), 640, 480, scenegraph::kBackgroundColour);
        root->removeChild(overlay.root());
    } catch (const std::runtime_error& e) {
        FAIL() << e.what();
    }
    // The depth labels (10 m ... 100 m) and the caption, in the label colour; the well's name
    // in its own; none of either without the annotations.
    EXPECT_EQ(pixelsOfColour(bare, scenegraph::kLabelColour), 0u);
    EXPECT_GT(pixelsOfColour(annotated, scenegraph::kLabelColour), 400u);
    EXPECT_EQ(pixelsOfColour(bare, scenegraph::kNameColour), 0u);
    EXPECT_GT(pixelsOfColour(annotated, scenegraph::kNameColour), 40u);
    // Labels lie right of the well, the name at its top (the top fifth of the picture).
    EXPECT_GT(pixelsOfColour(annotated, scenegraph::kLabelColour, 330, 0, 640, 480), 300u);
    EXPECT_GT(pixelsOfColour(annotated, scenegraph::kNameColour, 0, 0, 640, 96), 40u);
    // The north arrow's red in the bottom-left corner.
    const float north[3] = {0.95f, 0.30f, 0.25f};
    EXPECT_GT(pixelsOfColour(annotated, north, 0, 480 - 120, 120, 480), 20u);
    EXPECT_EQ(pixelsOfColour(bare, north, 0, 480 - 120, 120, 480), 0u);
}

TEST(OffscreenRenderTest, SpansOutsideTheViewAreCulledWithoutChangingAPixel) {
    // A 300 m well (a tree three spans deep) seen from inside near its top, looking down: the
    // spans behind and far beside the camera's cone are skipped by their separators' culling,
    // and the picture is the one drawn with culling off, pixel for pixel.
    scenegraph::initCoin();
    reconstruction::GeometryOptions options;
    options.radialExaggeration = 20.0;
    const reconstruction::WellGeometry geometry(
        std::make_shared<const io::SectionTable>(reconstruction::makeSyntheticWell(
            reconstruction::syntheticProfile("example", 300.0, 0.05))),
        options);
    scenegraph::WellScene scene;
    scene.buildAll(geometry);
    ASSERT_EQ(scene.treeDepth(), 3);
    auto root = scenegraph::makeRef(new SoSeparator);
    auto* camera = new SoPerspectiveCamera;
    camera->position.setValue(30.0f, -150.0f, 0.0f);  // beside the well, looking at one stretch
    camera->pointAt(SbVec3f(0.0f, -150.0f, 0.0f), SbVec3f(0.0f, 1.0f, 0.0f));
    camera->heightAngle = 0.3f;
    camera->nearDistance = 1.0f;
    camera->farDistance = 1000.0f;
    root->addChild(camera);
    root->addChild(new SoDirectionalLight);
    root->addChild(scene.root());
    scenegraph::OffscreenRenderer renderer;
    const scenegraph::RenderedImage culled =
        renderer.render(root.get(), 640, 400, scenegraph::kBackgroundColour);
    SoSearchAction search;
    search.setName("span");
    search.setInterest(SoSearchAction::ALL);
    search.setSearchingAll(TRUE);
    search.apply(scene.root());
    ASSERT_EQ(search.getPaths().getLength(), 22);
    for (int i = 0; i < search.getPaths().getLength(); ++i)
        static_cast<SoSeparator*>(search.getPaths()[i]->getTail())->renderCulling =
            SoSeparator::OFF;
    const scenegraph::RenderedImage whole =
        renderer.render(root.get(), 640, 400, scenegraph::kBackgroundColour);
    EXPECT_GT(culled.nonBackgroundPixels(), 10'000u);
    EXPECT_EQ(culled.rgba, whole.rgba);
    EXPECT_LT(culled.nodesVisited * 3, whole.nodesVisited)
        << culled.nodesVisited << " of " << whole.nodesVisited;
}
