// caliper3d compare and splice end to end: synthetic runs of one well with known differences,
// written as LAS, and the real CMI repeat pass against itself.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "cli_run.h"
#include "csv_table.h"
#include "io/casing_program.h"
#include "io/las_reader.h"
#include "io/las_writer.h"
#include "io/log_reader.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "test_support.h"

using caliper3d::test::CommandRun;
using caliper3d::test::Csv;
using caliper3d::test::readCsv;
using caliper3d::test::runCaliper3d;
using namespace caliper3d;
using namespace caliper3d::reconstruction;

namespace {

using Kind = SyntheticFeature::Kind;

// A vertical 80 m hole every 5 cm, logged by a 24-arm tool, with a gamma-ray log and a breakout
// 245.9 x 217.9 mm at azimuth 135 over 20-25 m.
SyntheticWellSpec firstRun() {
    SyntheticWellSpec spec;
    spec.armCount = 24;
    spec.length_m = 80.0;
    spec.step_m = 0.05;
    spec.gammaRay = true;
    spec.features.push_back({Kind::Breakout, 20.0, 25.0, 245.9, 217.9, 135.0, 0.0});
    return spec;
}

// The second run: the counter 0.35 m deeper, the breakout 10 mm wider, a 2 m washout new at
// 50-52 m.
SyntheticWellSpec secondRun() {
    SyntheticWellSpec spec = firstRun();
    spec.depthOffset_m = 0.35;
    spec.features[0].dmax_mm = 255.9;
    spec.features.push_back({Kind::Washout, 50.0, 52.0, 265.9, 265.9, 0.0, 0.0});
    return spec;
}

// Two runs to splice: run 1 logs 0-60 m, run 2 40-100 m of its counter, which reads 0.3 m
// deeper than run 1's.
std::pair<SyntheticWellSpec, SyntheticWellSpec> overlappingRuns() {
    SyntheticWellSpec upper = firstRun();
    upper.length_m = 60.0;
    SyntheticWellSpec lower = firstRun();
    lower.top_m = 40.0;
    lower.length_m = 60.0;
    lower.depthOffset_m = 0.3;
    return {upper, lower};
}

std::string writeRun(const std::filesystem::path& dir, const std::string& name,
                     const SyntheticWellSpec& spec) {
    const std::string path = (dir / name).string();
    io::writeLasFile(path, makeSyntheticWell(spec));
    return path;
}

// A LAS file's curve by mnemonic (empty when it has none).
std::vector<double> lasCurve(const io::LasLog& las, const std::string& mnemonic) {
    for (const io::LasCurve& c : las.curves)
        if (c.mnemonic == mnemonic) return c.values;
    ADD_FAILURE() << "no curve " << mnemonic;
    return {};
}

io::LasLog readLasFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return io::readLas(text.str(), path.string(), {}, nullptr);
}

std::string quoted(const std::filesystem::path& p) {
    return "'" + p.string() + "'";
}

}  // namespace

