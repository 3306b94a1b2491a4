#include "app/scene_assembly.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "io/column_text_writer.h"
#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "scenegraph/main_thread.h"
#include "scenegraph/picture/picture.h"
#include "scenegraph/picture_scale.h"
#include "test_support.h"

using namespace caliper3d;

TEST(SceneAssemblyTest, WellheadsPlaceWellsRelativeToTheFirst) {
    scenegraph::initCoin();
    const auto log = test::scratch("assembly_circle.txt");
    io::writeColumnTextFile(
        log.string(),
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile("circle", 20.0, 0.5)));
    app::WellSource first{log.string(), {}, reconstruction::Wellhead{1000.0, 2000.0, 50.0}, {}};
    app::WellSource second{log.string(), {}, reconstruction::Wellhead{1100.0, 1950.0, 40.0}, {}};
    const app::AssembledScene scene = app::assembleScene({first, second}, app::LoadOptions{});
    ASSERT_EQ(scene.wells, 2);
    ASSERT_EQ(scene.failures, 0);
    // Analysis frame (north, east, down) of the top section of each well: the
    // second is 50 m south, 100 m east and, 10 m lower, 10 m further down.
    const reconstruction::Ned a = scene.geometries[0]->centre(0);
    const reconstruction::Ned b = scene.geometries[1]->centre(0);
    EXPECT_DOUBLE_EQ(a.x, 0.0);
    EXPECT_DOUBLE_EQ(a.y, 0.0);
    EXPECT_DOUBLE_EQ(a.z, 0.0);
    EXPECT_DOUBLE_EQ(b.x, -50.0);
    EXPECT_DOUBLE_EQ(b.y, 100.0);
    EXPECT_DOUBLE_EQ(b.z, 10.0);
}

TEST(SceneAssemblyTest, AMissingSurveyFailsThatWellOnly) {
    scenegraph::initCoin();
    const auto log = test::scratch("assembly_circle2.txt");
    io::writeColumnTextFile(
        log.string(),
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile("circle", 20.0, 0.5)));
    app::WellSource good{log.string(), {}, {}, {}};
    app::WellSource bad{log.string(), test::scratch("no_such_survey.csv").string(), {}, {}};
    const app::AssembledScene scene = app::assembleScene({bad, good}, app::LoadOptions{});
    EXPECT_EQ(scene.wells, 1);
    EXPECT_EQ(scene.failures, 1);
}

TEST(SceneAssemblyTest, WellsWithDifferentLogTopsArePlacedAtTheirTrueDepths) {
    // Two vertical wells at the same elevation, one logged from 0 m and one
    // from 27.7 m: their tops are 27.7 m apart in depth, not level.
    scenegraph::initCoin();
    const auto fromSurface = test::scratch("assembly_top0.txt");
    const auto fromBelow = test::scratch("assembly_top27.txt");
    {
        std::ofstream a(fromSurface), b(fromBelow);
        for (int i = 0; i <= 40; ++i) {
            a << 0.5 * i << " 4.25 4.25 4.25 4.25 4.25 4.25 10 0 0\n";
            b << 27.7 + 0.5 * i << " 4.25 4.25 4.25 4.25 4.25 4.25 10 0 0\n";
        }
    }
    app::WellSource first{
        fromSurface.string(), {}, reconstruction::Wellhead{1000.0, 2000.0, 50.0}, {}};
    app::WellSource second{
        fromBelow.string(), {}, reconstruction::Wellhead{1030.0, 2000.0, 50.0}, {}};
    const app::AssembledScene scene = app::assembleScene({first, second}, app::LoadOptions{});
    ASSERT_EQ(scene.wells, 2);
    const reconstruction::Ned a = scene.geometries[0]->centre(0);
    const reconstruction::Ned b = scene.geometries[1]->centre(0);
    EXPECT_DOUBLE_EQ(a.z, 0.0);
    EXPECT_NEAR(b.z, 27.7, 1e-9);
    EXPECT_NEAR(b.y, 30.0, 1e-9);  // 30 m east
    // Row for row the deeper log lies 27.7 m lower.
    EXPECT_NEAR(scene.geometries[1]->centre(10).z - scene.geometries[0]->centre(10).z, 27.7, 1e-9);
}

