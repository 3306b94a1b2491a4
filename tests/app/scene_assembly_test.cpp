#include "app/scene_assembly.h"

#include <fstream>

#include <gtest/gtest.h>

#include "io/column_text_writer.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "scenegraph/main_thread.h"
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