TEST(CompareCommandTest, FindsTheShiftTheWiderBreakoutAndTheNewWashout) {
    const auto dir = caliper3d::test::freshScratchFolder("compare_pair");
    const std::string run1 = writeRun(dir, "run1.las", firstRun());
    const std::string run2 = writeRun(dir, "run2.las", secondRun());
    const auto csv = dir / "change.csv", zones = dir / "zones.csv", json = dir / "s.jsonl";
    const CommandRun r = runCaliper3d("compare " + run1 + " " + run2 + " -o " + csv.string() +
                                      " --zones " + zones.string() + " --summary " + json.string());
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("depth match: run 2 depth = run 1 depth +0.350 m (GR"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("wrote " + csv.string()), std::string::npos) << r.output;

    const Csv table = readCsv(csv);
    const std::vector<std::string> first = {
        "md_m",      "md2_m",    "deq1_mm",  "deq2_mm",   "d_deq_mm", "dmin1_mm", "dmin2_mm",
        "d_dmin_mm", "dmax1_mm", "dmax2_mm", "d_dmax_mm", "class1",   "class2"};
    ASSERT_GE(table.names.size(), first.size());
    for (std::size_t k = 0; k < first.size(); ++k) EXPECT_EQ(table.names[k], first[k]);
    // Run 1's sampling over the overlap: 0 to 80 - 0.35 m.
    ASSERT_EQ(table.rows.size(), 1594u);
    for (std::size_t i = 0; i < table.rows.size(); ++i) {
        const double md = table.number(i, "md_m");
        EXPECT_NEAR(table.number(i, "md2_m") - md, 0.35, 0.01);
        if (md > 20.1 && md < 24.9) {
            EXPECT_NEAR(table.number(i, "d_dmax_mm"), 10.0, 0.5) << md;
            EXPECT_EQ(table.rows[i].at("significant"), "yes") << md;
            EXPECT_NEAR(table.number(i, "max_growth_mm"), 5.0, 0.5) << md;
            EXPECT_EQ(table.rows[i].at("note"), "") << md;
        }
        if (md > 50.1 && md < 51.9) {
            EXPECT_EQ(table.rows[i].at("class2"), "washout") << md;
        }
        if (md > 30.0 && md < 45.0) {
            EXPECT_EQ(table.rows[i].at("d_deq_mm"), "0.00") << md;
            EXPECT_EQ(table.rows[i].at("significant"), "no") << md;
            // Unchanged: the outlines are not compared, and the row says so.
            EXPECT_EQ(table.rows[i].at("max_growth_mm"), "") << md;
            EXPECT_EQ(table.rows[i].at("note"),
                      "outline not compared: diameters within 1.50 mm and major axis within 10 "
                      "deg")
                << md;
        }
    }
    const Csv zoneTable = readCsv(zones);
    ASSERT_EQ(zoneTable.rows.size(), 4u);  // two zones, two changed intervals
    EXPECT_EQ(zoneTable.rows[0].at("change"), "grew");
    EXPECT_EQ(zoneTable.rows[1].at("change"), "appeared");
    EXPECT_EQ(zoneTable.rows[1].at("class"), "washout");
    EXPECT_NEAR(zoneTable.number(1, "top1_m"), 50.0, 0.06);
    EXPECT_NEAR(zoneTable.number(1, "top2_m"), 50.35, 0.06);

    std::ifstream in(json);
    std::string line;
    ASSERT_TRUE(std::getline(in, line));
    const nlohmann::json summary = nlohmann::json::parse(line);
    EXPECT_EQ(summary["verb"], "compare");
    EXPECT_EQ(summary["status"], "ok");
    EXPECT_EQ(summary["file2"], run2);
    EXPECT_NEAR(summary["comparison"]["shift_m"].get<double>(), 0.35, 0.01);
    EXPECT_EQ(summary["comparison"]["agree"], false);
    EXPECT_EQ(summary["comparison"]["zones"].size(), 2u);
}

TEST(CompareCommandTest, AllOutlinesComparesTheWallAtEveryOrientedSection) {
    const auto dir = caliper3d::test::freshScratchFolder("compare_all_outlines");
    const std::string run1 = writeRun(dir, "run1.las", firstRun());
    const std::string run2 = writeRun(dir, "run2.las", secondRun());
    const auto csv = dir / "change.csv";
    const CommandRun r =
        runCaliper3d("compare " + run1 + " " + run2 + " --all-outlines -o " + csv.string());
    ASSERT_EQ(r.status, 0) << r.output;
    const Csv table = readCsv(csv);
    ASSERT_EQ(table.rows.size(), 1594u);
    for (std::size_t i = 0; i < table.rows.size(); ++i) {
        const double md = table.number(i, "md_m");
        EXPECT_EQ(table.rows[i].at("note"), "") << md;
        if (md > 30.0 && md < 45.0) {
            EXPECT_NEAR(table.number(i, "max_growth_mm"), 0.0, 0.05) << md;
        }
    }
}

TEST(CompareCommandTest, ARunAgainstItselfAgreesWithZeroChange) {
    const auto dir = caliper3d::test::freshScratchFolder("compare_same");
    const std::string run = writeRun(dir, "run.las", firstRun());
    const CommandRun r = runCaliper3d("compare " + run + " " + run + " -o -", false);
    ASSERT_EQ(r.status, 0) << r.output;
    std::istringstream text(r.output);
    const Csv table = caliper3d::test::parseCsv(text);
    ASSERT_EQ(table.rows.size(), 1601u);
    for (std::size_t i = 0; i < table.rows.size(); ++i) {
        EXPECT_EQ(table.rows[i].at("d_deq_mm"), "0.00");
        EXPECT_EQ(table.rows[i].at("d_dmax_mm"), "0.00");
        EXPECT_EQ(table.rows[i].at("significant"), "no");
    }
    const CommandRun summary =
        runCaliper3d("compare " + run + " " + run + " -o " + (dir / "same.csv").string());
    EXPECT_NE(summary.output.find("agreement: the runs agree within the tool's repeatability"),
              std::string::npos)
        << summary.output;
}