TEST(SceneAssemblyTest, WellsReadSideBySideKeepTheirOrderAndEachFailureIsItsOwn) {
    // Several wells are read on the machine's threads at once and their meshes built ahead of
    // their nodes: the scene still lists them in the order given, each bad one fails alone,
    // and each well is what it is when assembled on its own.
    scenegraph::initCoin();
    std::vector<app::WellSource> wells;
    std::vector<double> lengths;
    for (int k = 0; k < 7; ++k) {
        const auto log = test::scratch("assembly_side_by_side_" + std::to_string(k) + ".txt");
        const double length = 12.0 + 4.0 * k;
        io::writeColumnTextFile(log.string(),
                                reconstruction::makeSyntheticWell(reconstruction::syntheticProfile(
                                    k % 2 ? "circle" : "example", length, 0.05)));
        const reconstruction::Wellhead head{1000.0 + 30.0 * k, 2000.0 - 20.0 * k, 50.0};
        wells.push_back({log.string(), {}, head, {}});
        lengths.push_back(length);
    }
    wells[2].path = test::scratch("assembly_no_such_log.txt").string();
    wells[5].surveyPath = test::scratch("assembly_no_such_survey.csv").string();
    const app::AssembledScene scene = app::assembleScene(wells, app::LoadOptions{});
    EXPECT_EQ(scene.wells, 5);
    EXPECT_EQ(scene.failures, 2);
    ASSERT_EQ(scene.inputs.size(), wells.size());
    std::size_t loaded = 0;
    for (std::size_t k = 0; k < wells.size(); ++k) {
        SCOPED_TRACE(k);
        EXPECT_EQ(scene.inputs[k].file, wells[k].path);
        if (k == 2 || k == 5) {
            EXPECT_TRUE(scene.inputs[k].error.has_value());
            continue;
        }
        ASSERT_FALSE(scene.inputs[k].error.has_value()) << scene.inputs[k].error->reason;
        ASSERT_TRUE(scene.inputs[k].top_m && scene.inputs[k].bottom_m);
        EXPECT_NEAR(*scene.inputs[k].bottom_m - *scene.inputs[k].top_m, lengths[k], 1e-6);
        // The same well assembled alone: the same rows at the same places, the same tree.
        const app::AssembledScene alone = app::assembleScene({wells[k]}, app::LoadOptions{});
        ASSERT_EQ(alone.wells, 1);
        const reconstruction::WellGeometry& a = *scene.geometries[loaded];
        const reconstruction::WellGeometry& b = *alone.geometries[0];
        ASSERT_EQ(a.table().rowCount(), b.table().rowCount());
        const std::size_t last = a.table().rowCount() - 1;
        // Relative to the scene's first well, not to itself.
        EXPECT_NEAR(a.centre(last).x - b.centre(last).x, -20.0 * double(k), 1e-9);
        EXPECT_NEAR(a.centre(last).y - b.centre(last).y, 30.0 * double(k), 1e-9);
        EXPECT_EQ(scene.scenes[loaded]->segmentCount(), alone.scenes[0]->segmentCount());
        EXPECT_EQ(scene.scenes[loaded]->mergedSpans(), alone.scenes[0]->mergedSpans());
        EXPECT_EQ(scene.scenes[loaded]->fullDetailTriangles(),
                  alone.scenes[0]->fullDetailTriangles());
        ++loaded;
    }
    EXPECT_EQ(loaded, 5u);
}

