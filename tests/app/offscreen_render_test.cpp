#include <memory>

#include <gtest/gtest.h>
#include <QImage>

#include "app/png_output.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "reconstruction/well_geometry.h"
#include "scenegraph/main_thread.h"
#include "scenegraph/well_scene.h"
#include "test_support.h"

using namespace caliper3d;

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
        image = app::renderToPng(scene.root(), path.string(), 320, 240,
                                 scenegraph::ViewDirection::East);
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
