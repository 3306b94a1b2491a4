// Two runs of one well in the window: opened as one well (WellSession::addRun), grouped in the
// wells dock, depth-matched, both sections in the inspector, both traces in the log track,
// and the wall coloured by their change. A synthetic pair with known differences: the second
// run's counter 0.35 m deeper, its tool 90 degrees round, its washout 10 mm wider.
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <QSignalSpy>
#include <QTest>
#include <QTreeWidget>
#include <QtCharts/QChart>
#include <QtCharts/QLineSeries>

#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>
#include <Inventor/nodes/SoCamera.h>

#include "app/desktop/desk_model.h"
#include "app/desktop/log_track_dock.h"
#include "app/desktop/main_window.h"
#include "app/desktop/section_inspector_dock.h"
#include "app/desktop/well_navigator.h"
#include "app/desktop/well_session.h"
#include "app/desktop/wells_dock.h"
#include "desktop_test_support.h"
#include "io/las_writer.h"
#include "reconstruction/mesh/colour_map.h"
#include "scenegraph/colour_legend.h"
#include "support/run_pair.h"

using namespace caliper3d;
using reconstruction::SyntheticFeature;
using reconstruction::SyntheticWellSpec;

namespace {

// 60 m of vertical hole with a washout at 30-32 m; the second run deeper, turned, widened.
SyntheticWellSpec firstRun() {
    return reconstruction::widenedWashoutRuns(60.0, 30.0).first;
}
SyntheticWellSpec secondRun() {
    return reconstruction::widenedWashoutRuns(60.0, 30.0).second;
}

class WellRunsTest : public ::testing::Test {
protected:
    void SetUp() override {
        if (!test::ensureGuiApplication()) GTEST_SKIP() << "no display (run under xvfb-run)";
        // A folder of the test's own: ctest runs the tests as processes at once.
        const auto dir = test::freshScratchFolder(
            std::string("well_runs_") +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        m_run1 = dir / "run1.las";
        m_run2 = dir / "run2.las";
        io::writeLasFile(m_run1.string(), reconstruction::makeSyntheticWell(firstRun()));
        io::writeLasFile(m_run2.string(), reconstruction::makeSyntheticWell(secondRun()));
    }
    // Opens the two runs as one well and waits until both are analysed and matched.
    bool openRuns(app::WellSession& session, const app::DeskModel& model) {
        app::LoadOptions options;
        const int main = session.openWell(QString::fromStdString(m_run1.string()), options);
        app::WellSource second;
        second.path = m_run2.string();
        session.addRun(second, options, main);
        return test::waitUntil(
            [&] {
                return model.wellCount() == 2 && model.well(0).analysis && model.well(1).analysis &&
                       model.well(1).mapping;
            },
            120000);
    }
    std::filesystem::path m_run1, m_run2;
};

}  // namespace

TEST(DeskModelRunsTest, MatchedDepthsGoThroughTheMainRun) {
    app::DeskModel model;
    app::DeskWell main, second, third, alone;
    main.id = 10;
    second.id = 11;
    third.id = 12;
    alone.id = 13;
    model.addWell(main);
    model.addWell(second);
    model.addWell(third);
    model.addWell(alone);
    for (int i = 0; i < 3; ++i) model.setRunOf(i, 10);
    reconstruction::DepthMapping shift;
    shift.shift_m = 0.35;
    app::DeskWell record = model.well(1);
    record.mapping = shift;
    model.updateWell(1, record);
    EXPECT_EQ(model.otherRuns(0), (std::vector<int>{1, 2}));
    EXPECT_EQ(model.otherRuns(1), (std::vector<int>{0, 2}));
    EXPECT_TRUE(model.otherRuns(3).empty());
    EXPECT_EQ(model.mainRun(2), 0);
    EXPECT_EQ(model.mainRun(3), 3);
    EXPECT_DOUBLE_EQ(model.matchedDepth_m(0, 1, 100.0), 100.35);
    EXPECT_DOUBLE_EQ(model.matchedDepth_m(1, 0, 100.35), 100.0);
    EXPECT_TRUE(std::isnan(model.matchedDepth_m(0, 2, 100.0)));  // not matched yet
    EXPECT_TRUE(std::isnan(model.matchedDepth_m(0, 3, 100.0)));  // another well
    EXPECT_DOUBLE_EQ(model.matchedDepth_m(3, 3, 7.0), 7.0);
}

TEST_F(WellRunsTest, TheRunsOpenAsOneWellGroupedAndMatched) {
    app::DeskModel model;
    app::WellSession session(model, nullptr);
    app::WellsDock wells(model);
    ASSERT_TRUE(openRuns(session, model)) << "the runs did not load, analyse and match";
    EXPECT_EQ(model.well(0).runOf, model.well(0).id);
    EXPECT_EQ(model.well(1).runOf, model.well(0).id);
    EXPECT_NEAR(model.well(1).mapping->shift_m, 0.35, 0.01);
    EXPECT_EQ(model.well(1).mapping->curve, "GR");
    // The second run is hidden (its wall lies on the main run's) and listed under the first.
    EXPECT_TRUE(model.well(0).visible);
    EXPECT_FALSE(model.well(1).visible);
    ASSERT_NE(wells.item(1), nullptr);
    EXPECT_EQ(wells.item(1)->parent(), wells.item(0));
    EXPECT_EQ(wells.tree()->topLevelItemCount(), 1);
    EXPECT_NE(wells.item(0)->text(app::WellsDock::Name).indexOf("main run, run1.las"), -1);
    EXPECT_NE(wells.item(1)->text(app::WellsDock::State).indexOf("matched 0.35"), -1)
        << wells.item(1)->text(app::WellsDock::State).toStdString();
    // Clicking the second run opens it at the depth matched to the current one.
    model.setCurrent(0, 20.0);
    wells.tree()->itemClicked(wells.item(1), 0);
    EXPECT_EQ(model.currentWell(), 1);
    EXPECT_NEAR(model.currentDepth_m(), 20.35, 0.026);
}

TEST_F(WellRunsTest, TheInspectorAndTheLogTrackShowBothRuns) {
    app::DeskModel model;
    app::WellSession session(model, nullptr);
    ASSERT_TRUE(openRuns(session, model));
    app::SectionInspectorDock inspector(&model);
    app::LogTrackDock track(model);
    track.resize(320, 720);
    track.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&track));
    QTest::qWait(50);
    model.setCurrent(0, 31.0);  // in the washout of both
    EXPECT_EQ(inspector.otherWell(), 1);
    EXPECT_NEAR(inspector.otherDepth_m(), 31.35, 0.01);
    ASSERT_TRUE(inspector.outline().measured);
    ASSERT_TRUE(inspector.otherOutline().measured);
    // Each spline about its own tool axis: run 1's washout 265.9 mm across, run 2's 275.9.
    for (const auto& p : inspector.outline().spline) EXPECT_NEAR(p.radius_mm, 132.95, 1.0);
    for (const auto& p : inspector.otherOutline().spline) EXPECT_NEAR(p.radius_mm, 137.95, 1.0);
    EXPECT_GT(inspector.series("other run")->count(), 100);
    // Above the washout the runs read alike.
    model.setCurrent(0, 10.0);
    EXPECT_NEAR(inspector.otherDepth_m(), 10.35, 0.01);
    ASSERT_TRUE(inspector.otherOutline().measured);
    EXPECT_NEAR(inspector.otherOutline().spline.front().radius_mm,
                inspector.outline().spline.front().radius_mm, 1.0);

    // The log track: run 2's dmax at its depths matched into run 1's, the washout's 275.9 mm
    // at 30-32 m of run 1 (30.35-32.35 m of its own).
    std::size_t inWashout = 0;
    for (QtCharts::QAbstractSeries* s : track.chart()->series()) {
        auto* line = qobject_cast<QtCharts::QLineSeries*>(s);
        if (!line || line->name() != "run2.las dmax") continue;
        for (const QPointF& p : line->pointsVector())
            if (p.y() > 30.2 && p.y() < 31.8) {
                EXPECT_NEAR(p.x(), 275.9, 1.0) << p.y();
                ++inWashout;
            }
    }
    EXPECT_GT(inWashout, 5u);
    EXPECT_NE(track.legendText().indexOf("run2.las&nbsp;dmax"), -1)
        << track.legendText().toStdString();
}