TEST(SceneAssemblyTest, AFieldPictureHoldsOnlyItsCoarsestSegmentLevelUpFront) {
    scenegraph::initCoin();
    const auto log = test::scratch("assembly_field_level.txt");
    io::writeColumnTextFile(
        log.string(),
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile("example", 30.0, 0.05)));
    const app::WellSource a{log.string(), {}, reconstruction::Wellhead{0.0, 0.0, 0.0}, {}};
    const app::WellSource b{log.string(), {}, reconstruction::Wellhead{25.0, 0.0, 0.0}, {}};
    const app::AssembledScene usual = app::assembleScene({a, b}, app::LoadOptions{}, {});
    const app::AssembledScene field =
        app::assembleScene({a, b}, app::LoadOptions{}, {}, reconstruction::kFieldFirstCoarseLevel);
    ASSERT_EQ(field.wells, 2);
    for (std::size_t w = 0; w < 2; ++w)
        for (std::size_t s = 0; s < field.scenes[w]->segmentCount(); ++s) {
            EXPECT_EQ(usual.scenes[w]->heldFrom(s), reconstruction::kFirstCoarseLevel);
            EXPECT_EQ(field.scenes[w]->heldFrom(s), reconstruction::kFieldFirstCoarseLevel);
        }
}

// Three wells 30 m apart, each the "example" log `length_m` long every 0.05 m, written to
// `name` in the scratch folder.
std::vector<app::WellSource> threeWellsOfOneLog(const std::string& name, double length_m) {
    const auto log = test::scratch(name);
    io::writeColumnTextFile(log.string(),
                            reconstruction::makeSyntheticWell(
                                reconstruction::syntheticProfile("example", length_m, 0.05)));
    std::vector<app::WellSource> wells;
    for (const double east : {0.0, 30.0, 60.0})
        wells.push_back({log.string(), {}, reconstruction::Wellhead{east, 0.0, 0.0}, {}});
    return wells;
}

