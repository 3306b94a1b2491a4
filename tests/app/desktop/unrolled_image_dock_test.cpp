#include "app/desktop/unrolled_image_dock.h"

#include <cmath>

#include <gtest/gtest.h>
#include <QComboBox>
#include <QTest>
#include <QWheelEvent>
#include <QtCharts/QChart>
#include <QtCharts/QChartView>

#include "desk_test_well.h"
#include "reconstruction/mesh/wall_colouring.h"

using namespace caliper3d;

namespace {

class UnrolledImageDockTest : public ::testing::Test {
protected:
    void SetUp() override {
        if (!test::deskApplication()) GTEST_SKIP() << "no display (run under xvfb-run)";
    }
    // Shows the dock at a fixed size and lets the chart lay itself out.
    static void show(app::UnrolledImageDock& dock) {
        dock.resize(480, 640);
        dock.show();
        ASSERT_TRUE(QTest::qWaitForWindowExposed(&dock));
        QTest::qWait(50);
    }
    // Where the value (angle, md) lies in the chart view's viewport.
    static QPoint viewportPoint(const app::UnrolledImageDock& dock, double angle_deg, double md_m) {
        const QPointF inChart =
            dock.chart()->mapToPosition(QPointF(angle_deg, md_m), dock.chart()->series().front());
        return dock.view()->mapFromScene(dock.chart()->mapToScene(inChart));
    }
};

std::size_t firstRowOf(const reconstruction::WellAnalysis& a, reconstruction::BoreholeClass c) {
    for (std::size_t i = 0; i < a.sections.size(); ++i)
        if (a.sections[i].cls == c) return i;
    return a.sections.size();
}

// Pixels of `image` that are neither the chart's white nor a grey (a departure's colour; the
// in-gauge grey and the axes' greys are left out).
int colouredPixels(const QImage& image) {
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            n += std::abs(c.red() - c.blue()) > 40 ? 1 : 0;
        }
    return n;
}

}  // namespace

TEST_F(UnrolledImageDockTest, DrawsTheDeparturesOfAWindowAroundTheCurrentDepth) {
    app::DeskModel model;
    model.addWell(test::syntheticDeskWell("example", 60.0, 0.1));
    app::UnrolledImageDock dock(&model);
    EXPECT_EQ(dock.objectName(), "unrolledImage");
    show(dock);
    // The window is 20 m about the current depth, kept inside the log.
    EXPECT_DOUBLE_EQ(dock.windowTop_m(), model.current()->geometry->table().depth_m.front());
    EXPECT_NEAR(dock.windowBottom_m() - dock.windowTop_m(), 20.0, 1e-9);
    // The bottom 20 m are in gauge: grey. In the breakout (245.9 x 217.9, major axis at 135)
    // the wall is 15 mm over the bit at 135 and 315 degrees, 1 mm over at 45 and 225.
    model.setCurrentDepth(model.current()->geometry->table().depth_m.back());
    QTest::qWait(20);
    const QImage gauge = dock.grab().toImage();
    const auto& analysis = *model.current()->analysis;
    const std::size_t breakout = firstRowOf(analysis, reconstruction::BoreholeClass::Breakout);
    ASSERT_LT(breakout, analysis.sections.size());
    model.setCurrentDepth(analysis.sections[breakout + 5].md_m);
    QTest::qWait(20);
    const QImage coloured = dock.grab().toImage();
    EXPECT_GT(colouredPixels(coloured), colouredPixels(gauge) + 2000);
    const auto& image = dock.image();
    ASSERT_GT(image.rows, 100);
    ASSERT_GT(image.columns, 100);
    int row = 0;
    while (row + 1 < image.rows && image.rowDepth_m(row) < model.currentDepth_m()) ++row;
    const auto at = [&](double angle) {
        return image.at(row, static_cast<int>(angle / 360.0 * image.columns));
    };
    EXPECT_NEAR(at(135.0), (245.9 - 215.9) / 2, 0.5);
    EXPECT_NEAR(at(315.0), (245.9 - 215.9) / 2, 0.5);
    EXPECT_NEAR(at(45.0), (217.9 - 215.9) / 2, 0.5);
    EXPECT_TRUE(dock.chart()->title().contains("bit radius"));
}

TEST_F(UnrolledImageDockTest, ClickSetsTheCurrentDepthAndAzimuthAndTheWheelZooms) {
    app::DeskModel model;
    model.addWell(test::syntheticDeskWell("example", 60.0, 0.1));
    app::UnrolledImageDock dock(&model);
    show(dock);
    const double target = dock.windowTop_m() + 12.34;
    QTest::mouseClick(dock.view()->viewport(), Qt::LeftButton, Qt::NoModifier,
                      viewportPoint(dock, 90.0, target));
    // Within a row (0.1 m) and a pixel of depth (20 m over some 500 pixels).
    EXPECT_NEAR(model.currentDepth_m(), target, 0.1);
    EXPECT_NEAR(model.currentAzimuth_deg(), 90.0, 1.5);
    // The click is inside the window: the window stays where it is.
    EXPECT_NEAR(dock.image().top_m, dock.windowTop_m(), 1e-9);

    const double before = dock.windowLength_m();
    QWheelEvent wheel(QPointF(50, 50), dock.view()->viewport()->mapToGlobal(QPoint(50, 50)),
                      QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase,
                      false);
    QApplication::sendEvent(dock.view()->viewport(), &wheel);
    EXPECT_NEAR(dock.windowLength_m(), before / 1.25, 1e-9);
    EXPECT_NEAR(dock.windowBottom_m() - dock.windowTop_m(), before / 1.25, 1e-9);
}

TEST_F(UnrolledImageDockTest, WithoutABitSizeDepartsFromTheReportsGauge) {
    io::SectionTable table =
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile("circle", 30.0, 0.1));
    table.bitSize_mm.clear();
    app::DeskModel model;
    model.addWell(test::deskWellOf(table, "no bit"));
    ASSERT_TRUE(model.current()->analysis->bitSizeFromSections);
    app::UnrolledImageDock dock(&model);
    show(dock);
    EXPECT_TRUE(dock.chart()->title().contains("no bit size"));
    // A gauge hole measured against its own median diameter: about 0 everywhere (the 48-gon's
    // equivalent diameter is a little under the circle's).
    const auto& image = dock.image();
    ASSERT_GT(image.rows, 0);
    for (int c = 0; c < image.columns; c += 10) EXPECT_NEAR(image.at(image.rows / 2, c), 0.0, 0.5);
    // High side in a vertical hole is north: the same picture.
    dock.referenceBox()->setCurrentIndex(1);
    EXPECT_NEAR(dock.image().at(image.rows / 2, 3), 0.0, 0.5);
}