TEST(CompareCommandTest, ArmsThatDidNotOpenInOneRunAreReportedNotCompared) {
    const auto dir = caliper3d::test::freshScratchFolder("compare_closed");
    SyntheticWellSpec closed = firstRun();
    closed.closedTop_m = 40.0;
    closed.closedBottom_m = 45.0;
    closed.closedRadius_mm = 55.0;
    const std::string run1 = writeRun(dir, "run1.las", firstRun());
    const std::string run2 = writeRun(dir, "run2.las", closed);
    const auto csv = dir / "change.csv";
    const CommandRun r = runCaliper3d("compare " + run1 + " " + run2 + " -o " + csv.string());
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("not compared: 101 run 2 arms not open"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("agreement: the runs agree"), std::string::npos) << r.output;
    const Csv table = readCsv(csv);
    for (std::size_t i = 0; i < table.rows.size(); ++i) {
        const double md = table.number(i, "md_m");
        if (md > 40.0 && md < 45.0) {
            EXPECT_EQ(table.rows[i].at("note"), "not compared: run 2 arms not open") << md;
            EXPECT_EQ(table.rows[i].at("d_deq_mm"), "") << md;
            EXPECT_EQ(table.rows[i].at("class2"), "no_data") << md;
        }
    }
}

TEST(CompareCommandTest, RunsThatDoNotOverlapAreBadInput) {
    const auto dir = caliper3d::test::freshScratchFolder("compare_apart");
    SyntheticWellSpec deeper = firstRun();
    deeper.top_m = 300.0;
    const std::string run1 = writeRun(dir, "run1.las", firstRun());
    const std::string run2 = writeRun(dir, "run2.las", deeper);
    const CommandRun r =
        runCaliper3d("compare " + run1 + " " + run2 + " -o " + (dir / "c.csv").string());
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("do not overlap"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "c.csv"));
    const CommandRun given =
        runCaliper3d("compare " + run1 + " " + run2 + " --shift 0 -o " + (dir / "c.csv").string());
    EXPECT_EQ(given.status, 1) << given.output;
    EXPECT_NE(given.output.find("do not overlap"), std::string::npos) << given.output;
}

TEST(CompareCommandTest, RunsOfDifferentFormationsMatchWeaklyAndSaySo) {
    // Two holes whose gamma rays share nothing (one run's formation 500 m deeper).
    const auto dir = caliper3d::test::freshScratchFolder("compare_weak");
    SyntheticWellSpec other = firstRun();
    other.depthOffset_m = -500.0;
    other.top_m = 0.0;
    const std::string run1 = writeRun(dir, "run1.las", firstRun());
    const std::string run2 = writeRun(dir, "run2.las", other);
    const CommandRun r =
        runCaliper3d("compare " + run1 + " " + run2 + " -o " + (dir / "c.csv").string());
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("weak: the runs may not be of one well"), std::string::npos)
        << r.output;
}

TEST(CompareCommandTest, BadUsageExitsTwo) {
    const auto dir = caliper3d::test::freshScratchFolder("compare_usage");
    const std::string run = writeRun(dir, "run.las", firstRun());
    EXPECT_EQ(runCaliper3d("compare " + run + " -o x.csv").status, 2);
    EXPECT_EQ(runCaliper3d("compare " + run + " " + run).status, 2);
    EXPECT_EQ(runCaliper3d("compare " + run + " " + run + " -o - --max-shift -1").status, 2);
    EXPECT_EQ(
        runCaliper3d("compare " + run + " " + run + " -o - --shift 0 --match-curve GR").status, 2);
    const CommandRun missing =
        runCaliper3d("compare " + run + " " + run + " -o - --match-curve RHOB");
    EXPECT_EQ(missing.status, 1) << missing.output;
    EXPECT_NE(missing.output.find("no curve 'RHOB'"), std::string::npos) << missing.output;
}