// A field held lean (FieldRows) keeps a sample of each well's rows, among them every row its
// coarse meshes draw (planned as the well was read), builds those meshes from the sample once
// the field's exaggeration is chosen, and reads the well again for its finer levels: its scene
// and its picture are the field held whole's, coloured by `colour`. So with its segments made
// only where a picture's camera comes near (`nodes`, as render holds a field).
void expectLeanDrawsWhatWholeDraws(const std::string& colour, scenegraph::SegmentNodes nodes) {
    const bool whenNear = nodes == scenegraph::SegmentNodes::whenNear;
    SCOPED_TRACE("coloured by " + colour + (whenNear ? ", segments made when near" : ""));
    scenegraph::initCoin();
    const std::vector<app::WellSource> wells =
        threeWellsOfOneLog("assembly_lean_field_" + colour + ".txt", 1000.0);
    app::LoadOptions options;
    options.colour.quantity = colour;
    // As render plans a picture 480 pixels high: the exaggeration chosen over the wells given.
    const app::ScenePlan plan = [](auto& geometries, double& exaggeration) {
        exaggeration = scenegraph::chooseExaggeration(geometries, 0.0, 1.0e300, 480);
    };
    const app::AssembledScene whole =
        app::assembleScene(wells, options, plan, reconstruction::kFieldFirstCoarseLevel);
    // Lean from the first well on: the budget is below one well's rows.
    const app::AssembledScene lean =
        app::assembleScene(wells, options, plan, reconstruction::kFieldFirstCoarseLevel,
                           app::FieldRows{1000, false, nodes});
    // Held whole, its segments made as `nodes` says.
    const app::AssembledScene wholeToo =
        app::assembleScene(wells, options, plan, reconstruction::kFieldFirstCoarseLevel,
                           app::FieldRows{0, false, nodes});
    ASSERT_EQ(wholeToo.wells, 3);
    ASSERT_EQ(whole.wells, 3);
    ASSERT_EQ(lean.wells, 3);
    ASSERT_NE(whole.legend(), nullptr);
    ASSERT_NE(lean.legend(), nullptr);
    EXPECT_EQ(lean.legend()->range, whole.legend()->range);
    EXPECT_EQ(lean.legend()->lo, whole.legend()->lo);
    EXPECT_EQ(lean.legend()->hi, whole.legend()->hi);
    const std::size_t rows = whole.geometries.front()->table().rowCount();
    ASSERT_EQ(rows, 20001u);
    for (std::size_t w = 0; w < 3; ++w) {
        SCOPED_TRACE("well " + std::to_string(w));
        EXPECT_FALSE(whole.rows[w]);
        ASSERT_TRUE(lean.rows[w]);
        // A sample: the first and last rows, every fourth between, and the rows its coarse
        // meshes draw (a few more).
        const reconstruction::WellGeometry& sample = *lean.geometries[w];
        const std::vector<double>& held = sample.table().depth_m;
        const std::vector<double>& all = whole.geometries[w]->table().depth_m;
        EXPECT_GE(held.size(), 5001u);
        EXPECT_LT(held.size(), 5101u);
        for (std::size_t row = 0; row < rows; row += 4)
            ASSERT_TRUE(std::binary_search(held.begin(), held.end(), all[row])) << row;
        EXPECT_EQ(sample.table().depth_m.back(), whole.geometries[w]->table().depth_m.back());
        EXPECT_EQ(sample.options().radialExaggeration,
                  whole.geometries[w]->options().radialExaggeration);
        // Read again, the well is the one held whole, coloured the same.
        const auto again = lean.rows[w]();
        ASSERT_EQ(again->table().rowCount(), rows);
        EXPECT_EQ(again->options().radialExaggeration,
                  whole.geometries[w]->options().radialExaggeration);
        ASSERT_TRUE(again->options().colouring);
        EXPECT_EQ(again->options().colouring->legend().range, whole.legend()->range);
        EXPECT_EQ(again->path().back().north, whole.geometries[w]->path().back().north);
        EXPECT_EQ(lean.scenes[w]->segmentCount(), whole.scenes[w]->segmentCount());
        EXPECT_EQ(lean.scenes[w]->fullDetailTriangles(), whole.scenes[w]->fullDetailTriangles());
        // Before any picture: no segment made when near (every span has its merged mesh).
        EXPECT_EQ(lean.scenes[w]->segmentNodes(), whenNear ? 0u : lean.scenes[w]->segmentCount());
    }
    // The same pictures, pixel for pixel: of the whole field, from above, and from inside the
    // first well (whose finer levels are built from its rows read again).
    for (int view = 0; view < 3; ++view) {
        scenegraph::PictureRequest request;
        request.width = 640;
        request.height = 480;
        request.view = view == 0 ? scenegraph::ViewDirection::Iso : scenegraph::ViewDirection::Map;
        if (view == 2) {
            request.pose = scenegraph::downHolePose(*whole.geometries.front(), 100.0);
            request.tickMarks = false;
        }
        request.unloggedPath = view < 2;
        request.radialExaggeration = whole.geometries.front()->options().radialExaggeration;
        request.legend = whole.legend();
        scenegraph::Picture a, b, c;
        try {
            a = scenegraph::drawPicture(whole.pictureWells(), request);
            c = scenegraph::drawPicture(wholeToo.pictureWells(), request);
            request.legend = lean.legend();
            b = scenegraph::drawPicture(lean.pictureWells(), request);
        } catch (const std::runtime_error& e) {
            GTEST_SKIP() << e.what();  // no OpenGL
        }
        EXPECT_EQ(b.refinedSegments, a.refinedSegments);
        EXPECT_EQ(c.refinedSegments, a.refinedSegments);
        EXPECT_TRUE(c.image.rgba == a.image.rgba) << "held whole, view " << view;
        if (view == 2) {
            EXPECT_GT(a.refinedSegments, 0u);
            // Down the first hole: that well's segments near the eye, not all of them.
            const scenegraph::WellScene& first = *lean.scenes.front();
            EXPECT_GT(first.segmentNodes(), 0u);
            if (whenNear) {
                EXPECT_LT(first.segmentNodes(), first.segmentCount());
            }
        }
        ASSERT_EQ(a.image.rgba.size(), b.image.rgba.size());
        EXPECT_TRUE(a.image.rgba == b.image.rgba) << "view " << view;
    }
}

