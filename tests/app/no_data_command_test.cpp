// Every verb on logs with sections without caliper data: the report marks
// them no_data, a log without any usable section is bad input (exit 1 naming
// the file), and the warning count printed is the number of warnings printed.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_run.h"
#include "io/las_writer.h"
#include "io/log_reader.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "test_support.h"

using caliper3d::test::CommandRun;
using caliper3d::test::runCaliper3d;
using caliper3d::test::scratch;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The synthetic example well with every arm null over [top, bottom] m
// (everywhere when top > bottom is not asked for: pass the whole range).
std::string writeNulledWell(const std::string& name, double top, double bottom) {
    caliper3d::io::SectionTable t = caliper3d::reconstruction::makeSyntheticWell(
        caliper3d::reconstruction::syntheticProfile("example", 60.0, 0.1));
    for (std::size_t i = 0; i < t.rowCount(); ++i)
        if (t.depth_m[i] >= top - 1e-6 && t.depth_m[i] <= bottom + 1e-6)
            for (int k = 0; k < t.armCount; ++k) t.radii(i)[k] = kNaN;
    const std::string path = scratch(name).string();
    caliper3d::io::writeLasFile(path, t);
    return path;
}

// class of every row of a report CSV, by md.
std::vector<std::pair<double, std::string>> classes(const std::filesystem::path& csv) {
    std::ifstream in(csv);
    std::string line;
    std::getline(in, line);
    std::vector<std::pair<double, std::string>> out;
    while (std::getline(in, line)) {
        std::vector<std::string> f;
        std::stringstream s(line);
        for (std::string x; std::getline(s, x, ',');) f.push_back(x);
        out.emplace_back(std::stod(f.at(0)), f.at(12));
        if (f.at(12) == "no_data") {
            EXPECT_TRUE(f.at(6).empty() && f.at(7).empty()) << line;
        }
    }
    return out;
}

std::size_t countOf(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
    return n;
}

// The "N warnings" a command's summary line gives.
long printedTotal(const std::string& output) {
    std::smatch m;
    if (!std::regex_search(output, m, std::regex(R"((\d+) warnings)"))) return -1;
    return std::stol(m[1]);
}

}  // namespace

TEST(NoDataCommandTest, ReportMarksTheIntervalNoDataAndLeavesItOutOfZonesAndVolumes) {
    const std::string log = writeNulledWell("nodata_gap.las", 30.0, 32.0);
    const auto csv = scratch("nodata_gap.csv"), zones = scratch("nodata_gap_zones.csv");
    const CommandRun r =
        runCaliper3d("report " + log + " -o " + csv.string() + " --zones " + zones.string());
    ASSERT_EQ(r.status, 0) << r.output;
    std::size_t noData = 0;
    for (const auto& [md, cls] : classes(csv)) {
        const bool inGap = md >= 30.0 - 1e-6 && md <= 32.0 + 1e-6;
        EXPECT_EQ(cls == "no_data", inGap) << md << " " << cls;
        noData += cls == "no_data";
    }
    EXPECT_EQ(noData, 21u);
    std::ifstream z(zones);
    std::string line;
    while (std::getline(z, line)) EXPECT_EQ(line.find("no_data"), std::string::npos) << line;
    EXPECT_NE(r.output.find("hole volume not covered (no caliper data): 29.90-32.10 m"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("no caliper data over 30.00-32.00 m (21 sections)"), std::string::npos)
        << r.output;
}

TEST(NoDataCommandTest, ReportAndExportCountEveryWarningTheyPrint) {
    const std::string log = writeNulledWell("nodata_count.las", 30.0, 32.0);
    for (const std::string& verb :
         {"report " + log + " -o " + scratch("nodata_count.csv").string(),
          "export " + log + " -o " + scratch("nodata_count.iv").string()}) {
        const CommandRun r = runCaliper3d(verb);
        ASSERT_EQ(r.status, 0) << r.output;
        const long total = printedTotal(r.output);
        EXPECT_GE(total, 1) << r.output;  // the no-data interval at least
        EXPECT_EQ(total, static_cast<long>(countOf(r.output, "warning: "))) << verb << "\n"
                                                                            << r.output;
    }
}

TEST(NoDataCommandTest, LogWithoutUsableCaliperDataFailsWithExitOneNamingTheFile) {
    const std::string log = writeNulledWell("nodata_all_null.las", 0.0, 1e9);
    for (const std::string& verb :
         {"report " + log + " -o " + scratch("nodata_all_null.csv").string(),
          "export " + log + " -o " + scratch("nodata_all_null.iv").string(),
          "render " + log + " -o " + scratch("nodata_all_null.png").string() +
              " --width 64 --height 64"}) {
        const CommandRun r = runCaliper3d(verb);
        EXPECT_EQ(r.status, 1) << verb << "\n" << r.output;
        EXPECT_NE(r.output.find(log + ": no usable caliper data"), std::string::npos)
            << verb << "\n"
            << r.output;
    }
    EXPECT_FALSE(std::filesystem::exists(scratch("nodata_all_null.csv")));
    // info still describes the file, and says why it cannot be used.
    const CommandRun info = runCaliper3d("info " + log);
    EXPECT_EQ(info.status, 1) << info.output;
    EXPECT_NE(info.output.find("format:"), std::string::npos) << info.output;
    EXPECT_NE(info.output.find("caliper:   0 of 601 sections measured"), std::string::npos)
        << info.output;
    EXPECT_NE(info.output.find(log + ": no usable caliper data"), std::string::npos) << info.output;
    // Why, and where: the first data line of the file the writer wrote (after its header).
    EXPECT_NE(info.output.find("every arm reading is null (NaN or the file's NULL value); the "
                               "first at line "),
              std::string::npos)
        << info.output;
}

TEST(NoDataCommandTest, StarLogNullIntervalsAreNoDataAndEverythingElseIsMeasured) {
    const auto star =
        caliper3d::test::sharedData() / "real" / "1AA072209208W400_WL_0477502_STAR_FIELD.las";
    CALIPER3D_REQUIRE_DATA(star);
    const auto csv = scratch("nodata_star.csv");
    const CommandRun r = runCaliper3d("report " + star.string() + " -o " + csv.string());
    ASSERT_EQ(r.status, 0) << r.output;
    std::size_t noData = 0;
    for (const auto& [md, cls] : classes(csv)) {
        // The issue quotes the depths to 0.01 m (40.6908 is "40.69"); the step is 0.0762 m.
        const bool inGap = (md >= 26.97 - 0.005 && md <= 40.69 + 0.005) ||
                           (md >= 183.95 - 0.005 && md <= 187.99 + 0.005);
        EXPECT_EQ(cls == "no_data", inGap) << md << " " << cls;
        noData += cls == "no_data";
    }
    EXPECT_EQ(noData, 181u + 54u);
    EXPECT_EQ(printedTotal(r.output), static_cast<long>(countOf(r.output, "warning: ")))
        << r.output;

    // The same log with every radius null, written by our own LAS writer.
    caliper3d::io::ReadOptions options;
    caliper3d::io::SectionTable t = caliper3d::io::readCaliperLog(star.string(), options, nullptr);
    for (double& radius : t.radius_mm) radius = kNaN;
    const std::string copy = scratch("nodata_star_all_null.las").string();
    caliper3d::io::writeLasFile(copy, t);
    const CommandRun bad =
        runCaliper3d("report " + copy + " -o " + scratch("nodata_star_all_null.csv").string());
    EXPECT_EQ(bad.status, 1) << bad.output;
    EXPECT_NE(bad.output.find(copy + ": no usable caliper data"), std::string::npos) << bad.output;
}