TEST(CompareCommandTest, AGivenShiftIsUsedAsGiven) {
    const auto dir = caliper3d::test::freshScratchFolder("compare_given");
    const std::string run1 = writeRun(dir, "run1.las", firstRun());
    const std::string run2 = writeRun(dir, "run2.las", secondRun());
    const CommandRun r = runCaliper3d("compare " + run1 + " " + run2 + " --shift 0.35 -o " +
                                      (dir / "c.csv").string());
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("run 1 depth +0.350 m (given)"), std::string::npos) << r.output;
}

TEST(CompareCommandTest, TheRealCmiRepeatPassAgainstItselfAndShifted) {
    const auto cmi = caliper3d::test::sharedData() / "vendors" /
                     "WL_0486896_AA-03-08-092-07W4-00_REPEAT_PASS DIPMETER.las";
    if (!std::filesystem::exists(cmi)) GTEST_SKIP() << "no " << cmi;
    const auto dir = caliper3d::test::freshScratchFolder("compare_cmi");
    const std::string options = " --diameters DI26,DI48";  // docs/formats.md
    const CommandRun same = runCaliper3d("compare " + quoted(cmi) + " " + quoted(cmi) + options +
                                         " -o " + (dir / "same.csv").string());
    ASSERT_EQ(same.status, 0) << same.output;
    EXPECT_NE(same.output.find("+0.000 m (GRGM"), std::string::npos) << same.output;
    EXPECT_NE(same.output.find("agreement: the runs agree"), std::string::npos) << same.output;

    // The same pass with every depth of its data section written 0.47 m deeper.
    std::ifstream in(cmi);
    std::ostringstream shifted;
    std::string line;
    bool data = false;
    while (std::getline(in, line)) {
        if (data && !line.empty() && line[0] != '#') {
            std::istringstream fields(line);
            double depth = 0.0;
            fields >> depth;
            std::string rest;
            std::getline(fields, rest);
            char text[32];
            std::snprintf(text, sizeof text, "%.4f", depth + 0.47);
            line = text + rest;
        }
        if (line.rfind("~A", 0) == 0) data = true;
        shifted << line << "\n";
    }
    const auto copy = dir / "shifted.las";
    std::ofstream(copy) << shifted.str();
    const auto csv = dir / "shifted.csv";
    const CommandRun r = runCaliper3d("compare " + quoted(cmi) + " " + copy.string() + options +
                                      " -o " + csv.string());
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("+0.470 m (GRGM"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("agreement: the runs agree"), std::string::npos) << r.output;
    const Csv table = readCsv(csv);
    for (std::size_t i = 0; i < table.rows.size(); ++i)
        if (table.rows[i].at("note").empty()) {
            EXPECT_NEAR(table.number(i, "d_deq_mm"), 0.0, 0.5) << table.number(i, "md_m");
        }
}

TEST(SpliceCommandTest, TwoOverlappingRunsBecomeOneLogWithEveryFeatureAtItsDepth) {
    // Run 1 logs 0-60 m; run 2 40-100 m of its counter, which reads 0.3 m deeper (the hole at
    // 39.7-99.7 m), with a washout at 70-72 m of the hole. Joined in the overlap's middle.
    const auto dir = caliper3d::test::freshScratchFolder("splice_pair");
    auto [upper, lower] = overlappingRuns();
    lower.features.push_back({Kind::Washout, 70.0, 72.0, 265.9, 265.9, 0.0, 0.0});
    const std::string run1 = writeRun(dir, "run1.las", upper);
    const std::string run2 = writeRun(dir, "run2.las", lower);
    const auto out = dir / "spliced.las";
    const CommandRun r = runCaliper3d("splice " + run1 + " " + run2 + " -o " + out.string());
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("matched on GR, +0.300 m against run 1"), std::string::npos)
        << r.output;

    const io::LasLog las = readLasFile(out);
    const std::vector<double> depth = lasCurve(las, "DEPT");
    const std::vector<double> runs = lasCurve(las, "RUN");
    ASSERT_EQ(depth.size(), 1995u);  // 0 to 99.7 m every 0.05 m
    EXPECT_NEAR(depth.front(), 0.0, 1e-9);
    EXPECT_NEAR(depth.back(), 99.7, 1e-6);
    for (std::size_t i = 1; i < depth.size(); ++i)
        ASSERT_NEAR(depth[i] - depth[i - 1], 0.05, 1e-6) << depth[i];
    // Joined in the middle of the overlap, 39.7-60 m.
    for (std::size_t i = 0; i < depth.size(); ++i)
        EXPECT_EQ(runs[i], depth[i] < 49.85 - 1e-6 ? 1.0 : 2.0) << depth[i];
    // The breakout at 20-25 m from run 1, the washout at 70-72 m from run 2: each at its depth.
    const std::vector<double> r1 = lasCurve(las, "R1");
    for (std::size_t i = 0; i < depth.size(); ++i) {
        const double d = depth[i];
        // (The rows at exactly 70 and 72 m are the washout's edges to rounding.)
        if (d > 70.01 && d < 71.99) {
            EXPECT_NEAR(r1[i], 132.95, 1e-3) << d;
        }
        if ((d > 65.0 && d < 69.9) || (d > 72.1 && d < 80.0)) {
            EXPECT_NEAR(r1[i], 107.95, 1e-3) << d;
        }
    }
}