TEST(SceneAssemblyTest, AFieldHeldLeanDrawsWhatTheFieldHeldWholeDraws) {
    for (const auto nodes : {scenegraph::SegmentNodes::now, scenegraph::SegmentNodes::whenNear}) {
        expectLeanDrawsWhatWholeDraws("departure", nodes);
        if (testing::Test::IsSkipped()) return;
        // A range shared by the wells (each well's own colouring of the rows it holds, under it).
        expectLeanDrawsWhatWholeDraws("diameter", nodes);
    }
}

// A field held lean reads a well again from its log where a picture wants finer levels: row
// for row the well that was loaded. A log that changed since the load is refused, naming it,
// rather than drawn into the loaded well's picture.
TEST(SceneAssemblyTest, AFieldHeldLeanReadsItsWellsAgainUnlessTheLogChanged) {
    scenegraph::initCoin();
    const std::vector<app::WellSource> wells =
        threeWellsOfOneLog("assembly_lean_again.txt", 1000.0);
    const app::AssembledScene whole =
        app::assembleScene(wells, {}, {}, reconstruction::kFieldFirstCoarseLevel);
    const app::AssembledScene lean = app::assembleScene(
        wells, {}, {}, reconstruction::kFieldFirstCoarseLevel, app::FieldRows{1000, false});
    ASSERT_EQ(lean.wells, 3);
    for (std::size_t w = 0; w < 3; ++w) {
        SCOPED_TRACE("well " + std::to_string(w));
        ASSERT_TRUE(lean.rows[w]);
        EXPECT_LT(lean.geometries[w]->table().rowCount(), 20001u);  // held by some rows
        const auto again = lean.rows[w]();
        const io::SectionTable& a = again->table();
        const io::SectionTable& b = whole.geometries[w]->table();
        EXPECT_EQ(a.rowCount(), 20001u);
        EXPECT_EQ(a.depth_m, b.depth_m);
        EXPECT_EQ(a.radius_mm, b.radius_mm);
        EXPECT_EQ(a.p1az_deg, b.p1az_deg);
        EXPECT_EQ(again->path().back().north, whole.geometries[w]->path().back().north);
        EXPECT_EQ(again->path().back().east, whole.geometries[w]->path().back().east);
        EXPECT_EQ(again->options().radialExaggeration,
                  whole.geometries[w]->options().radialExaggeration);
    }
    io::writeColumnTextFile(
        wells.front().path,
        reconstruction::makeSyntheticWell(reconstruction::syntheticProfile("circle", 50.0, 0.5)));
    try {
        lean.rows[0]();
        ADD_FAILURE() << "a changed log was read";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(wells.front().path), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("changed since it was loaded"), std::string::npos)
            << e.what();
    }
}

// A colouring the wells cannot have fails every well of a field held lean as it fails a field
// held whole: each well's line says why, and none is drawn.
TEST(SceneAssemblyTest, AColouringAFieldCannotHaveFailsItsWellsHeldLeanOrWhole) {
    scenegraph::initCoin();
    const std::vector<app::WellSource> wells =
        threeWellsOfOneLog("assembly_lean_colour.txt", 200.0);
    app::LoadOptions options;
    options.colour.quantity = "no-such-curve";
    for (const std::size_t budget : {std::size_t{0}, std::size_t{1000}}) {
        SCOPED_TRACE("budget " + std::to_string(budget));
        const app::AssembledScene scene = app::assembleScene(
            wells, options, {}, reconstruction::kFieldFirstCoarseLevel, app::FieldRows{budget});
        EXPECT_EQ(scene.wells, 0);
        EXPECT_EQ(scene.failures, 3);
        ASSERT_EQ(scene.inputs.size(), 3u);
        for (const app::InputSummary& input : scene.inputs) {
            ASSERT_TRUE(input.error);
            EXPECT_NE(input.error->reason.find("cannot colour by 'no-such-curve'"),
                      std::string::npos)
                << input.error->reason;
        }
    }
}
