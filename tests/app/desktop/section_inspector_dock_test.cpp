#include "app/desktop/section_inspector_dock.h"

#include <cmath>

#include <gtest/gtest.h>
#include <QApplication>
#include <QDockWidget>
#include <QLabel>
#include <QMainWindow>
#include <QtCharts/QPolarChart>
#include <QtCharts/QXYSeries>

#include "desk_test_well.h"
#include "reconstruction/analysis/report_writer.h"
#include "test_support.h"

using namespace caliper3d;

namespace {

class SectionInspectorDockTest : public ::testing::Test {
protected:
    void SetUp() override {
        if (!test::deskApplication()) GTEST_SKIP() << "no display (run under xvfb-run)";
    }
};

// The report's text for `field` of `section`.
QString reportField(const reconstruction::SectionResult& section, const std::string& field) {
    for (const auto& [name, text] : reconstruction::sectionReportFields(section))
        if (name == field) return QString::fromStdString(text);
    return "(not in the report)";
}

const char* const kShown[] = {"md_m",
                              "dmin_mm",
                              "dmax_mm",
                              "ellipticity",
                              "major_azimuth_deg",
                              "area_mm2",
                              "equivalent_diameter_mm",
                              "centre_offset_mm",
                              "class"};

std::size_t firstRowOf(const reconstruction::WellAnalysis& a, reconstruction::BoreholeClass c) {
    for (std::size_t i = 0; i < a.sections.size(); ++i)
        if (a.sections[i].cls == c) return i;
    return a.sections.size();
}

// Points of a polar series inside the angular axis's range (the rest are the 0-degree crossings).
int onRange(const QtCharts::QXYSeries* s) {
    int n = 0;
    for (const QPointF& p : s->points()) n += p.x() >= 0.0 && p.x() <= 360.0 ? 1 : 0;
    return n;
}

}  // namespace

TEST_F(SectionInspectorDockTest, ShowsTheReportsNumbersForTheCurrentRowAndFollowsTheDepth) {
    app::DeskModel model;
    model.addWell(test::syntheticDeskWell("example", 30.0, 0.1));
    app::SectionInspectorDock dock(&model);
    EXPECT_EQ(dock.objectName(), "sectionInspector");
    const auto& analysis = *model.current()->analysis;
    const std::size_t breakout = firstRowOf(analysis, reconstruction::BoreholeClass::Breakout);
    ASSERT_LT(breakout, analysis.sections.size());
    for (std::size_t row : {std::size_t{0}, breakout + 2}) {
        model.setCurrentDepth(analysis.sections[row].md_m);
        ASSERT_EQ(model.currentRow(), row);
        for (const char* field : kShown) {
            // An empty field of a measured section: a round section's axis.
            const QString report = reportField(analysis.sections[row], field);
            EXPECT_EQ(dock.value(field), report.isEmpty() ? "none" : report)
                << field << " at row " << row;
        }
    }
    // In the breakout the ellipse is the report's: 245.9 x 217.9 with its major axis at 135.
    EXPECT_EQ(dock.value("class"), "breakout");
    EXPECT_NEAR(dock.value("dmax_mm").toDouble(), 245.9, 0.5);
    EXPECT_NEAR(dock.outline().ellipse.majorAngle_deg,
                analysis.sections[breakout + 2].majorAzimuth_deg, test::storedInFloat(180.0));
}

TEST_F(SectionInspectorDockTest, HeadingNeverRunsOverTheNumbersWhenTheDockIsShort) {
    // As the window lays it out: in the right column above another dock, so the column's
    // height is shared and the inspector gets less than its plot and numbers ask for. The
    // north line as a LAS file's curve descriptions make it: four lines at this width.
    io::SectionTable table =
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile("example", 30.0, 0.1));
    table.north =
        "P1AZ (pad-1 azimuth) from true north, its description 'pad 1 azimuth from true north'; "
        "HAZI (hole azimuth) from true north, its description 'hole azimuth from true north'";
    app::DeskModel model;
    model.addWell(test::deskWellOf(std::move(table), "CALIPER3D"));
    QMainWindow window;
    window.setCentralWidget(new QWidget);
    auto* dock = new app::SectionInspectorDock(&model, &window);
    window.addDockWidget(Qt::RightDockWidgetArea, dock);
    auto* below = new QDockWidget("below", &window);
    auto* filler = new QWidget;
    filler->setMinimumSize(200, 260);
    below->setWidget(filler);
    window.addDockWidget(Qt::RightDockWidgetArea, below);
    window.show();
    const auto* heading = dock->findChild<QLabel*>("heading");
    const auto* md = dock->findChild<QLabel*>("value_md_m");
    ASSERT_TRUE(heading && md);
    for (const QSize size : {QSize(1400, 1000), QSize(1100, 800), QSize(900, 700)}) {
        window.resize(size);
        for (int i = 0; i < 5; ++i) QApplication::processEvents();
        ASSERT_TRUE(heading->isVisible() && md->isVisible());
        const QRect h(heading->mapTo(&window, QPoint(0, 0)), heading->size());
        const QRect m(md->mapTo(&window, QPoint(0, 0)), md->size());
        EXPECT_GE(heading->height(), heading->heightForWidth(heading->width()))
            << size.width() << " x " << size.height();
        EXPECT_LE(h.bottom(), m.top()) << "the heading runs over the first number in a window of "
                                       << size.width() << " x " << size.height();
    }
}

