// The window holding a field lean (WellSession::setFieldRowBudget): a field whose wells hold
// more rows than the budget keeps every well but the current one by a sample of its rows, and
// draws, picks up and restyles it as the field held whole does.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <QObject>
#include <QSignalSpy>
#include <QTimer>
#include <QTreeWidget>

#include <Inventor/SbViewportRegion.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include "app/desktop/desk_model.h"
#include "app/desktop/well_session.h"
#include "app/desktop/wells_dock.h"
#include "desktop_test_support.h"
#include "io/column_text_writer.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "reconstruction/well_geometry.h"
#include "scenegraph/camera_setup.h"
#include "scenegraph/node_ref.h"
#include "scenegraph/picture/picture.h"
#include "scenegraph/well_scene.h"

using namespace caliper3d;

namespace {

class LeanFieldTest : public ::testing::Test {
protected:
    void SetUp() override {
        if (!test::ensureGuiApplication()) GTEST_SKIP() << "no display (run under xvfb-run)";
    }

    // Three wells 30 m apart of one 300 m log at 1 cm: 30,001 rows each.
    static std::vector<app::WellSource> field(
        const std::filesystem::path& log = test::syntheticLog("example", 300.0, 0.01)) {
        std::vector<app::WellSource> wells;
        for (const double east : {0.0, 30.0, 60.0})
            wells.push_back({log.string(), {}, reconstruction::Wellhead{east, 0.0, 0.0}, {}});
        return wells;
    }