TEST_F(WellRunsTest, TheWallIsColouredByTheChangeBetweenTheRuns) {
    app::DeskModel model;
    app::WellSession session(model, nullptr);
    ASSERT_TRUE(openRuns(session, model));
    const auto quantities = session.colourQuantities();
    EXPECT_NE(std::find(quantities.begin(), quantities.end(), "change"), quantities.end());
    reconstruction::ColourRequest change;
    change.quantity = "change";
    // The runs are compared on a worker: the colours come in through the event loop.
    QSignalSpy looks(&session, &app::WellSession::lookChanged);
    ASSERT_TRUE(session.restyle(1.0, change));
    ASSERT_TRUE(test::waitUntil(
        [&] { return session.legend() && session.legend()->title == "run1.las minus run2.las"; },
        120000));
    EXPECT_GE(looks.count(), 1);
    EXPECT_EQ(scenegraph::legendText(*session.legend()).labels[1], "0 (no change)");
    // Run 1's washout is 10 mm narrower than run 2's: the blue end; its gauge hole grey.
    const auto& colouring = model.well(0).geometry->options().colouring;
    ASSERT_NE(colouring, nullptr);
    const auto row = [&](double md) {
        return app::DeskModel::nearestRow(*model.well(0).geometry, md);
    };
    const auto expectColour = [](std::uint32_t colour, std::uint32_t expected) {
        EXPECT_NEAR(reconstruction::red(colour), reconstruction::red(expected), 3);
        EXPECT_NEAR(reconstruction::green(colour), reconstruction::green(expected), 3);
        EXPECT_NEAR(reconstruction::blue(colour), reconstruction::blue(expected), 3);
    };
    expectColour(colouring->colour(row(31.0), 130.0), reconstruction::divergingColour(0.0));
    expectColour(colouring->colour(row(10.0), 108.0), reconstruction::divergingColour(0.5));
    // A well with no other run cannot be coloured so, and says why.
    app::DeskModel single;
    app::WellSession alone(single, nullptr);
    alone.openWell(QString::fromStdString(m_run1.string()), app::LoadOptions{});
    ASSERT_TRUE(test::waitUntil([&] { return single.wellCount() == 1 && single.well(0).analysis; },
                                120000));
    QSignalSpy status(&alone, &app::WellSession::status);
    EXPECT_FALSE(alone.restyle(1.0, change));
    ASSERT_GE(status.count(), 1);
    EXPECT_NE(status.last().at(0).toString().indexOf("no other run"), -1);
}

