#include "app/desktop/log_track_dock.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include <gtest/gtest.h>
#include <QApplication>
#include <QGraphicsScene>
#include <QGraphicsTextItem>
#include <QTest>
#include <QWheelEvent>
#include <QtCharts/QAreaSeries>
#include <QtCharts/QChart>
#include <QtCharts/QChartView>
#include <QtCharts/QLegendMarker>
#include <QtCharts/QLineSeries>

#include "app/desktop/desk_model.h"
#include "app/desktop/trace_decimation.h"
#include "desk_test_well.h"

using namespace caliper3d;
QT_CHARTS_USE_NAMESPACE

namespace {

class LogTrackDockTest : public ::testing::Test {
protected:
    void SetUp() override {
        if (!test::deskApplication()) GTEST_SKIP() << "no display (run under xvfb-run)";
    }
    // The dock on screen, 320 x 720, over `model`.
    static std::unique_ptr<app::LogTrackDock> shownDock(app::DeskModel& model) {
        auto dock = std::make_unique<app::LogTrackDock>(model);
        dock->resize(320, 720);
        dock->show();
        EXPECT_TRUE(QTest::qWaitForWindowExposed(dock.get()));
        QTest::qWait(50);  // the chart's layout, then the queued redraw at the plot's height
        return dock;
    }
    // The points of every line series called `name`, as (depth, value).
    static std::vector<QPointF> points(const QChart& chart, const QString& name) {
        std::vector<QPointF> out;
        for (QAbstractSeries* s : chart.series())
            if (auto* line = qobject_cast<QLineSeries*>(s); line && line->name() == name)
                for (const QPointF& p : line->pointsVector()) out.emplace_back(p.y(), p.x());
        return out;
    }
    // The viewport position of (value, depth) on the track.
    static QPoint at(const app::LogTrackDock& dock, double value, double md_m) {
        QChart* chart = dock.chart();
        const QPointF inChart = chart->mapToPosition(QPointF(value, md_m), chart->series().back());
        return dock.chartView()->mapFromScene(chart->mapToScene(inChart));
    }
};

}  // namespace

TEST_F(LogTrackDockTest, SaysAnalysingUntilTheAnalysisIsIn) {
    app::DeskModel model;
    // On screen from the start, as in the window: its axes are laid out before any well.
    const auto shown = shownDock(model);
    app::LogTrackDock& dock = *shown;
    EXPECT_FALSE(dock.showsChart());
    EXPECT_EQ(dock.message(), "No well loaded");
    const int well = model.addWell(test::exampleDeskWell(false));
    EXPECT_FALSE(dock.showsChart());
    EXPECT_EQ(dock.message(), "analysing...");
    model.updateWell(well, test::exampleDeskWell(true));
    EXPECT_TRUE(dock.showsChart());
    QTest::qWait(50);
    EXPECT_TRUE(dock.legendText().contains("breakout"));
    EXPECT_TRUE(dock.legendText().contains("dmax"));
    // A 300 m well is shown whole.
    const auto& depth = model.well(well).geometry->table().depth_m;
    EXPECT_DOUBLE_EQ(dock.top_m(), depth.front());
    EXPECT_DOUBLE_EQ(dock.bottom_m(), depth.back());
}

