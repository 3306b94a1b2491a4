#include "app/desktop/breakouts_dock.h"

#include <cmath>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>
#include <QTableWidget>
#include <QTest>
#include <QtCharts/QAreaSeries>
#include <QtCharts/QChartView>
#include <QtCharts/QLineSeries>
#include <QtCharts/QPolarChart>

#include "app/desktop/desk_model.h"
#include "desk_test_well.h"
#include "reconstruction/analysis/breakout_rose.h"

using namespace caliper3d;
QT_CHARTS_USE_NAMESPACE

namespace {

class BreakoutsDockTest : public ::testing::Test {
protected:
    void SetUp() override {
        if (!test::deskApplication()) GTEST_SKIP() << "no display (run under xvfb-run)";
        m_model.addWell(test::exampleDeskWell());
    }
    const reconstruction::WellAnalysis& analysis() const { return *m_model.well(0).analysis; }
    std::unique_ptr<app::BreakoutsDock> shownDock() {
        auto dock = std::make_unique<app::BreakoutsDock>(m_model);
        dock->resize(420, 760);
        dock->show();
        EXPECT_TRUE(QTest::qWaitForWindowExposed(dock.get()));
        return dock;
    }
    app::DeskModel m_model;
};

}  // namespace

TEST_F(BreakoutsDockTest, ListsEveryZoneOfTheAnalysis) {
    app::BreakoutsDock dock(m_model);
    const auto& zones = analysis().zones;
    // The example: a breakout at 60-80 m, a washout at 150-160 m.
    ASSERT_EQ(zones.size(), 2u);
    QTableWidget* table = dock.zoneTable();
    ASSERT_EQ(table->rowCount(), 2);
    EXPECT_EQ(table->item(0, app::BreakoutsDock::kClass)->text(), "breakout");
    EXPECT_EQ(table->item(1, app::BreakoutsDock::kClass)->text(), "washout");
    for (int row = 0; row < 2; ++row) {
        const auto& z = zones[std::size_t(row)];
        EXPECT_NEAR(table->item(row, app::BreakoutsDock::kTop)->text().toDouble(), z.top_m, 0.005);
        EXPECT_NEAR(table->item(row, app::BreakoutsDock::kBottom)->text().toDouble(), z.bottom_m,
                    0.005);
        EXPECT_NEAR(table->item(row, app::BreakoutsDock::kLength)->text().toDouble(), z.length_m,
                    0.005);
    }
    EXPECT_NEAR(zones[0].top_m, 60.0, 0.1);
    EXPECT_TRUE(table->item(0, app::BreakoutsDock::kAzimuth)->text().startsWith("135"));
    // Mean dmax / dmin over the zone: near the ellipse's 245.9 x 217.9 mm.
    const QStringList diameters =
        table->item(0, app::BreakoutsDock::kDiameters)->text().split(" / ");
    ASSERT_EQ(diameters.size(), 2);
    EXPECT_NEAR(diameters[0].toDouble(), zones[0].meanDmax_mm, 0.05);
    EXPECT_NEAR(diameters[1].toDouble(), zones[0].meanDmin_mm, 0.05);
    EXPECT_NEAR(zones[0].meanDmax_mm, 245.9, 1.0);
    EXPECT_NEAR(zones[0].meanDmin_mm, 217.9, 1.0);
    // One breakout zone of some 20 m: WSM quality D.
    EXPECT_TRUE(dock.summaryText().contains("1 breakout zone,"));
    EXPECT_TRUE(dock.summaryText().contains("<b>D</b>"));
    EXPECT_TRUE(dock.summaryText().contains("SHmax 45"));
}