namespace {

// The spliced log of overlappingRuns() with run 1 in 12 1/4 in hole below 13 3/8 in 68 lb/ft
// casing set to 10.01 m, run 2 in 8 1/2 in hole below 9 5/8 in 47 lb/ft casing set to 55.01 m
// of its counter (54.71 m of run 1's), in what run 1 logged as open hole; joined at 49.85 m.
// Read back: run 1's rows cased to 10.01 m only, run 2's cased to 54.71 m, each row with its
// run's bit size.
void expectEachRunsCasingOverItsOwnRows(const std::filesystem::path& spliced,
                                        const std::string& surfaceType) {
    io::Diagnostics diagnostics;
    const io::SectionTable t = io::readCaliperLog(spliced.string(), {}, &diagnostics);
    ASSERT_EQ(t.rowCount(), 1995u);
    ASSERT_EQ(t.casing.size(), 2u);
    const double id133 = (13.375 - 2 * 0.480) * 25.4, id958 = (9.625 - 2 * 0.472) * 25.4;
    EXPECT_NEAR(t.casing[0].innerDiameter_mm, id133, 1e-9);
    EXPECT_EQ(t.casing[0].type, surfaceType);
    EXPECT_NEAR(t.casing[1].innerDiameter_mm, id958, 1e-9);
    EXPECT_NEAR(t.casing[1].bottom_m, 54.71, 1e-9);
    const std::vector<double>& runs = t.extraCurves.back().values;
    ASSERT_EQ(t.extraCurves.back().mnemonic, "RUN");
    ASSERT_EQ(t.bitSize_mm.size(), t.rowCount());
    std::size_t cased = 0;
    for (std::size_t i = 0; i < t.rowCount(); ++i) {
        const double md = t.depth_m[i];
        const bool first = md < 49.85 - 1e-6;
        ASSERT_EQ(runs[i], first ? 1.0 : 2.0) << md;
        EXPECT_NEAR(t.bitSize_mm[i], first ? 311.15 : 215.9, 1e-9) << md;
        const io::CasingString* c = io::casingAt(t.casing, md);
        const double expected =
            first ? (md < 10.01 ? id133 : io::kNaN) : (md < 54.71 ? id958 : io::kNaN);
        if (std::isnan(expected)) {
            EXPECT_EQ(c, nullptr) << md;
        } else {
            ASSERT_NE(c, nullptr) << md;
            EXPECT_NEAR(c->innerDiameter_mm, expected, 1e-9) << md;
            ++cased;
        }
    }
    EXPECT_EQ(cased, 201u + 98u);
}

// overlappingRuns() with `parameters` in each run's ~Parameter section (no BS curve).
std::pair<std::string, std::string> runsWithHeaders(
    const std::filesystem::path& dir, const std::vector<io::LasParameter>& upperParameters,
    const std::vector<io::LasParameter>& lowerParameters) {
    auto [upper, lower] = overlappingRuns();
    const auto writeWithHeader = [&](const std::string& name, const SyntheticWellSpec& spec,
                                     const std::vector<io::LasParameter>& parameters) {
        io::SectionTable t = makeSyntheticWell(spec);
        t.bitSize_mm.clear();
        io::LasWriteOptions las;
        las.parameters = parameters;
        const std::string path = (dir / name).string();
        io::writeLasFile(path, t, las);
        return path;
    };
    return {writeWithHeader("run1.las", upper, upperParameters),
            writeWithHeader("run2.las", lower, lowerParameters)};
}

}  // namespace