TEST_F(LogTrackDockTest, SeriesHoldTheAnalysisValuesThinnedToThePlotsHeight) {
    app::DeskModel model;
    model.addWell(test::exampleDeskWell());
    const auto dock = shownDock(model);
    const reconstruction::WellAnalysis& analysis = *model.well(0).analysis;
    std::vector<double> md, dmax, dmin;
    std::map<double, std::size_t> rowOf;
    for (std::size_t i = 0; i < analysis.sections.size(); ++i) {
        md.push_back(analysis.sections[i].md_m);
        dmax.push_back(analysis.sections[i].dmax_mm);
        dmin.push_back(analysis.sections[i].dmin_mm);
        rowOf[md.back()] = i;
    }
    const int height = int(std::lround(dock->chart()->plotArea().height()));
    ASSERT_GT(height, 300);
    const std::vector<QPointF> maxima = points(*dock->chart(), "dmax");
    // Thinned: some two points a pixel of the 6000 rows, exactly as decimateTrace says.
    EXPECT_LE(maxima.size(), std::size_t(2 * (height + 1) + 2));
    std::vector<QPointF> expected;
    for (const auto& run : app::decimateTrace(md, dmax, dock->top_m(), dock->bottom_m(), height))
        for (const auto& p : run) expected.emplace_back(p.depth_m, p.value);
    EXPECT_EQ(maxima, expected);
    // Each point is a row of the analysis: the breakout's 245.9 mm and the washout's 265.9 mm
    // are there at their depths, and dmin is the gauge's 215.9 mm in the washout.
    double breakout = 0.0, washout = 0.0;
    for (const QPointF& p : maxima) {
        ASSERT_EQ(rowOf.count(p.x()), 1u) << p.x();
        EXPECT_DOUBLE_EQ(p.y(), dmax[rowOf[p.x()]]);
        if (p.x() > 61.0 && p.x() < 79.0) breakout = std::max(breakout, p.y());
        if (p.x() > 151.0 && p.x() < 159.0) washout = std::max(washout, p.y());
    }
    EXPECT_NEAR(breakout, 245.9, 0.5);
    EXPECT_NEAR(washout, 265.9, 0.5);
    for (const QPointF& p : points(*dock->chart(), "dmin"))
        EXPECT_DOUBLE_EQ(p.y(), dmin[rowOf.at(p.x())]);
    EXPECT_FALSE(points(*dock->chart(), "bit size").empty());
    // The breakout's band spans its zone, in the legend once.
    int breakoutBands = 0;
    for (QAbstractSeries* s : dock->chart()->series())
        if (auto* area = qobject_cast<QAreaSeries*>(s); area && area->name() == "breakout") {
            ++breakoutBands;
            const auto band = area->upperSeries()->pointsVector();
            EXPECT_NEAR(band.front().y(), 60.0, 0.1);
            EXPECT_NEAR(band.back().y(), 80.1, 0.1);
        }
    EXPECT_EQ(breakoutBands, 1);
}

TEST_F(LogTrackDockTest, AClickOrADragSetsTheCurrentDepthAndTheTrackFollowsIt) {
    app::DeskModel model;
    model.addWell(test::exampleDeskWell());
    const auto dock = shownDock(model);
    dock->setDepthWindow(60.0, 80.0);  // 20 m: a pixel is less than a row (5 cm)
    QTest::qWait(20);
    const double step_m = 0.05;
    QTest::mouseClick(dock->chartView()->viewport(), Qt::LeftButton, {}, at(*dock, 230.0, 70.0));
    EXPECT_NEAR(model.currentDepth_m(), 70.0, 2 * step_m);
    // A drag: pressed at 65 m, released at 75.5 m.
    QWidget* viewport = dock->chartView()->viewport();
    QTest::mousePress(viewport, Qt::LeftButton, {}, at(*dock, 230.0, 65.0));
    EXPECT_NEAR(model.currentDepth_m(), 65.0, 2 * step_m);
    QMouseEvent move(QEvent::MouseMove, at(*dock, 230.0, 75.5), Qt::NoButton, Qt::LeftButton,
                     Qt::NoModifier);
    QApplication::sendEvent(viewport, &move);
    QTest::mouseRelease(viewport, Qt::LeftButton, {}, at(*dock, 230.0, 75.5));
    EXPECT_NEAR(model.currentDepth_m(), 75.5, 2 * step_m);
    // Set elsewhere (the 3D view, a zone's row), the depth comes into view, the span kept.
    model.setCurrentDepth(200.0);
    EXPECT_LT(dock->top_m(), 200.0);
    EXPECT_GT(dock->bottom_m(), 200.0);
    EXPECT_NEAR(dock->bottom_m() - dock->top_m(), 20.0, 1e-9);
}