TEST_F(BreakoutsDockTest, ARowClickMovesTheCurrentDepthToTheZonesFirstRow) {
    const auto dock = shownDock();
    QTableWidget* table = dock->zoneTable();
    for (int row : {1, 0}) {
        const QRect cell = table->visualItemRect(table->item(row, app::BreakoutsDock::kTop));
        QTest::mouseClick(table->viewport(), Qt::LeftButton, {}, cell.center());
        // The zone's top is half a step above its first row: the current depth is that row.
        const auto& zone = analysis().zones[std::size_t(row)];
        EXPECT_EQ(m_model.currentRow(), zone.firstSection);
        EXPECT_NEAR(m_model.currentDepth_m(), zone.top_m, 0.05);
        EXPECT_EQ(table->currentRow(), row);
    }
    // Moved elsewhere, into the washout: its row is selected; out of every zone: none.
    m_model.setCurrentDepth(155.0);
    ASSERT_EQ(table->selectionModel()->selectedRows().size(), 1);
    EXPECT_EQ(table->selectionModel()->selectedRows().front().row(), 1);
    m_model.setCurrentDepth(120.0);
    EXPECT_TRUE(table->selectionModel()->selectedRows().empty());
}

TEST_F(BreakoutsDockTest, TheRoseHoldsTheCombinedBreakoutLengthMirrored) {
    app::BreakoutsDock dock(m_model);
    const auto& summary = analysis().breakouts;
    const reconstruction::BreakoutRose rose = reconstruction::breakoutRose(analysis().zones);
    EXPECT_NEAR(std::accumulate(rose.axial_m.begin(), rose.axial_m.end(), 0.0),
                summary.combinedLength_m, 1e-9);
    // As drawn: the outline's radius over each 10-degree bin, all round.
    QAreaSeries* area = nullptr;
    std::vector<QLineSeries*> lines;
    for (QAbstractSeries* s : dock.rose()->series()) {
        if (auto* a = qobject_cast<QAreaSeries*>(s)) area = a;
        if (auto* l = qobject_cast<QLineSeries*>(s)) lines.push_back(l);
    }
    ASSERT_NE(area, nullptr);
    std::vector<double> drawn(36, 0.0);
    for (const QPointF& p : area->upperSeries()->pointsVector()) {
        const double middle = std::fmod(p.x(), 10.0);
        if (middle > 4.0 && middle < 6.0) drawn[std::size_t(p.x() / 10.0)] = p.y();
    }
    double firstHalf = 0.0;
    for (std::size_t i = 0; i < 18; ++i) {
        EXPECT_DOUBLE_EQ(drawn[i], drawn[i + 18]) << "bin " << i;
        firstHalf += drawn[i];
    }
    EXPECT_NEAR(firstHalf, summary.combinedLength_m, 1e-9);
    // All of it at 135 (and 315): the breakout's azimuth.
    EXPECT_NEAR(drawn[13], summary.combinedLength_m, 1e-9);
    EXPECT_NEAR(drawn[31], summary.combinedLength_m, 1e-9);
    // The mean and SHmax lines, each through the centre at its azimuth and half a turn on.
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_NEAR(lines[0]->at(0).x(), 135.0, 0.5);
    EXPECT_NEAR(lines[0]->at(3).x(), 315.0, 0.5);
    EXPECT_NEAR(lines[1]->at(0).x(), 45.0, 0.5);
    EXPECT_NEAR(lines[1]->at(3).x(), 225.0, 0.5);
}

TEST_F(BreakoutsDockTest, SaysAnalysingUntilTheAnalysisIsInThenDrawsTheRose) {
    app::DeskModel model;
    model.addWell(test::exampleDeskWell(false));
    app::BreakoutsDock dock(model);
    EXPECT_EQ(dock.zoneTable()->rowCount(), 0);
    EXPECT_EQ(dock.summaryText(), "analysing...");
    model.updateWell(0, test::exampleDeskWell());
    EXPECT_EQ(dock.zoneTable()->rowCount(), 2);

    const auto shown = shownDock();
    EXPECT_GT(test::drawnPixels(*shown->roseView()), 3000);
    // The petals in the palette's breakout orange (230, 159, 0) at alpha 200 over white.
    EXPECT_GT(test::pixelsNear(*shown->roseView(), QColor(234, 174, 43), 14), 200);
}
