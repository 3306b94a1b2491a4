// loadWell: the one recipe that loads a well for every verb, the window and
// the load pipeline (reconstruction/load/load_well.h).
#include "reconstruction/load/load_well.h"

#include <cmath>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "io/column_text_writer.h"
#include "io/las_writer.h"
#include "io/parse_error.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "test_support.h"

namespace caliper3d::reconstruction {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A 40 m synthetic log written as column text by our own writer; returns its
// path and, through `lines`, how many lines the file has.
std::string writeLog(const std::string& name, std::size_t* lines = nullptr) {
    const auto path = test::scratch(name);
    io::writeColumnTextFile(path.string(),
                            makeSyntheticWell(syntheticProfile("circle", 40.0, 0.5)));
    if (lines) {
        std::ifstream in(path);
        std::string line;
        *lines = 0;
        while (std::getline(in, line)) ++*lines;
    }
    return path.string();
}

// A straight survey, 30 degrees from vertical towards east (azimuth 90),
// from the depth reference to 100 m; with `tvdColumn`, TVD written as MD
// (which ignores the inclination: 100 - 100 cos 30 = 13.4 m off at 100 m).
std::string writeSurvey(const std::string& name, bool tvdColumn) {
    const auto path = test::scratch(name);
    std::ofstream out(path);
    out << (tvdColumn ? "MD,Inc,Azi,TVD\n" : "MD,Inc,Azi\n");
    for (int md = 0; md <= 100; md += 10) {
        out << md << ",30,90";
        if (tvdColumn) out << "," << md;
        out << "\n";
    }
    return path.string();
}

bool hasWarning(const io::Diagnostics& d, const std::string& file, std::size_t line,
                const std::string& text) {
    for (const io::Warning& w : d.warnings)
        if (w.file == file && w.line == line && w.message.find(text) != std::string::npos)
            return true;
    return false;
}

TEST(LoadWellTest, SurveyAndWellheadPlaceTheGeometryAlongTheSurvey) {
    const std::string log = writeLog("load_well_placed.txt");
    const WellSource source{
        log, writeSurvey("load_well_placed_survey.csv", false), Wellhead{1100.0, 1950.0, 40.0}, {}};
    const Wellhead origin{1000.0, 2000.0, 50.0};
    const LoadedWell well = loadWell(source, LoadOptions{}, origin);
    ASSERT_TRUE(well.table);
    ASSERT_TRUE(well.geometry);
    EXPECT_EQ(well.geometry->table().source, log);
    ASSERT_GT(well.table->rowCount(), 10u);
    // A straight hole: MD sin 30 east and MD cos 30 down of the wellhead, which
    // lies 50 m south, 100 m east and 10 m below the origin.
    const double s = std::sin(30.0 * kPi / 180.0), c = std::cos(30.0 * kPi / 180.0);
    for (std::size_t row = 0; row < well.table->rowCount(); row += 7) {
        const double md = well.table->depth_m[row];
        const Ned p = well.geometry->centre(row);
        EXPECT_NEAR(p.x, -50.0, 1e-6) << "MD " << md;
        EXPECT_NEAR(p.y, 100.0 + md * s, 1e-6) << "MD " << md;
        EXPECT_NEAR(p.z, 10.0 + md * c, 1e-6) << "MD " << md;
    }
}

TEST(LoadWellTest, WithoutSurveyOrWellheadTheWellStandsAtTheOrigin) {
    const LoadedWell well = loadWell({writeLog("load_well_plain.txt"), {}, {}, {}}, LoadOptions{});
    for (std::size_t row = 0; row < well.table->rowCount(); row += 9) {
        const Ned p = well.geometry->centre(row);
        EXPECT_NEAR(p.x, 0.0, 1e-9);
        EXPECT_NEAR(p.y, 0.0, 1e-9);
        EXPECT_NEAR(p.z, well.table->depth_m[row], 1e-9);
    }
}

TEST(LoadWellTest, TheTableCarriesTheLogsWellName) {
    const auto las = test::scratch("load_well_named.las");
    io::LasWriteOptions named;
    named.wellName = "SUNCOR LEWIS 7-22-92-8";
    io::writeLasFile(las.string(), makeSyntheticWell(syntheticProfile("circle", 10.0, 0.5)), named);
    EXPECT_EQ(loadWell({las.string(), {}, {}, {}}, LoadOptions{}).table->wellName,
              "SUNCOR LEWIS 7-22-92-8");
    // Column text has no header to name it.
    EXPECT_EQ(
        loadWell({writeLog("load_well_unnamed.txt"), {}, {}, {}}, LoadOptions{}).table->wellName,
        "");
}

TEST(LoadWellTest, TheTableCarriesTheUnitsTheFileWrote) {
    const auto las = test::scratch("load_well_units.las");
    io::writeLasFile(las.string(), makeSyntheticWell(syntheticProfile("circle", 10.0, 0.5)));
    std::string depthUnit, caliperUnit;
    {
        std::ifstream in(las);
        std::string line;
        while (
            std::getline(in, line)) {  // the writer's own ~Curve lines: "DEPT.M ...", "R1.IN ..."
            const auto dot = line.find('.');
            const auto space = line.find(' ', dot);
            if (dot == std::string::npos || space == std::string::npos) continue;
            const std::string name = line.substr(0, dot),
                              unit = line.substr(dot + 1, space - dot - 1);
            if (name.find("DEPT") != std::string::npos && depthUnit.empty()) depthUnit = unit;
            if (name.find("R1") != std::string::npos && caliperUnit.empty()) caliperUnit = unit;
        }
    }
    ASSERT_FALSE(depthUnit.empty());
    ASSERT_FALSE(caliperUnit.empty());
    const auto table = loadWell({las.string(), {}, {}, {}}, LoadOptions{}).table;
    EXPECT_EQ(table->fileDepthUnit, depthUnit);
    EXPECT_EQ(table->fileCaliperUnit, caliperUnit);
}

TEST(LoadWellTest, DiagnosticsHoldTheSurveysWarningThenTheReaders) {
    std::size_t lines = 0;
    const std::string log = writeLog("load_well_warned.txt", &lines);
    // A truncated last row: skipped by the reader with a warning on its line.
    { std::ofstream(log, std::ios::app) << "40.5 1.0 2.0\n"; }
    const std::string survey = writeSurvey("load_well_warned_survey.csv", true);
    const LoadedWell well = loadWell({log, survey, {}, {}}, LoadOptions{});
    const io::Diagnostics& d = well.diagnostics;
    EXPECT_TRUE(hasWarning(d, survey, 1, "disagree with minimum curvature")) << d.warningCount;
    EXPECT_TRUE(hasWarning(d, log, lines + 1, "(truncated file?); skipped")) << d.warningCount;
    ASSERT_GE(d.warnings.size(), 2u);
    EXPECT_EQ(d.warnings.front().file, survey);  // read first: it is small
    EXPECT_EQ(d.warningCount, d.warnings.size());
}

TEST(LoadWellTest, GeometryWarningsJoinUnlessTheCallerAnalysesTheWell) {
    // Arm 1 closed (zero) on every row: interpolated from its neighbours.
    io::SectionTable table = makeSyntheticWell(syntheticProfile("circle", 20.0, 0.5));
    for (std::size_t row = 0; row < table.rowCount(); ++row)
        table.radius_mm[row * static_cast<std::size_t>(table.armCount)] = 0.0;
    const auto path = test::scratch("load_well_repaired.txt").string();
    io::writeColumnTextFile(path, table);
    const LoadedWell scanned = loadWell({path, {}, {}, {}}, LoadOptions{});
    EXPECT_TRUE(hasWarning(scanned.diagnostics, path, 0,
                           std::to_string(table.rowCount()) + " arms interpolated on " +
                               std::to_string(table.rowCount()) + " sections"));
    LoadOptions analysed;
    analysed.geometryWarnings = false;
    EXPECT_EQ(loadWell({path, {}, {}, {}}, analysed).diagnostics.warningCount, 0u);
}

TEST(LoadWellTest, BadSurveyFailsNamingItsFileAndLine) {
    const auto survey = test::scratch("load_well_bad_survey.csv");
    { std::ofstream(survey) << "MD,Inc,Azi\n0,0,0\n10,abc,0\n20,1,0\n"; }
    try {
        loadWell({writeLog("load_well_bad.txt"), survey.string(), {}, {}}, LoadOptions{});
        FAIL() << "a bad survey was accepted";
    } catch (const io::ParseError& e) {
        EXPECT_EQ(e.file(), survey.string());
        EXPECT_EQ(e.line(), 3u);
    }
}

TEST(LoadWellTest, CheckedSurveyMeasuresHowFarItsPositionsAreFromMinimumCurvature) {
    const std::string survey = writeSurvey("load_well_checked.csv", true);
    io::Diagnostics d;
    const CheckedSurvey checked = readCheckedSurvey(survey, io::ReadOptions{}, &d);
    EXPECT_EQ(checked.table.stationCount(), 11u);
    EXPECT_NEAR(checked.check.maxTvdDifference_m, 100.0 - 100.0 * std::cos(30.0 * kPi / 180.0),
                1e-6);
    EXPECT_EQ(d.warningCount, 1u);
    // Without a TVD column there is nothing to disagree with.
    io::Diagnostics none;
    readCheckedSurvey(writeSurvey("load_well_unchecked.csv", false), io::ReadOptions{}, &none);
    EXPECT_EQ(none.warningCount, 0u);
}

TEST(LoadWellTest, SceneOriginIsTheFirstWellsWellhead) {
    EXPECT_EQ(sceneOrigin({}).easting_m, 0.0);
    const Wellhead origin =
        sceneOrigin({{"a", {}, Wellhead{1.0, 2.0, 3.0}, {}}, {"b", {}, {}, {}}});
    EXPECT_EQ(origin.easting_m, 1.0);
    EXPECT_EQ(origin.northing_m, 2.0);
    EXPECT_EQ(origin.elevation_m, 3.0);
}

}  // namespace
}  // namespace caliper3d::reconstruction