    // Opens the field and waits until every well is loaded, analysed or held lean, and settled.
    static bool open(app::WellSession& session, const app::LoadOptions& options,
                     const std::vector<app::WellSource>& wells = field()) {
        session.openWell(wells[0], options);
        for (std::size_t w = 1; w < wells.size(); ++w) session.addWell(wells[w], options);
        return settle(session);
    }
    // The same field opened held whole (`whole`, no budget) and with a budget its second well
    // passes (`lean`).
    static void openBoth(app::WellSession& whole, app::WellSession& lean) {
        whole.setFieldRowBudget(0);
        lean.setFieldRowBudget(40'000);
        ASSERT_TRUE(open(whole, app::LoadOptions{})) << "the field held whole did not settle";
        ASSERT_TRUE(open(lean, app::LoadOptions{})) << "the field held lean did not settle";
    }

    // The field's first well alone, with the budget the second well passes.
    static void openFirstWell(app::WellSession& session) {
        session.setFieldRowBudget(40'000);
        ASSERT_TRUE(open(session, app::LoadOptions{}, {field().front()}));
    }

    // The first well held lean (-1: none).
    static int firstLean(const app::WellSession& session) {
        for (int i = 0; i < session.model().wellCount(); ++i)
            if (session.heldLean(i)) return i;
        return -1;
    }
    static bool settle(app::WellSession& session) {
        return test::waitUntil(
            [&] {
                if (session.loading() || session.leanJobsRunning() > 0) return false;
                const app::DeskModel& model = session.model();
                for (int i = 0; i < model.wellCount(); ++i)
                    if (!model.well(i).geometry ||
                        (!model.well(i).analysis && !session.heldLean(i)))
                        return false;
                return true;
            },
            300000);
    }

    // The visible wells' picture, `view` 0 iso, 1 from above, 2 down well `down` at 150 m.
    static scenegraph::Picture picture(const app::WellSession& session, int view, int down) {
        scenegraph::PictureRequest request;
        request.width = 640;
        request.height = 480;
        request.view = view == 1 ? scenegraph::ViewDirection::Map : scenegraph::ViewDirection::Iso;
        if (view == 2) {
            request.pose = scenegraph::downHolePose(*session.model().well(down).geometry, 150.0);
            request.tickMarks = false;
        }
        request.unloggedPath = view < 2;
        request.radialExaggeration = session.look().radialExaggeration;
        request.legend = session.legend();
        return scenegraph::drawPicture(session.pictureWells(), request);
    }

    // The same pictures: the field from two sides, and down well `down` (held lean: its finer
    // levels built from its log read again).
    static void expectSamePictures(const app::WellSession& whole, const app::WellSession& lean,
                                   int down) {
        for (int view = 0; view < 3; ++view) {
            scenegraph::Picture a, b;
            try {
                a = picture(whole, view, down);
                b = picture(lean, view, down);
            } catch (const std::runtime_error& e) {
                GTEST_SKIP() << e.what();  // no OpenGL
            }
            // Down the hole, finer levels built for the picture (a well held lean may hold
            // fewer levels up front: it refines more segments to draw the same).
            if (view == 2) {
                EXPECT_GT(a.refinedSegments, 0u);
                EXPECT_GE(b.refinedSegments, a.refinedSegments);
            }
            ASSERT_EQ(a.image.rgba.size(), b.image.rgba.size());
            EXPECT_TRUE(a.image.rgba == b.image.rgba) << "view " << view;
        }
    }
};

TEST_F(LeanFieldTest, AFieldPastTheBudgetKeepsTheCurrentWellWholeAndDrawsWhatItDrawsWhole) {
    app::DeskModel wholeModel, leanModel;
    app::WellSession whole(wholeModel, nullptr), lean(leanModel, nullptr);
    ASSERT_NO_FATAL_FAILURE(openBoth(whole, lean));

    ASSERT_EQ(leanModel.wellCount(), 3);
    // The first well placed is the current one (the loads run side by side).
    const int current = leanModel.currentWell();
    ASSERT_GE(current, 0);
    EXPECT_DOUBLE_EQ(lean.look().radialExaggeration, whole.look().radialExaggeration);
    for (int i = 0; i < 3; ++i) {
        SCOPED_TRACE("well " + std::to_string(i));
        const app::DeskWell& held = leanModel.well(i);
        const app::DeskWell& all = wholeModel.well(i);
        EXPECT_FALSE(whole.heldLean(i));
        ASSERT_EQ(all.geometry->table().rowCount(), 30001u);
        EXPECT_EQ(held.geometry->options().radialExaggeration,
                  all.geometry->options().radialExaggeration);
        if (i == current) {  // whole, analysed
            EXPECT_FALSE(lean.heldLean(i));
            EXPECT_EQ(held.geometry->table().rowCount(), 30001u);
            EXPECT_NE(held.analysis, nullptr);
            continue;
        }
        // A sample of its rows (every rows/4096-th, the ones its meshes draw), no analysis.
        EXPECT_TRUE(lean.heldLean(i));
        EXPECT_EQ(held.analysis, nullptr);
        const std::vector<double>& kept = held.geometry->table().depth_m;
        const std::vector<double>& every = all.geometry->table().depth_m;
        EXPECT_GE(kept.size(), 4096u);
        EXPECT_LT(kept.size(), every.size() / 2);
        for (const double md : kept)
            ASSERT_TRUE(std::binary_search(every.begin(), every.end(), md)) << md;
        EXPECT_EQ(kept.front(), every.front());
        EXPECT_EQ(kept.back(), every.back());
        EXPECT_EQ(lean.scene(std::size_t(i))->segmentCount(),
                  whole.scene(std::size_t(i))->segmentCount());
    }
    ASSERT_NE(lean.legend(), nullptr);
    EXPECT_EQ(lean.legend()->lo, whole.legend()->lo);
    EXPECT_EQ(lean.legend()->hi, whole.legend()->hi);
    expectSamePictures(whole, lean, firstLean(lean));
}

TEST_F(LeanFieldTest, AWellHeldLeanMadeCurrentIsReadWholeAndAnalysedAndTheOneBeforeGoesLean) {
    app::DeskModel model;
    app::WellSession session(model, nullptr);
    session.setFieldRowBudget(40'000);
    ASSERT_TRUE(open(session, app::LoadOptions{}));
    const int before = model.currentWell(), lean = firstLean(session);
    ASSERT_GE(before, 0);
    ASSERT_GE(lean, 0);
    ASSERT_FALSE(session.heldLean(before));
    model.setCurrent(lean, 150.0);
    EXPECT_EQ(model.currentWell(), lean);
    ASSERT_TRUE(test::waitUntil(
        [&] {
            return !session.heldLean(lean) && model.well(lean).analysis &&
                   session.heldLean(before) && session.leanJobsRunning() == 0;
        },
        120000))
        << "the well made current was not read whole, or the one before did not go lean";
    const app::DeskWell& current = model.well(lean);
    ASSERT_EQ(current.geometry->table().rowCount(), 30001u);
    EXPECT_EQ(current.analysis->sections.size(), 30001u);
    // Still at 150 m, a row of the whole well.
    EXPECT_NEAR(model.currentDepth_m(), 150.0, 1e-9);
    EXPECT_EQ(current.geometry->table().depth_m[model.currentRow()], model.currentDepth_m());
    EXPECT_EQ(model.well(before).analysis, nullptr);
    EXPECT_LT(model.well(before).geometry->table().rowCount(), 15000u);
}

TEST_F(LeanFieldTest, AWellLoadedPastTheBudgetIsMadeLeanWithoutBeingAnalysed) {
    // The first well alone, analysed; the two added pass the budget as each is placed, so each
    // is made lean as its load ends: an analysis of it would be dropped.
    app::DeskModel model;
    app::WellSession session(model, nullptr);
    ASSERT_NO_FATAL_FAILURE(openFirstWell(session));
    ASSERT_NE(model.well(0).analysis, nullptr);
    const std::vector<app::WellSource> wells = field();
    QSignalSpy analysed(&session, &app::WellSession::wellAnalysed);
    session.addWell(wells[1], app::LoadOptions{});
    session.addWell(wells[2], app::LoadOptions{});
    ASSERT_TRUE(settle(session));
    EXPECT_EQ(model.currentWell(), 0);
    EXPECT_FALSE(session.heldLean(0));
    for (int w = 1; w < 3; ++w) {
        EXPECT_TRUE(session.heldLean(w)) << "well " << w;
        EXPECT_EQ(model.well(w).wholeRows, 30001u) << "well " << w;
    }
    EXPECT_EQ(analysed.count(), 0) << "a well made lean was analysed first";
}

TEST_F(LeanFieldTest, AWellHeldLeanShowsTheSmallestBitSizeOfItsWholeLog) {
    // One section of the log on a smaller bit (as where a bit was changed for a few
    // centimetres): the Wells dock says it for every well, held lean or not, though the
    // sample a well is held by does not hold that row.
    io::SectionTable table =
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile("example", 300.0, 0.01));
    ASSERT_EQ(table.bitSize_mm.size(), table.rowCount());
    const double usual = table.bitSize_mm.front();
    table.bitSize_mm[1] = 150.0;
    const auto log = test::scratch("lean_field_bit_step.txt");
    io::writeColumnTextFile(log.string(), table);

    app::DeskModel model;
    app::WellSession session(model, nullptr);
    app::WellsDock dock(model);
    session.setFieldRowBudget(40'000);
    ASSERT_TRUE(open(session, app::LoadOptions{}, field(log)));
    ASSERT_TRUE(session.heldLean(1));
    // What the well is held by no longer has the row on the smaller bit.
    EXPECT_DOUBLE_EQ(app::smallestBitSize_mm(model.well(1).geometry->table()), usual);
    for (int w = 0; w < 3; ++w)
        EXPECT_TRUE(dock.tree()
                        ->topLevelItem(w)
                        ->text(app::WellsDock::BitSize)
                        .startsWith("150.0 mm (5.906 in)"))
            << "well " << w << ": "
            << dock.tree()->topLevelItem(w)->text(app::WellsDock::BitSize).toStdString();
}

TEST_F(LeanFieldTest, AWellMadeCurrentWhileItIsMadeLeanStaysWholeAndIsAnalysed) {
    // Well 1 is made current as its load ends, while its lean form is made on a worker: the
    // form is not taken, the well is analysed, and the well current before goes lean.
    app::DeskModel model;
    app::WellSession session(model, nullptr);
    ASSERT_NO_FATAL_FAILURE(openFirstWell(session));
    const std::vector<app::WellSource> wells = field();
    bool moved = false;
    QObject::connect(&session, &app::WellSession::wellLoaded, [&] {
        if (moved || model.wellCount() < 2 || model.well(1).loadFraction < 1.0) return;
        moved = true;
        model.setCurrent(1, 150.0);
    });
    session.addWell(wells[1], app::LoadOptions{});
    session.addWell(wells[2], app::LoadOptions{});
    ASSERT_TRUE(settle(session));
    ASSERT_TRUE(moved);
    EXPECT_EQ(model.currentWell(), 1);
    EXPECT_FALSE(session.heldLean(1));
    ASSERT_NE(model.well(1).analysis, nullptr) << "the well made current was not analysed";
    EXPECT_EQ(model.well(1).analysis->sections.size(), 30001u);
    EXPECT_TRUE(session.heldLean(0));
    EXPECT_TRUE(session.heldLean(2));
}

TEST_F(LeanFieldTest, AWellLoadedPastTheBudgetIsDrawnOnceFromItsPlanAsTheFieldHeldWhole) {
    // A budget below one well: the two wells loaded first pass it, so the third is loaded as
    // its geometry only. Its load ends with no nodes but its path; it is drawn once, from its
    // plan as it is made lean, and only then has the field's load ended.
    app::DeskModel wholeModel, leanModel;
    app::WellSession whole(wholeModel, nullptr), lean(leanModel, nullptr);
    app::WellsDock dock(leanModel);
    whole.setFieldRowBudget(0);
    lean.setFieldRowBudget(20'000);
    std::vector<int> endedUndrawn;
    QString stateAsItEnded;
    QObject::connect(&lean, &app::WellSession::wellLoaded, [&] {
        for (int i = 0; i < leanModel.wellCount(); ++i)
            if (leanModel.well(i).loadFraction >= 1.0 && !lean.heldLean(i) &&
                lean.scene(std::size_t(i))->segmentCount() == 0 &&
                std::find(endedUndrawn.begin(), endedUndrawn.end(), i) == endedUndrawn.end()) {
                endedUndrawn.push_back(i);
                stateAsItEnded = dock.tree()->topLevelItem(i)->text(app::WellsDock::State);
            }
    });
    std::vector<std::size_t> segmentsAtTheEnd;
    QObject::connect(&lean, &app::WellSession::allWellsLoaded, [&] {
        for (int i = 0; i < leanModel.wellCount(); ++i)
            segmentsAtTheEnd.push_back(lean.scene(std::size_t(i))->segmentCount());
    });
    ASSERT_TRUE(open(whole, app::LoadOptions{}));
    ASSERT_TRUE(open(lean, app::LoadOptions{}));
    EXPECT_EQ(endedUndrawn, std::vector<int>{2}) << "the third well was drawn by its load";
    // The wells dock says what is being done to it, then what it holds.
    EXPECT_EQ(stateAsItEnded, "making lean");
    EXPECT_EQ(dock.tree()->topLevelItem(2)->text(app::WellsDock::State), "held lean");
    ASSERT_EQ(segmentsAtTheEnd.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i)
        EXPECT_EQ(segmentsAtTheEnd[i], whole.scene(i)->segmentCount()) << "well " << i;
    EXPECT_TRUE(lean.heldLean(2));
    EXPECT_EQ(leanModel.well(2).wholeRows, 30001u);
    EXPECT_GT(lean.scene(2)->fullDetailTriangles(), 0u);
    EXPECT_DOUBLE_EQ(lean.look().radialExaggeration, whole.look().radialExaggeration);
    expectSamePictures(whole, lean, 2);
}

TEST_F(LeanFieldTest, AWellStartedWhileTheFieldIsBoundToPassTheBudgetIsLoadedAsItsGeometryOnly) {
    // Four wells of 30,001 rows and a budget of 65,000: as the third starts, the wells placed
    // hold at most 60,002 rows, under the budget, but the files still to be read are bound to
    // take the field past it. The third is loaded as its geometry only, as the fourth is, and
    // not streamed to be made lean afterwards.
    std::vector<app::WellSource> wells = field();
    wells.push_back({wells[0].path, {}, reconstruction::Wellhead{90.0, 0.0, 0.0}, {}});
    app::DeskModel model;
    app::WellSession session(model, nullptr);
    session.setFieldRowBudget(65'000);
    std::vector<int> endedUndrawn;
    QObject::connect(&session, &app::WellSession::wellLoaded, [&] {
        for (int i = 0; i < model.wellCount(); ++i)
            if (model.well(i).loadFraction >= 1.0 && !session.heldLean(i) &&
                session.scene(std::size_t(i))->segmentCount() == 0 &&
                std::find(endedUndrawn.begin(), endedUndrawn.end(), i) == endedUndrawn.end())
                endedUndrawn.push_back(i);
    });
    ASSERT_TRUE(open(session, app::LoadOptions{}, wells));
    std::sort(endedUndrawn.begin(), endedUndrawn.end());
    EXPECT_EQ(endedUndrawn, (std::vector<int>{2, 3})) << "a well was streamed to be made lean";
    EXPECT_EQ(model.currentWell(), 0);
    for (int w = 1; w < 4; ++w) {
        EXPECT_TRUE(session.heldLean(w)) << "well " << w;
        EXPECT_GT(session.scene(std::size_t(w))->segmentCount(), 0u) << "well " << w;
    }
}

TEST_F(LeanFieldTest, AWellDrawnFromItsPlanAsTheFieldLoadsTakesItsExaggerationAndIsKept) {
    // Six wells 30 m apart past a budget of 65,000 rows: the wells loaded as their geometry
    // only are drawn from their plans at the exaggeration the wells placed so far would get,
    // not to scale, and the caption says both while the current well is still drawn as it
    // loaded. The field's end restyles to the exaggeration chosen over every well; a well
    // drawn at it already keeps its scene, the others are drawn again.
    std::vector<app::WellSource> wells = field();
    for (const double east : {90.0, 120.0, 150.0})
        wells.push_back({wells[0].path, {}, reconstruction::Wellhead{east, 0.0, 0.0}, {}});
    app::DeskModel model;
    app::WellSession session(model, nullptr);
    session.setFieldRowBudget(65'000);
    struct Drawn {
        double exaggeration = 0.0;
        const scenegraph::WellScene* scene = nullptr;
    };
    std::vector<std::optional<Drawn>> drawn(wells.size());
    std::vector<std::vector<double>> captions;            // drawnExaggerations while loading
    std::vector<bool> endedUndrawn(wells.size(), false);  // loaded as their geometry only
    QObject::connect(&session, &app::WellSession::wellLoaded, [&] {
        for (int i = 0; i < model.wellCount(); ++i)
            if (model.well(i).loadFraction >= 1.0 && !session.heldLean(i) &&
                session.scene(std::size_t(i))->segmentCount() == 0)
                endedUndrawn[std::size_t(i)] = true;
    });
    QObject::connect(&model, &app::DeskModel::wellChanged, &session, [&](int i) {
        // After the call that drew it (holdLean edits the record, then draws).
        QTimer::singleShot(0, &session, [&, i] {
            if (!session.loading() || drawn[std::size_t(i)] || !endedUndrawn[std::size_t(i)] ||
                !session.heldLean(i) || session.scene(std::size_t(i))->segmentCount() == 0)
                return;
            drawn[std::size_t(i)] = Drawn{model.well(i).geometry->options().radialExaggeration,
                                          session.scene(std::size_t(i))};
            captions.push_back(session.drawnExaggerations());
        });
    });
    ASSERT_TRUE(open(session, app::LoadOptions{}, wells));
    const double chosen = session.look().radialExaggeration;
    ASSERT_GT(chosen, 1.0);
    EXPECT_EQ(session.drawnExaggerations(), std::vector<double>{chosen});
    int kept = 0;
    for (std::size_t w = 0; w < wells.size(); ++w) {
        EXPECT_DOUBLE_EQ(model.well(int(w)).geometry->options().radialExaggeration, chosen) << w;
        if (!drawn[w]) continue;
        EXPECT_GT(drawn[w]->exaggeration, 1.0) << "well " << w << " drawn to scale as it loaded";
        if (drawn[w]->exaggeration == chosen) {
            EXPECT_EQ(session.scene(w), drawn[w]->scene) << "well " << w << " drawn again";
            ++kept;
        } else {
            EXPECT_NE(session.scene(w), drawn[w]->scene) << "well " << w << " not drawn again";
        }
    }
    EXPECT_GT(kept, 0) << "no well drawn from its plan kept its scene";
    ASSERT_FALSE(captions.empty());
    // The current well is drawn to scale until the end, beside the wells drawn from plans.
    EXPECT_EQ(captions.back().front(), 1.0);
    EXPECT_GT(captions.back().back(), 1.0);
}

TEST_F(LeanFieldTest, ARunAddedToAFieldPastTheBudgetIsStreamedAndHeldWhole) {
    // Two wells load; a run of the first waits its turn and starts with the field past the
    // budget. The runs of one well stay whole, so it is streamed as ever, drawn by its load.
    app::DeskModel model;
    app::WellSession session(model, nullptr);
    session.setFieldRowBudget(20'000);
    const std::vector<app::WellSource> wells = field();
    const int first = session.openWell(wells[0], app::LoadOptions{});
    session.addWell(wells[1], app::LoadOptions{});
    const int run = session.addRun(wells[2], app::LoadOptions{}, first);
    // Each load's end says what it drew; one that drew nothing (its geometry only) counts no
    // triangles.
    QStringList ends;
    QObject::connect(&session, &app::WellSession::status, [&](const QString& text) {
        if (text.contains(" segments, ")) ends << text;
    });
    ASSERT_TRUE(settle(session));
    const int index = model.indexOf(run);
    ASSERT_GE(index, 0);
    EXPECT_GE(model.well(index).runOf, 0);
    ASSERT_GE(ends.size(), 3) << ends.join("; ").toStdString();  // the last said again at the end
    for (const QString& end : ends)
        EXPECT_TRUE(end.contains("triangles at full detail")) << end.toStdString();
    EXPECT_FALSE(session.heldLean(index));
    ASSERT_NE(model.well(index).analysis, nullptr);
    EXPECT_EQ(model.well(index).analysis->sections.size(), 30001u);
}

TEST_F(LeanFieldTest, AWellLoadedPastTheBudgetAndMadeCurrentAsItEndsIsDrawnWholeAndAnalysed) {
    // Well 1 passes the budget as it starts, so it is loaded as its geometry only; made current
    // as its load ends, it is not made lean: it is drawn whole, as the field held whole draws
    // it, and analysed; the well current before goes lean.
    app::DeskModel wholeModel, model;
    app::WellSession whole(wholeModel, nullptr), session(model, nullptr);
    whole.setFieldRowBudget(0);
    const std::vector<app::WellSource> wells = field();
    ASSERT_TRUE(open(whole, app::LoadOptions{}, {wells[0], wells[1]}));
    session.setFieldRowBudget(20'000);
    ASSERT_TRUE(open(session, app::LoadOptions{}, {wells[0]}));
    bool moved = false;
    std::size_t segmentsAsItEnded = 1;
    QObject::connect(&session, &app::WellSession::wellLoaded, [&] {
        if (moved || model.wellCount() < 2 || model.well(1).loadFraction < 1.0) return;
        moved = true;
        segmentsAsItEnded = session.scene(1)->segmentCount();
        model.setCurrent(1, 150.0);
    });
    session.addWell(wells[1], app::LoadOptions{});
    ASSERT_TRUE(settle(session));
    ASSERT_TRUE(moved);
    EXPECT_EQ(segmentsAsItEnded, 0u) << "its load drew it";
    EXPECT_EQ(model.currentWell(), 1);
    EXPECT_FALSE(session.heldLean(1));
    ASSERT_NE(model.well(1).analysis, nullptr) << "the well made current was not analysed";
    EXPECT_EQ(model.well(1).analysis->sections.size(), 30001u);
    EXPECT_EQ(session.scene(1)->segmentCount(), whole.scene(1)->segmentCount());
    EXPECT_EQ(session.scene(1)->fullDetailTriangles(), whole.scene(1)->fullDetailTriangles());
    EXPECT_TRUE(session.heldLean(0));
}

TEST_F(LeanFieldTest, AWellHeldLeanMakesItsSegmentsWhereTheCameraComesNearAndRefinesThem) {
    // A well held lean is drawn by its spans, its segments' nodes made when the window's camera
    // first comes near (scenegraph::SegmentNodes::whenNear): none from far away; beside it at
    // 150 m they are made and those near refined from the log read whole again.
    app::DeskModel model;
    std::optional<scenegraph::DetailView> camera;
    app::WellSession session(model, [&] { return camera; });
    session.setFieldRowBudget(40'000);
    ASSERT_TRUE(open(session, app::LoadOptions{}));
    const int target = firstLean(session);
    ASSERT_GE(target, 0);
    const scenegraph::WellScene& scene = *session.scene(std::size_t(target));
    const std::size_t segments = scene.segmentCount();
    ASSERT_GT(segments, 16u);
    EXPECT_EQ(scene.segmentNodes(), 0u);
    // The detail loader looks every few tens of milliseconds: a second is many looks.
    camera = scenegraph::DetailView{{0.0f, 0.0f, 5000.0f}, scenegraph::lodViewFor(800, 0.8f)};
    EXPECT_FALSE(test::waitUntil([&] { return scene.segmentNodes() > 0; }, 1000))
        << "segments made for a camera 5 km away";
    const auto line = reconstruction::pathLine(*model.well(target).geometry, 1.0);
    ASSERT_GT(line.size(), 150u);
    camera->eye = line[150] + glm::vec3(0.0f, 0.0f, 3.0f);
    ASSERT_TRUE(test::waitUntil(
        [&] { return session.scene(std::size_t(target))->fineTriangles() > 0; }, 120000))
        << "no finer level came for the well held lean";
    const scenegraph::WellScene& near = *session.scene(std::size_t(target));
    EXPECT_GT(near.segmentNodes(), 0u);
    EXPECT_LE(near.segmentNodes(), segments);
    EXPECT_TRUE(session.heldLean(target));
}

TEST_F(LeanFieldTest, ARestyledFieldHeldLeanIsReadAgainAndDrawsWhatItDrawsWhole) {
    // Coloured by ellipticity, drawn at x7: neither is what the wells held lean were planned
    // and coloured for, so they are read again, then drawn as the field held whole.
    app::DeskModel wholeModel, leanModel;
    app::WellSession whole(wholeModel, nullptr), lean(leanModel, nullptr);
    ASSERT_NO_FATAL_FAILURE(openBoth(whole, lean));
    reconstruction::ColourRequest colour;
    colour.quantity = "ellipticity";
    ASSERT_TRUE(whole.restyle(7.0, colour));
    ASSERT_TRUE(lean.restyle(7.0, colour));
    ASSERT_TRUE(test::waitUntil(
        [&] {
            return lean.leanJobsRunning() == 0 && lean.look().radialExaggeration == 7.0 &&
                   lean.look().colour == colour;
        },
        120000))
        << "the field held lean was not restyled";
    for (int i = 0; i < 3; ++i) EXPECT_EQ(lean.heldLean(i), i != leanModel.currentWell()) << i;
    ASSERT_NE(lean.legend(), nullptr);
    EXPECT_EQ(lean.legend()->title, whole.legend()->title);
    EXPECT_EQ(lean.legend()->lo, whole.legend()->lo);
    EXPECT_EQ(lean.legend()->hi, whole.legend()->hi);
    for (int i = 0; i < 3; ++i)
        EXPECT_EQ(leanModel.well(i).geometry->options().radialExaggeration, 7.0) << i;
    expectSamePictures(whole, lean, firstLean(lean));
}

TEST_F(LeanFieldTest, APickOnAWellHeldLeanFindsTheSectionHitOnceTheWellIsReadWhole) {
    app::DeskModel wholeModel, leanModel;
    app::WellSession whole(wholeModel, nullptr), lean(leanModel, nullptr);
    ASSERT_NO_FATAL_FAILURE(openBoth(whole, lean));
    const int target = firstLean(lean);
    ASSERT_GE(target, 0);
    // A camera 3 m south of the well's axis at about 150 m, looking at it (x east, y up).
    const auto line = reconstruction::pathLine(*wholeModel.well(target).geometry, 1.0);
    ASSERT_GT(line.size(), 150u);
    const glm::vec3 axis = line[150];
    const auto pickIn = [&](app::WellSession& session) {
        scenegraph::NodeRef<SoSeparator> root(new SoSeparator);
        auto* camera = new SoPerspectiveCamera;
        camera->nearDistance = 0.01f;
        camera->farDistance = 500.0f;
        camera->position = SbVec3f(axis.x, axis.y, axis.z + 3.0f);
        camera->pointAt(SbVec3f(axis.x, axis.y, axis.z), SbVec3f(0.0f, 1.0f, 0.0f));
        root->addChild(camera);
        root->addChild(session.sceneRoot());
        return session.pick(root.get(), SbViewportRegion(640, 480), SbVec2s(320, 240));
    };
    const std::optional<app::WellPick> exact = pickIn(whole);
    ASSERT_TRUE(exact) << "the well held whole was not hit";
    ASSERT_EQ(exact->well, target);
    const std::optional<app::WellPick> near = pickIn(lean);
    ASSERT_TRUE(near) << "the well held lean was not hit";
    EXPECT_EQ(near->well, target);
    EXPECT_NE(near->text.indexOf("held lean"), -1) << near->text.toStdString();
    // What the window does with a pick (WellNavigator::showPicked): the well becomes current,
    // is read whole, and the current section becomes the one hit.
    leanModel.setCurrentRow(near->well, near->row);
    ASSERT_TRUE(test::waitUntil(
        [&] {
            return !lean.heldLean(target) && leanModel.well(target).analysis &&
                   lean.leanJobsRunning() == 0;
        },
        120000));
    EXPECT_EQ(leanModel.currentWell(), target);
    EXPECT_EQ(leanModel.currentRow(), exact->row);
    // The well held lean makes its segments' nodes when the window's camera first comes near
    // (none here: no camera probe), so the pick hit its span's merged mesh, a coarser wall than
    // the segment the well held whole shows: the same section, the azimuth within 0.01 deg.
    EXPECT_NEAR(leanModel.currentAzimuth_deg(), exact->azimuth_deg, 0.01);
}

TEST_F(LeanFieldTest, AWellHeldLeanWhoseLogChangedIsNotReadAgainAndSaysSo) {
    // A copy of its own: the log changes under the window.
    const auto log = test::scratch("lean_field_changed.txt");
    std::filesystem::copy_file(test::syntheticLog("example", 300.0, 0.01), log,
                               std::filesystem::copy_options::overwrite_existing);
    app::DeskModel model;
    app::WellSession session(model, nullptr);
    session.setFieldRowBudget(40'000);
    ASSERT_TRUE(open(session, app::LoadOptions{}, field(log)));
    const int lean = firstLean(session);
    ASSERT_GE(lean, 0);
    QStringList said;
    QObject::connect(&session, &app::WellSession::status,
                     [&said](const QString& text) { said << text; });
    std::filesystem::last_write_time(log,
                                     std::filesystem::last_write_time(log) + std::chrono::hours(1));
    model.setCurrent(lean, 150.0);
    ASSERT_TRUE(test::waitUntil(
        [&] { return session.leanJobsRunning() == 0 && !said.filter("changed since").isEmpty(); },
        60000))
        << said.join("\n").toStdString();
    const QString message = said.filter("changed since").front();
    EXPECT_TRUE(message.startsWith(QString::fromStdString(log.string()))) << message.toStdString();
    // It stays as it was drawn: held lean, not analysed; moving along it does not read it
    // again (nor say so again).
    EXPECT_TRUE(session.heldLean(lean));
    EXPECT_EQ(model.well(lean).analysis, nullptr);
    EXPECT_EQ(model.currentWell(), lean);
    model.setCurrent(lean, 200.0);
    EXPECT_EQ(session.leanJobsRunning(), 0);
    QCoreApplication::processEvents();
    EXPECT_EQ(said.filter("changed since").size(), 1) << said.join("\n").toStdString();
}

}  // namespace