TEST(SpliceCommandTest, EachRunsCasingAndBitSizeReadBackOverItsOwnRows) {
    // Both runs give their casing and bit size in ~Parameter only.
    const auto dir = caliper3d::test::freshScratchFolder("splice_casing");
    const auto [run1, run2] = runsWithHeaders(dir,
                                              {{"BS", "IN", "12.25", "bit size"},
                                               {"CSGL", "M", "10.01", "casing shoe"},
                                               {"CSGS", "IN", "13.375", "casing size"},
                                               {"CSGW", "LB/FT", "68", "casing weight"},
                                               {"CSGT", "", "SURFACE", "casing type"}},
                                              {{"BS", "IN", "8.5", "bit size"},
                                               {"CSGL", "M", "55.01", "casing shoe"},
                                               {"CSGS", "IN", "9.625", "casing size"},
                                               {"CSGW", "LB/FT", "47", "casing weight"}});
    const auto out = dir / "spliced.las";
    const CommandRun r = runCaliper3d("splice " + run1 + " " + run2 + " -o " + out.string());
    ASSERT_EQ(r.status, 0) << r.output;
    expectEachRunsCasingOverItsOwnRows(out, "SURFACE");
}

TEST(SpliceCommandTest, CasingEachGivesEachRunItsOwnProgram) {
    // The headers carry bit sizes only: each run's casing comes from --casing-each, in order.
    // --casing, one program for every run, would case run 1's open hole with the 9 5/8 in
    // string set only after it was logged.
    const auto dir = caliper3d::test::freshScratchFolder("splice_casing_each");
    const auto [run1, run2] = runsWithHeaders(dir, {{"BS", "IN", "12.25", "bit size"}},
                                              {{"BS", "IN", "8.5", "bit size"}});
    const auto out = dir / "spliced.las";
    const CommandRun r = runCaliper3d(
        "splice --casing-each '10.01,13.375in,68lb/ft' --casing-each '55.01,9.625in,47lb/ft' " +
        run1 + " " + run2 + " -o " + out.string());
    ASSERT_EQ(r.status, 0) << r.output;
    expectEachRunsCasingOverItsOwnRows(out, "");

    const CommandRun both = runCaliper3d(
        "splice --casing 10.01,13.375in,68lb/ft --casing-each - "
        "--casing-each - " +
        run1 + " " + run2 + " -o " + out.string());
    EXPECT_EQ(both.status, 2) << both.output;
    EXPECT_NE(both.output.find("--casing and --casing-each exclude each other"), std::string::npos)
        << both.output;
    const CommandRun once = runCaliper3d("splice --casing-each 10.01,13.375in " + run1 + " " +
                                         run2 + " -o " + out.string());
    EXPECT_EQ(once.status, 2) << once.output;
    EXPECT_NE(once.output.find("give it once per file, in order"), std::string::npos)
        << once.output;
}

TEST(SpliceCommandTest, RunsOfDifferentToolsOrWithoutOverlapAreRefused) {
    const auto dir = caliper3d::test::freshScratchFolder("splice_bad");
    SyntheticWellSpec four = firstRun();
    four.armCount = 6;
    SyntheticWellSpec apart = firstRun();
    apart.top_m = 200.0;
    const std::string run1 = writeRun(dir, "run1.las", firstRun());
    const CommandRun arms = runCaliper3d("splice " + run1 + " " + writeRun(dir, "four.las", four) +
                                         " --shift 0 -o " + (dir / "o.las").string());
    EXPECT_EQ(arms.status, 1) << arms.output;
    EXPECT_NE(arms.output.find("splice joins runs of one tool"), std::string::npos) << arms.output;
    const CommandRun gap = runCaliper3d("splice " + run1 + " " + writeRun(dir, "apart.las", apart) +
                                        " -o " + (dir / "o.las").string());
    EXPECT_EQ(gap.status, 1) << gap.output;
    EXPECT_NE(gap.output.find("do not overlap"), std::string::npos) << gap.output;
    EXPECT_EQ(runCaliper3d("splice " + run1 + " -o x.las").status, 2);
}