TEST_F(SectionInspectorDockTest, ChartHasEachSeriesWithItsPoints) {
    app::DeskModel model;
    model.addWell(test::syntheticDeskWell("example", 30.0, 0.1));
    app::SectionInspectorDock dock(&model);
    const int arms = model.current()->geometry->table().armCount;
    using Dock = app::SectionInspectorDock;
    ASSERT_NE(dock.series("pads"), nullptr);
    EXPECT_EQ(dock.series("pads")->count(), arms);
    // Closed curves: every sample and the first again, plus one crossing of the 0-degree ray
    // (two points just off the axis's range).
    for (const char* curve : {"spline", "ellipse", "bit size"}) {
        EXPECT_EQ(onRange(dock.series(curve)), Dock::kSplineSamples + 1) << curve;
        EXPECT_EQ(dock.series(curve)->count(), Dock::kSplineSamples + 3) << curve;
    }
    for (const QPointF& p : dock.series("bit size")->points()) EXPECT_NEAR(p.y(), 215.9 / 2, 1e-9);
    // A pad lies on the spline: the pads are its knots.
    const auto& outline = dock.outline();
    EXPECT_NEAR(outline.spline.front().radius_mm, outline.pads.front().radius_mm, 1e-9);
    // Round (in gauge): no axes to draw; in the breakout, both.
    EXPECT_EQ(dock.series("major axis")->count(), 0);
    const auto& analysis = *model.current()->analysis;
    model.setCurrentRow(0, firstRowOf(analysis, reconstruction::BoreholeClass::Breakout) + 2);
    EXPECT_GE(dock.series("major axis")->count(), 33);
    EXPECT_GE(dock.series("minor axis")->count(), 33);
    model.setCurrentRow(0, 0);
    // The top of the example is vertical: north marked, no high side.
    EXPECT_EQ(dock.series("north")->count(), 2);
    EXPECT_DOUBLE_EQ(dock.series("north")->at(0).x(), 0.0);
    EXPECT_EQ(dock.series("high side")->count(), 0);
    EXPECT_TRUE(dock.chart()->title().contains("from north"));
    // Deeper, where the well has built angle, the high side is marked too.
    model.setCurrentDepth(model.current()->geometry->table().depth_m.back());
    EXPECT_EQ(dock.series("high side")->count(), 2);
}

TEST_F(SectionInspectorDockTest, SaysAnalysingUntilTheAnalysisAndNoDataWhereThereIsNone) {
    io::SectionTable table =
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile("circle", 10.0, 0.1));
    for (std::size_t row = 40; row < 50; ++row)
        for (int k = 0; k < table.armCount; ++k) table.radii(row)[k] = io::kNaN;
    app::DeskWell well = test::deskWellOf(table, "gap");
    const auto analysis = well.analysis;
    well.analysis.reset();
    app::DeskModel model;
    model.addWell(well);
    app::SectionInspectorDock dock(&model);
    model.setCurrentRow(0, 45);
    EXPECT_EQ(dock.value("dmin_mm"), "analysing...");
    EXPECT_EQ(dock.value("class"), "analysing...");
    EXPECT_FALSE(dock.outline().measured);
    EXPECT_EQ(dock.series("spline")->count(), 0);
    EXPECT_TRUE(dock.chart()->title().contains("no data"));
    EXPECT_EQ(dock.series("major axis")->count(), 0);

    well.analysis = analysis;
    model.updateWell(0, well);
    EXPECT_EQ(dock.value("md_m"), reportField(analysis->sections[45], "md_m"));
    EXPECT_EQ(dock.value("dmin_mm"), "no data");
    EXPECT_EQ(dock.value("class"), "no_data");
    model.setCurrentRow(0, 60);
    EXPECT_EQ(dock.value("dmin_mm"), reportField(analysis->sections[60], "dmin_mm"));
    EXPECT_EQ(dock.value("class"), "in_gauge");
}
