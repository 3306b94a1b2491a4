// --colour-by change --compare-with RUN end to end: a synthetic pair of runs of one well (the
// drawn run's counter 0.35 m deeper, its tool 90 degrees round, its washout 10 mm wider)
// exported with per-vertex colours and rendered.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <assimp/scene.h>
#include <gtest/gtest.h>
#include <QColor>
#include <QImage>
#include <assimp/Importer.hpp>
#include <nlohmann/json.hpp>

#include "cli_run.h"
#include "io/las_writer.h"
#include "reconstruction/mesh/colour_map.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "support/run_pair.h"
#include "test_support.h"

using caliper3d::test::CommandRun;
using caliper3d::test::runCaliper3d;
using namespace caliper3d;
using namespace caliper3d::reconstruction;

namespace {

// 60 m of vertical hole with a washout at 30-32 m; the second run deeper, turned, widened.
SyntheticWellSpec firstRun() {
    return widenedWashoutRuns(60.0, 30.0).first;
}
SyntheticWellSpec secondRun() {
    return widenedWashoutRuns(60.0, 30.0).second;
}

struct Runs {
    std::filesystem::path dir;
    std::string run1, run2;
};

// The pair written into a folder of the test's own (ctest runs the tests as processes at once).
Runs runs(const std::string& folder) {
    Runs r;
    r.dir = caliper3d::test::freshScratchFolder(folder);
    r.run1 = (r.dir / "run1.las").string();
    r.run2 = (r.dir / "run2.las").string();
    io::writeLasFile(r.run1, makeSyntheticWell(firstRun()));
    io::writeLasFile(r.run2, makeSyntheticWell(secondRun()));
    return r;
}

bool near(const aiColor4D& c, std::uint32_t expected, float tolerance = 1.01f / 255.0f) {
    return std::abs(c.r - static_cast<float>(red(expected)) / 255.0f) <= tolerance &&
           std::abs(c.g - static_cast<float>(green(expected)) / 255.0f) <= tolerance &&
           std::abs(c.b - static_cast<float>(blue(expected)) / 255.0f) <= tolerance;
}

// Red pixels in columns [from, to): the warm end of the diverging map, lit or shaded.
int redPixels(const QImage& image, int from, int to) {
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = from; x < to; ++x) {
            const QColor c = image.pixelColor(x, y);
            count += c.red() > 110 && c.red() > 2 * c.green() && c.red() > 2 * c.blue();
        }
    return count;
}

}  // namespace

TEST(ChangeColourCommandTest, ExportColoursTheWidenedWashoutAndLeavesTheRestGreyOrNoValue) {
    const Runs r = runs("change_colour_export");
    const auto ply = (r.dir / "change.ply").string();
    const CommandRun run =
        runCaliper3d("export " + r.run2 + " -o " + ply +
                     " --detail full --colour-by change --compare-with " + r.run1);
    ASSERT_EQ(run.status, 0) << run.output;
    EXPECT_NE(run.output.find("colour by change: run2.las minus run1.las (wall movement), "
                              "run1.las depth = run2.las depth -0.350 m (GR, correlation 1.000)"),
              std::string::npos)
        << run.output;
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(ply, 0);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    ASSERT_EQ(scene->mNumMeshes, 1u);
    const aiMesh* mesh = scene->mMeshes[0];
    ASSERT_TRUE(mesh->HasVertexColors(0));
    // Depth is -y in the scene frame (a vertical well from the wellhead at 0). The range is
    // +-(98th percentile of |change|): 2 m of 10 mm change in 60 m passes 2 %, so the washout
    // is at the red end; the unchanged hole grey; above the overlap (0-0.30 m) no value.
    int washout = 0, gauge = 0, above = 0;
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
        const double md = -mesh->mVertices[v].y;
        const aiColor4D& c = mesh->mColors[0][v];
        if (md > 30.5 && md < 32.2) {
            EXPECT_TRUE(near(c, divergingColour(1.0), 0.06f)) << md << ": " << c.r << "," << c.g;
            ++washout;
        } else if (md > 1.0 && (md < 29.5 || md > 33.5)) {
            EXPECT_TRUE(near(c, divergingColour(0.5), 0.03f)) << md << ": " << c.r << "," << c.g;
            ++gauge;
        } else if (md < 0.28) {
            EXPECT_TRUE(near(c, kNoValueColour)) << md;
            ++above;
        }
    }
    EXPECT_GT(washout, 1000);
    EXPECT_GT(gauge, 10000);
    EXPECT_GT(above, 100);
}

