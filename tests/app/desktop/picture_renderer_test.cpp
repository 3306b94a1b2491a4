// File > Save picture and `caliper3d render` draw through one recipe (scenegraph::drawPicture):
// the same wells seen through the same camera at the same size give the same picture.
#include "app/desktop/picture_renderer.h"

#include <cstdlib>
#include <string>

#include <gtest/gtest.h>
#include <QGLWidget>

#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>
#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include "app/desktop/desk_model.h"
#include "app/desktop/file_menu.h"
#include "app/desktop/main_window.h"
#include "app/desktop/well_session.h"
#include "desk_test_support.h"
#include "scenegraph/camera_setup.h"
#include "scenegraph/node_ref.h"
#include "scenegraph/picture/png_file.h"
#include "scenegraph/render_stats.h"

using namespace caliper3d;

namespace {

// Pixels whose colour differs between `a` and `b` by more than `tolerance` in a channel.
std::size_t differingPixels(const scenegraph::RenderedImage& a, const scenegraph::RenderedImage& b,
                            int tolerance) {
    std::size_t count = 0;
    for (std::size_t p = 0; p + 3 < a.rgba.size(); p += 4)
        for (std::size_t c = 0; c < 3; ++c)
            if (std::abs(int(a.rgba[p + c]) - int(b.rgba[p + c])) > tolerance) {
                ++count;
                break;
            }
    return count;
}

}  // namespace

TEST(PictureRendererTest, SavePictureDrawsWhatRenderDrawsForTheSameCamera) {
    CALIPER3D_REQUIRE_GUI();
    const auto log = test::syntheticLog("example", 60.0, 0.1);
    constexpr int kWidth = 480, kHeight = 360;
    app::MainWindow window;
    window.resize(1280, 960);
    window.show();
    app::LoadOptions options;
    options.read.bitSize_mm = 215.9;
    options.radialExaggeration = 30.0;
    window.session().keepExaggeration();  // as caliper3d view --exaggerate 30
    window.session().openWell(QString::fromStdString(log.string()), options);
    // Loaded, and its legend in: the session sets it once the load is done, and render's
    // picture carries it (a picture saved before it came in draws none, and places its
    // labels where the legend would be).
    ASSERT_TRUE(test::waitUntil(
        [&] {
            return window.model().wellCount() == 1 && !window.session().loading() &&
                   window.session().legend();
        },
        120000))
        << "the well did not load";
    ASSERT_NE(window.model().well(0).geometry, nullptr);

    // The camera `caliper3d render --view iso` frames the well with, put in the viewer. (The
    // offscreen context cannot be made current over the viewer's: release that first, as Save
    // picture does.)
    if (auto* gl = qobject_cast<QGLWidget*>(window.viewer()->getGLWidget())) gl->doneCurrent();
    scenegraph::PictureRequest iso;
    iso.width = kWidth;
    iso.height = kHeight;
    iso.unloggedPath = true;
    const scenegraph::Picture framing =
        scenegraph::drawPicture(scenegraph::pictureWells({window.model().well(0).geometry}), iso);
    auto* framed = dynamic_cast<SoPerspectiveCamera*>(scenegraph::findCamera(framing.root.get()));
    auto* camera = dynamic_cast<SoPerspectiveCamera*>(window.viewer()->getCamera());
    ASSERT_NE(framed, nullptr);
    ASSERT_NE(camera, nullptr);
    camera->position = framed->position.getValue();
    camera->orientation = framed->orientation.getValue();
    camera->heightAngle = framed->heightAngle.getValue();
    camera->nearDistance = framed->nearDistance.getValue();
    camera->farDistance = framed->farDistance.getValue();
    camera->focalDistance = framed->focalDistance.getValue();

    const auto saved = test::scratch("save_picture.png");
    const auto rendered = test::scratch("render_picture.png");
    try {
        window.files().writePicture(QString::fromStdString(saved.string()), {kWidth, kHeight});
    } catch (const std::exception& e) {
        GTEST_SKIP() << "no offscreen context: " << e.what();
    }
    const std::string command = std::string(CALIPER3D_BINARY) + " render '" + log.string() +
                                "' -o '" + rendered.string() +
                                "' --view iso --width 480 --height 360 --exaggerate 30 "
                                "--bit-size 215.9mm > /dev/null";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;

    const scenegraph::RenderedImage a = scenegraph::readPng(saved.string());
    const scenegraph::RenderedImage b = scenegraph::readPng(rendered.string());
    ASSERT_EQ(a.width, kWidth);
    ASSERT_EQ(a.height, kHeight);
    ASSERT_EQ(b.width, kWidth);
    ASSERT_EQ(b.height, kHeight);
    EXPECT_GT(a.nonBackgroundPixels(), 2000u) << "the well, labels, legend and arrow are drawn";
    // The same picture: antialiasing aside, not a pixel apart.
    const std::size_t apart = differingPixels(a, b, 8);
    EXPECT_LT(apart, std::size_t(kWidth * kHeight / 500)) << apart << " pixels differ";
}

