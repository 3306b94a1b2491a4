// The wells shown, with no window: opening, adding, restyling, showing and hiding, cancelling,
// all through WellSession and read back from the DeskModel, the only store.
#include "app/desktop/well_session.h"

#include <algorithm>
#include <chrono>
#include <fstream>

#include <gtest/gtest.h>
#include <QSignalSpy>

#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoSwitch.h>

#include "app/desktop/desk_model.h"
#include "desktop_test_support.h"
#include "reconstruction/mesh/lod_levels.h"
#include "scenegraph/well_scene.h"

using namespace caliper3d;

namespace {

class WellSessionTest : public ::testing::Test {
protected:
    void SetUp() override {
        if (!test::ensureGuiApplication()) GTEST_SKIP() << "no display (run under xvfb-run)";
    }
    static app::LoadOptions eightAndAHalfInch() {
        app::LoadOptions options;
        options.read.bitSize_mm = 215.9;
        return options;
    }
    static QString path(const std::filesystem::path& p) {
        return QString::fromStdString(p.string());
    }
};

TEST_F(WellSessionTest, OpensAWellIntoTheModelAndTheScene) {
    const auto log = test::syntheticLog("example", 60.0, 0.1);
    app::DeskModel model;
    app::WellSession session(model, nullptr);
    QSignalSpy loaded(&session, &app::WellSession::allWellsLoaded);
    QSignalSpy analysed(&session, &app::WellSession::wellAnalysed);
    const int id = session.openWell(path(log), eightAndAHalfInch());
    ASSERT_EQ(model.wellCount(), 1);
    EXPECT_EQ(model.well(0).id, id);
    EXPECT_EQ(model.well(0).source.path, log.string());
    EXPECT_TRUE(session.loading());
    ASSERT_TRUE(test::waitUntil([&] { return analysed.count() == 1; }, 120000))
        << "the well did not load and analyse";
    EXPECT_EQ(loaded.count(), 1);
    EXPECT_FALSE(session.loading());
    EXPECT_FALSE(session.progress().busy);
    const app::DeskWell& well = model.well(0);
    ASSERT_NE(well.geometry, nullptr);
    ASSERT_NE(well.analysis, nullptr);
    EXPECT_EQ(well.geometry->table().rowCount(), 601u);  // 0-60 m every 0.1 m
    ASSERT_TRUE(well.options.read.bitSize_mm.has_value());
    EXPECT_DOUBLE_EQ(*well.options.read.bitSize_mm, 215.9);
    EXPECT_EQ(session.geometry(0), well.geometry);
    // One switch under the scene's root, showing the well's scene and annotations.
    ASSERT_EQ(session.sceneRoot()->getNumChildren(), 1);
    auto* shown = dynamic_cast<SoSwitch*>(session.sceneRoot()->getChild(0));
    ASSERT_NE(shown, nullptr);
    EXPECT_EQ(shown->getNumChildren(), 2);
    ASSERT_NE(session.legend(), nullptr);
    EXPECT_EQ(session.legend()->title, "radius - bit radius");
    // The model's current well is the one loaded, at its first row.
    EXPECT_EQ(model.currentWell(), 0);
    EXPECT_DOUBLE_EQ(model.currentDepth_m(), well.geometry->table().depth_m.front());
}

TEST_F(WellSessionTest, LoadingEndsOnlyOnceTheWholeSetIsStyled) {
    // The last load's end is taken from the event loop (wellDone: the colours and exaggeration
    // the set decides, then allWellsLoaded). Until then the session is still loading: a caller
    // that waits for loading() to end, and then draws, must find the set's own style.
    const auto log = test::syntheticLog("example", 60.0, 0.1);
    app::DeskModel model;
    app::WellSession session(model, nullptr);
    QSignalSpy loaded(&session, &app::WellSession::allWellsLoaded);
    session.openWell(path(log), eightAndAHalfInch());
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(2);
    // One pass of the event loop at a time, to see every state the session goes through.
    while (session.loading() && std::chrono::steady_clock::now() < deadline) {
        EXPECT_EQ(loaded.count(), 0) << "allWellsLoaded while still loading";
        QCoreApplication::processEvents(QEventLoop::AllEvents, 1);
    }
    ASSERT_FALSE(session.loading()) << "the well did not load";
    EXPECT_EQ(loaded.count(), 1) << "loading ended before the set was styled";
    ASSERT_NE(model.well(0).geometry, nullptr);
    EXPECT_DOUBLE_EQ(model.well(0).geometry->options().radialExaggeration,
                     session.look().radialExaggeration);
}

TEST_F(WellSessionTest, RestylesAndHidesAWellThroughTheModel) {
    const auto log = test::syntheticLog("example", 60.0, 0.1);
    app::DeskModel model;
    app::WellSession session(model, nullptr);
    session.openWell(path(log), eightAndAHalfInch());
    ASSERT_TRUE(
        test::waitUntil([&] { return model.wellCount() == 1 && model.well(0).analysis; }, 120000));
    const auto before = model.well(0).geometry;
    QSignalSpy look(&session, &app::WellSession::lookChanged);
    reconstruction::ColourRequest byClass;
    byClass.quantity = "class";
    ASSERT_TRUE(session.restyle(20.0, byClass));
    EXPECT_GE(look.count(), 1);
    const app::DeskWell& well = model.well(0);
    EXPECT_NE(well.geometry, before);  // a new geometry, the same rows: nothing read again
    EXPECT_EQ(well.geometry->table().rowCount(), before->table().rowCount());
    EXPECT_DOUBLE_EQ(well.options.radialExaggeration, 20.0);
    EXPECT_EQ(well.options.colour.quantity, "class");
    EXPECT_DOUBLE_EQ(session.look().radialExaggeration, 20.0);
    ASSERT_NE(session.legend(), nullptr);
    EXPECT_EQ(session.legend()->title, "class");

    auto* shown = dynamic_cast<SoSwitch*>(session.sceneRoot()->getChild(0));
    ASSERT_NE(shown, nullptr);
    session.setWellVisible(0, false);
    EXPECT_FALSE(model.well(0).visible);
    EXPECT_EQ(shown->whichChild.getValue(), SO_SWITCH_NONE);
    session.setWellVisible(0, true);
    EXPECT_TRUE(model.well(0).visible);
    EXPECT_EQ(shown->whichChild.getValue(), SO_SWITCH_ALL);

    // An unknown curve leaves the well as it was, and says why.
    QSignalSpy status(&session, &app::WellSession::status);
    reconstruction::ColourRequest bogus;
    bogus.quantity = "porosity";
    EXPECT_FALSE(session.restyle(1.0, bogus));
    EXPECT_EQ(model.well(0).geometry, well.geometry);
    ASSERT_GE(status.count(), 1);
    EXPECT_NE(status.last().at(0).toString().indexOf("cannot colour by 'porosity'"), -1);
}

// The tick marks under a well's switch (its scene and annotations).
int tickMarks(SoNode* wellRoot) {
    SoSearchAction search;
    search.setName("tick_marks");
    search.setInterest(SoSearchAction::ALL);
    search.setSearchingAll(TRUE);
    search.apply(wellRoot);
    return search.getPaths().getLength();
}

// With two wells, only the current one carries depth ticks (both wells' labels would pile up
// otherwise); the ticks follow the current well; one well alone keeps its own.
TEST_F(WellSessionTest, OnlyTheCurrentWellOfSeveralCarriesDepthTicks) {
    app::DeskModel model;
    app::WellSession session(model, nullptr);
    session.openWell(path(test::syntheticLog("example", 60.0, 0.1)), eightAndAHalfInch());
    ASSERT_TRUE(
        test::waitUntil([&] { return model.wellCount() == 1 && model.well(0).analysis; }, 120000));
    ASSERT_EQ(session.sceneRoot()->getNumChildren(), 1);
    EXPECT_EQ(tickMarks(session.sceneRoot()->getChild(0)), 1);

    session.addWell(path(test::syntheticLog("circle", 40.0, 0.1)), eightAndAHalfInch());
    ASSERT_TRUE(
        test::waitUntil([&] { return model.wellCount() == 2 && model.well(1).analysis; }, 120000));
    ASSERT_EQ(session.sceneRoot()->getNumChildren(), 2);
    ASSERT_EQ(model.currentWell(), 0);
    EXPECT_EQ(tickMarks(session.sceneRoot()->getChild(0)), 1);
    EXPECT_EQ(tickMarks(session.sceneRoot()->getChild(1)), 0);

    model.setCurrent(1, 10.0);
    EXPECT_EQ(tickMarks(session.sceneRoot()->getChild(0)), 0);
    EXPECT_EQ(tickMarks(session.sceneRoot()->getChild(1)), 1);
}

TEST_F(WellSessionTest, CancelRemovesOnlyTheWellsStillLoading) {
    const auto small = test::syntheticLog("example", 60.0, 0.1);
    const auto large = test::syntheticLog("example", 4000.0, 0.01);
    app::DeskModel model;
    app::WellSession session(model, nullptr);
    const int first = session.openWell(path(small), eightAndAHalfInch());
    ASSERT_TRUE(test::waitUntil([&] { return !session.loading(); }, 120000));
    QSignalSpy cancelled(&session, &app::WellSession::loadCancelled);
    const int second = session.addWell(path(large), eightAndAHalfInch());
    EXPECT_NE(first, second);
    ASSERT_EQ(model.wellCount(), 2);
    ASSERT_EQ(session.sceneRoot()->getNumChildren(), 2);
    ASSERT_TRUE(test::waitUntil([&] { return session.progress().fraction > 0.0; }, 20000));
    EXPECT_TRUE(session.progress().busy);
    EXPECT_TRUE(session.progress().text.startsWith("Reading "))
        << session.progress().text.toStdString();
    // A streamed load draws what it has read while it reads on, and says so.
    EXPECT_TRUE(test::waitUntil(
        [&] { return session.progress().text.startsWith("Reading and drawing desktop_example_"); },
        20000))
        << session.progress().text.toStdString();
    session.cancelLoading();
    EXPECT_EQ(cancelled.count(), 1);
    EXPECT_FALSE(session.loading());
    EXPECT_FALSE(session.progress().busy);
    // The loaded well stays, under its id, in the model and in the scene.
    ASSERT_EQ(model.wellCount(), 1);
    EXPECT_EQ(model.well(0).id, first);
    EXPECT_EQ(model.indexOf(second), -1);
    EXPECT_EQ(session.sceneRoot()->getNumChildren(), 1);
    EXPECT_EQ(session.wellSources().size(), 1u);
    EXPECT_TRUE(test::waitUntil([&] { return session.retiredLoadsRunning() == 0; }, 5000));
}

TEST_F(WellSessionTest, AFieldLoadsAFewWellsAtATimeAndCancelStopsThoseWaiting) {
    const int atOnce = app::WellSession::loadsAtOnce();
    ASSERT_GE(atOnce, 2);
    const int wells = atOnce + 3;
    app::DeskModel model;
    app::WellSession session(model, nullptr);
    for (int i = 0; i < wells; ++i) {
        const auto log = test::syntheticLog(i % 2 ? "circle" : "example", 30.0 + i, 0.1);
        if (i == 0)
            session.openWell(path(log), eightAndAHalfInch());
        else
            session.addWell(path(log), eightAndAHalfInch());
    }
    // Every well is in the model at once; only the first `atOnce` load, the others wait.
    ASSERT_EQ(model.wellCount(), wells);
    EXPECT_EQ(session.loadsRunning(), atOnce);
    for (int i = atOnce; i < wells; ++i) EXPECT_EQ(model.well(i).geometry, nullptr) << i;
    int most = 0;
    ASSERT_TRUE(test::waitUntil(
        [&] {
            most = std::max(most, session.loadsRunning());
            for (int i = 0; i < model.wellCount(); ++i)
                if (!model.well(i).analysis) return false;
            return !session.loading();
        },
        120000))
        << "the field did not load";
    EXPECT_LE(most, atOnce);
    EXPECT_EQ(session.loadsRunning(), 0);
    for (int i = 0; i < wells; ++i) {
        ASSERT_NE(model.well(i).geometry, nullptr) << i;
        EXPECT_EQ(model.well(i).geometry->table().rowCount(),
                  static_cast<std::size_t>(10 * (30 + i) + 1))
            << i;
        // The first well holds the finer coarse level up front, the field's others only the
        // coarsest (no camera here asks for more).
        const scenegraph::WellScene* scene = session.scene(std::size_t(i));
        ASSERT_NE(scene, nullptr);
        ASSERT_GT(scene->segmentCount(), 0u);
        for (std::size_t s = 0; s < scene->segmentCount(); ++s)
            ASSERT_EQ(scene->heldFrom(s), i == 0 ? reconstruction::kFirstCoarseLevel
                                                 : reconstruction::kFieldFirstCoarseLevel)
                << i;
    }

    // Cancelling while some load and others wait removes them all, the loaded ones stay.
    QSignalSpy cancelled(&session, &app::WellSession::loadCancelled);
    for (int i = 0; i < wells; ++i)
        session.addWell(path(test::syntheticLog("example", 1500.0, 0.01)), eightAndAHalfInch());
    ASSERT_EQ(model.wellCount(), 2 * wells);
    EXPECT_EQ(session.loadsRunning(), atOnce);
    session.cancelLoading();
    EXPECT_EQ(cancelled.count(), 1);
    EXPECT_FALSE(session.loading());
    EXPECT_EQ(session.loadsRunning(), 0);
    EXPECT_EQ(model.wellCount(), wells);
    EXPECT_EQ(session.sceneRoot()->getNumChildren(), wells);
    EXPECT_TRUE(test::waitUntil([&] { return session.retiredLoadsRunning() == 0; }, 20000));
}

TEST_F(WellSessionTest, AFailedWellSaysWhichFileAndLine) {
    const auto bad = test::scratch("session_bad.txt");
    { std::ofstream(bad) << "1 2 3 4 5 6 7 8 9 10\n2 2 3\n3 2 3 4 5 6 7 8 9 10\n"; }
    app::DeskModel model;
    app::WellSession session(model, nullptr);
    QSignalSpy failed(&session, &app::WellSession::wellFailed);
    session.openWell(path(bad), {});
    ASSERT_TRUE(test::waitUntil([&] { return failed.count() == 1; }, 30000));
    EXPECT_EQ(failed.first().at(0).toString(), "session_bad.txt");
    EXPECT_TRUE(failed.first().at(1).toString().contains(path(bad) + ":2"))
        << failed.first().at(1).toString().toStdString();
    ASSERT_EQ(model.wellCount(), 1);
    EXPECT_FALSE(model.well(0).error.isEmpty());
    EXPECT_FALSE(session.loading());
}

}  // namespace

TEST_F(WellSessionTest, AWellsImageLogPicksAreReadAndDrawnOnTheWall) {
    const auto log = test::syntheticLog("example", 100.0, 0.1);
    const auto picks = test::scratch("session_picks.csv");
    std::ofstream(picks) << "md,azimuth,type\n70,317,BREAKOUT\n75,140,breakout\nx,1,bad row\n";
    app::DeskModel model;
    app::WellSession session(model, nullptr);
    session.openWell(app::WellSource{log.string(), {}, {}, picks.string()}, eightAndAHalfInch());
    ASSERT_TRUE(
        test::waitUntil([&] { return model.wellCount() == 1 && model.well(0).analysis; }, 120000));
    const app::DeskWell& well = model.well(0);
    ASSERT_EQ(well.picks.size(), 2u);
    EXPECT_EQ(well.picks[0].azimuth_deg, 317.0);
    // The row that is not a pick is a counted warning of the well, with its line.
    bool warned = false;
    for (const io::Warning& w : well.diagnostics.warnings)
        warned = warned || (w.file == picks.string() && w.line == 4);
    EXPECT_TRUE(warned);
    // The markers hang under the well's annotations.
    EXPECT_NE(SoNode::getByName("image_log_picks"), nullptr);
}