TEST_F(LogTrackDockTest, TheWheelZoomsAboutThePointer) {
    app::DeskModel model;
    model.addWell(test::exampleDeskWell());
    const auto dock = shownDock(model);
    dock->setDepthWindow(100.0, 200.0);
    QTest::qWait(20);
    const QPoint pointer = at(*dock, 230.0, 125.0);
    QWheelEvent wheel(pointer, dock->chartView()->viewport()->mapToGlobal(pointer), QPoint(),
                      QPoint(0, 120), Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
    QApplication::sendEvent(dock->chartView()->viewport(), &wheel);
    // One notch: 1.25 times closer, 125 m where it was, a quarter of the way down.
    EXPECT_NEAR(dock->bottom_m() - dock->top_m(), 80.0, 1e-6);
    EXPECT_NEAR(dock->top_m(), 125.0 - 0.25 * 80.0, 0.5);
    // Out as far as the well goes, no further.
    for (int i = 0; i < 20; ++i) dock->zoom(0.5, 150.0);
    const auto& depth = model.well(0).geometry->table().depth_m;
    EXPECT_DOUBLE_EQ(dock->top_m(), depth.front());
    EXPECT_DOUBLE_EQ(dock->bottom_m(), depth.back());
}

TEST_F(LogTrackDockTest, LongWellsOpenOnAWindowAroundTheCurrentDepth) {
    const double length_m = 2000.0;
    auto table = std::make_shared<const io::SectionTable>(reconstruction::makeSyntheticWell(
        reconstruction::syntheticProfile("circle", length_m, 0.5)));
    app::DeskWell well;
    well.geometry = std::make_shared<const reconstruction::WellGeometry>(
        table, reconstruction::GeometryOptions{});
    well.analysis = std::make_shared<const reconstruction::WellAnalysis>(
        reconstruction::analyseWell(*well.geometry, reconstruction::AnalysisOptions{}));
    app::DeskModel model;
    model.addWell(well);
    model.setCurrentDepth(1000.0);
    app::LogTrackDock dock(model);
    EXPECT_NEAR(dock.bottom_m() - dock.top_m(), app::LogTrackDock::kDefaultSpan_m, 1e-9);
    EXPECT_NEAR(0.5 * (dock.top_m() + dock.bottom_m()), 1000.0, 0.5);
}

TEST_F(LogTrackDockTest, DrawsTheCurvesAndTheBands) {
    app::DeskModel model;
    model.addWell(test::exampleDeskWell());
    const auto dock = shownDock(model);
    // The breakout's dmax (245.9 mm) is drawn at its depth, down the page: a curve's dark
    // pixels there (black dmax, green dmin; the bands and grid are light), and none at the
    // mirror depth, where an axis drawn the other way would put it.
    const QImage image = dock->chartView()->grab().toImage();
    auto curveNear = [&](double value, double md_m) {
        const QPoint centre = at(*dock, value, md_m);
        int dark = 0;
        for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -3; dx <= 3; ++dx)
                dark += qGray(image.pixel(centre + QPoint(dx, dy))) < 150;
        return dark;
    };
    EXPECT_GT(curveNear(245.9, 70.0), 0);
    EXPECT_EQ(curveNear(245.9, 230.0), 0);
    EXPECT_GT(curveNear(265.9, 155.0), 0);
    EXPECT_EQ(curveNear(265.9, 145.0), 0);
    const int drawn = test::drawnPixels(*dock->chartView());
    EXPECT_GT(drawn, 5000);
    // The breakout's band: the palette's orange (230, 159, 0) at alpha 120 over white.
    const QColor band(243, 210, 135);
    EXPECT_GT(test::pixelsNear(*dock->chartView(), band, 12), 500);
}

TEST_F(LogTrackDockTest, TheDiameterAxisLabelsAreNeverCutShort) {
    app::DeskModel model;
    model.addWell(test::exampleDeskWell(true));
    auto dock = shownDock(model);
    // From the dock's narrowest to a wide one: as many labels as fit whole, never "1...".
    for (int width : {150, 180, 200, 240, 320, 480}) {
        dock->resize(width, 720);
        QTest::qWait(80);  // the chart's layout, then the queued fit to its width
        QApplication::processEvents();
        const qreal top = dock->chart()->plotArea().top();
        int labels = 0;
        for (QGraphicsItem* item : dock->chart()->scene()->items()) {
            auto* text = dynamic_cast<QGraphicsTextItem*>(item);
            if (!text || !text->isVisible()) continue;
            const QString shown = text->toPlainText();
            EXPECT_FALSE(shown.contains(QChar(0x2026)) || shown.contains("..."))
                << "width " << width << ": '" << shown.toStdString() << "'";
            if (text->sceneBoundingRect().bottom() <= top && !shown.isEmpty() && shown[0].isDigit())
                ++labels;  // a value label above the plot
        }
        EXPECT_GE(labels, 2) << "width " << width;
    }
}