TEST(PictureRendererTest, ALargerPictureRefinesTheWallForItsOwnSize) {
    CALIPER3D_REQUIRE_GUI();
    const auto log = test::syntheticLog("example", 60.0, 0.1);
    app::DeskModel model;
    app::WellSession session(model, nullptr);
    app::LoadOptions options;
    options.read.bitSize_mm = 215.9;
    session.openWell(QString::fromStdString(log.string()), options);
    ASSERT_TRUE(test::waitUntil([&] { return !session.loading(); }, 120000));
    ASSERT_NE(model.well(0).geometry, nullptr);
    // A camera inside the hole at 30 m, looking down it: near walls want full detail.
    scenegraph::NodeRef<SoPerspectiveCamera> held(new SoPerspectiveCamera);
    SoPerspectiveCamera& camera = *held.get();
    const scenegraph::CameraPose pose = scenegraph::downHolePose(*model.well(0).geometry, 30.0);
    camera.position.setValue(pose.eye);
    camera.pointAt(SbVec3f(pose.eye) + SbVec3f(pose.look), SbVec3f(pose.up));
    camera.heightAngle = pose.heightAngle_rad;
    camera.nearDistance = 0.01f;
    camera.farDistance = 100.0f;
    std::size_t small = 0, large = 0;
    try {
        small = app::drawWindowPicture(session, camera, 64, 48).refinedSegments;
        large = app::drawWindowPicture(session, camera, 1600, 1200).refinedSegments;
    } catch (const std::exception& e) {
        GTEST_SKIP() << "no offscreen context: " << e.what();
    }
    EXPECT_GT(large, small) << "the detail follows the picture's size, not the viewer's";
}

// Of several wells, the picture ticks the depths of the current one, as the window does.
TEST(PictureRendererTest, APictureOfSeveralWellsTicksTheCurrentOne) {
    CALIPER3D_REQUIRE_GUI();
    app::DeskModel model;
    app::WellSession session(model, nullptr);
    app::LoadOptions options;
    options.read.bitSize_mm = 215.9;
    session.openWell(QString::fromStdString(test::syntheticLog("example", 60.0, 0.1).string()),
                     options);
    session.addWell(QString::fromStdString(test::syntheticLog("circle", 40.0, 0.1).string()),
                    options);
    ASSERT_TRUE(test::waitUntil(
        [&] { return model.wellCount() == 2 && !session.loading() && model.well(1).geometry; },
        120000));
    model.setCurrent(1, 10.0);
    scenegraph::NodeRef<SoPerspectiveCamera> camera(new SoPerspectiveCamera);
    scenegraph::frameAll(camera.get(), session.sceneRoot(), SbViewportRegion(480, 360));
    scenegraph::Picture picture;
    try {
        picture = app::drawWindowPicture(session, *camera.get(), 480, 360);
    } catch (const std::exception& e) {
        GTEST_SKIP() << "no offscreen context: " << e.what();
    }
    // Each well's annotations, in the wells' order; the ticks under the second's only.
    SoSearchAction annotations;
    annotations.setName("annotations");
    annotations.setInterest(SoSearchAction::ALL);
    annotations.setSearchingAll(TRUE);
    annotations.apply(picture.root.get());
    ASSERT_EQ(annotations.getPaths().getLength(), 2);
    for (int i = 0; i < 2; ++i) {
        SoSearchAction ticks;
        ticks.setName("tick_marks");
        ticks.setInterest(SoSearchAction::ALL);
        ticks.setSearchingAll(TRUE);
        ticks.apply(annotations.getPaths()[i]->getTail());
        EXPECT_EQ(ticks.getPaths().getLength(), i == 1 ? 1 : 0) << "well " << i;
    }
}