TEST(ChangeColourCommandTest, RenderDrawsTheChangeInRedAndARunAgainstItselfInGrey) {
    const Runs r = runs("change_colour_render");
    const auto changed = (r.dir / "changed.png").string(), same = (r.dir / "same.png").string();
    const std::string common =
        " --depth 25,38 --view east --width 800 --height 480 --exaggerate 2 --colour-by change";
    CommandRun run =
        runCaliper3d("render " + r.run2 + " -o " + changed + common + " --compare-with " + r.run1);
    ASSERT_EQ(run.status, 0) << run.output;
    run = runCaliper3d("render " + r.run1 + " -o " + same + common + " --compare-with " + r.run1);
    ASSERT_EQ(run.status, 0) << run.output;
    EXPECT_NE(run.output.find("run1.las minus run1.las"), std::string::npos) << run.output;
    const QImage a(QString::fromStdString(changed)), b(QString::fromStdString(same));
    ASSERT_FALSE(a.isNull());
    ASSERT_FALSE(b.isNull());
    // Between the overlay (its north arrow is red) and the legend, only the wall of the
    // widened washout is red; a run against itself has none.
    const int from = a.width() / 4, to = a.width() / 2 + 60;
    EXPECT_GT(redPixels(a, from, to), 300);
    EXPECT_EQ(redPixels(b, from, to), 0);
}

TEST(ChangeColourCommandTest, ChangeAndCompareWithComeTogether) {
    const Runs r = runs("change_colour_usage");
    const auto png = (r.dir / "x.png").string();
    CommandRun run = runCaliper3d("render " + r.run2 + " -o " + png + " --colour-by change");
    EXPECT_EQ(run.status, 2) << run.output;
    EXPECT_NE(run.output.find("--colour-by change needs --compare-with RUN"), std::string::npos)
        << run.output;
    run = runCaliper3d("export " + r.run2 + " -o " + (r.dir / "x.iv").string() +
                       " --compare-with " + r.run1);
    EXPECT_EQ(run.status, 2) << run.output;
    EXPECT_NE(run.output.find("give --colour-by change"), std::string::npos) << run.output;
    // A run with no depth in common: bad input, naming why.
    SyntheticWellSpec far = firstRun();
    far.top_m = 500.0;
    const auto elsewhere = (r.dir / "elsewhere.las").string();
    io::writeLasFile(elsewhere, makeSyntheticWell(far));
    run = runCaliper3d("render " + r.run2 + " -o " + png + " --colour-by change --compare-with " +
                       elsewhere);
    EXPECT_EQ(run.status, 1) << run.output;
}

TEST(ChangeColourCommandTest, RenderAndExportSummariesCarryTheComparison) {
    // The drawn run (run 2) against run 1 as `compare RUN2 RUN1` finds it: run 1's depth is
    // run 2's less 0.35 m, and its washout 10 mm narrower (run 1 minus run 2: -10 mm) at run
    // 2's 30.35-32.35 m. The wall's colour is the opposite: run 2 minus run 1.
    const Runs r = runs("change_colour_summary");
    const std::string change = " --colour-by change --compare-with " + r.run1 + " --summary ";
    const auto renderJson = r.dir / "render.jsonl", exportJson = r.dir / "export.jsonl";
    CommandRun run = runCaliper3d("render " + r.run2 + " -o " + (r.dir / "a.png").string() +
                                  " --width 320 --height 240" + change + renderJson.string());
    ASSERT_EQ(run.status, 0) << run.output;
    run = runCaliper3d("export " + r.run2 + " -o " + (r.dir / "a.ply").string() + change +
                       exportJson.string());
    ASSERT_EQ(run.status, 0) << run.output;
    for (const auto& [verb, json] : {std::pair(std::string("render"), renderJson),
                                     std::pair(std::string("export"), exportJson)}) {
        std::ifstream in(json);
        std::string line;
        ASSERT_TRUE(std::getline(in, line)) << verb;
        const nlohmann::json summary = nlohmann::json::parse(line);
        EXPECT_EQ(summary["verb"], verb);
        EXPECT_EQ(summary["file"], r.run2);
        EXPECT_EQ(summary["file2"], r.run1) << verb;
        const nlohmann::json& c = summary["comparison"];
        ASSERT_TRUE(c.is_object()) << line;
        EXPECT_EQ(c["wall_colour"], "run2.las minus run1.las, wall movement in mm");
        EXPECT_NEAR(c["shift_m"].get<double>(), -0.35, 0.01);
        EXPECT_EQ(c["match_curve"], "GR");
        EXPECT_NEAR(c["largest_d_deq"]["change_mm"].get<double>(), -10.0, 0.5) << line;
        const double at = c["largest_d_deq"]["md_m"].get<double>();
        EXPECT_GE(at, 30.3);
        EXPECT_LE(at, 32.4);
        EXPECT_EQ(c["agree"], false);
        EXPECT_GT(c["sections"].get<std::size_t>(), 1100u);
    }
}