// The change legend arrives seconds after the window framed the runs, and is wider than the
// one it replaces: the view frames the runs again beside it, as a framing done with it would;
// once the user has moved the camera, a new legend leaves it where it is.
TEST_F(WellRunsTest, TheViewFramesTheRunsAgainBesideALegendThatArrivesLater) {
    app::MainWindow window;
    window.resize(900, 700);
    window.show();
    app::WellSession& session = window.session();
    ASSERT_TRUE(openRuns(session, window.model()));
    ASSERT_TRUE(test::waitUntil([&] { return !session.loading() && session.legend(); }, 120000));
    QTest::qWait(100);  // the framing after the load, through the event loop
    const float before = scenegraph::legendWidth_px(*session.legend());
    SoCamera* camera = window.viewer()->getCamera();
    ASSERT_NE(camera, nullptr);
    const auto where = [camera] {
        return std::make_pair(camera->position.getValue(), camera->focalDistance.getValue());
    };

    reconstruction::ColourRequest change;
    change.quantity = "change";
    ASSERT_TRUE(session.restyle(1.0, change));
    ASSERT_TRUE(test::waitUntil(
        [&] { return session.legend() && session.legend()->title == "run1.las minus run2.las"; },
        120000));
    QTest::qWait(100);
    const float after = scenegraph::legendWidth_px(*session.legend());
    ASSERT_NE(before, after) << "the test needs legends of different widths";
    const auto reframed = where();
    window.navigator().frameLogs([&] { return session.wellScenes(); });
    // The same framing (to float rounding: it starts from where the camera is).
    const auto [eye, focal] = where();
    EXPECT_LT((eye - reframed.first).length(), 1e-3f * focal)
        << "the view was not framed again beside the new legend";
    EXPECT_NEAR(focal, reframed.second, 1e-3f * focal);

    // Moved by the user: the next legend (back to the departure from bit size) does not move it.
    camera->position.setValue(camera->position.getValue() + SbVec3f(1.0f, 0.0f, 0.0f));
    const auto moved = where();
    reconstruction::ColourRequest departure;
    departure.quantity = "departure";
    ASSERT_TRUE(session.restyle(1.0, departure));
    ASSERT_TRUE(test::waitUntil(
        [&] { return session.legend() && session.legend()->title != "run1.las minus run2.las"; },
        120000));
    QTest::qWait(100);
    EXPECT_NE(scenegraph::legendWidth_px(*session.legend()), after);
    EXPECT_EQ(where(), moved);
}
