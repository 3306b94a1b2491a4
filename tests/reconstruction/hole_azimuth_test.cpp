// Hole azimuth from a known tool's convention, or unknown (docs/conventions.md,
// "Hole azimuth"), on the real logs in ../shared/data/real (skipped when absent).
#include "reconstruction/load/hole_azimuth.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "io/las_writer.h"
#include "io/log_reader.h"
#include "reconstruction/analysis/well_analysis.h"
#include "reconstruction/load/well_input.h"
#include "test_support.h"

namespace caliper3d::reconstruction {
namespace {

double circularDifference(double a, double b) {
    return std::abs(std::remainder(a - b, 360.0));
}

io::SectionTable withoutHoleAzimuth(io::SectionTable t) {
    t.hazi_deg.clear();
    t.extraCurves.erase(
        std::remove_if(t.extraCurves.begin(), t.extraCurves.end(),
                       [](const io::ExtraCurve& c) { return c.mnemonic.rfind("HAZ", 0) == 0; }),
        t.extraCurves.end());
    return t;
}

bool hasWarningContaining(const io::Diagnostics& d, const std::string& text) {
    for (const io::Warning& w : d.warnings)
        if (w.message.find(text) != std::string::npos) return true;
    return false;
}

TEST(HoleAzimuthTest, FmiCopyWithoutHaziDerivesItFromPadAzimuthAndRelativeBearing) {
    const auto file = test::sharedData() / "real" / "1AA063409108W400_FMI_SONIC_MAIN.las";
    CALIPER3D_REQUIRE_DATA(file);
    io::Diagnostics diagnostics;
    const io::SectionTable original =
        loadWellTable(file.string(), io::ReadOptions{}, false, &diagnostics);
    ASSERT_EQ(original.holeAzimuth, io::SectionTable::HoleAzimuth::Read);
    ASSERT_EQ(original.hazi_deg.size(), original.rowCount());

    // The same log without its HAZI curve (nor HAZIM, the memorised copy that
    // would be read as hole azimuth in its place), written by our own LAS
    // writer, with the service company the original names.
    io::SectionTable stripped = withoutHoleAzimuth(original);
    io::LasWriteOptions options;
    options.parameters.push_back({"SRVC", "", "Schlumberger", "service company"});
    const auto copy = test::scratch("fmi_without_hazi.las");
    io::writeLasFile(copy.string(), stripped, options);

    io::Diagnostics copyDiagnostics;
    const io::SectionTable derived =
        loadWellTable(copy.string(), io::ReadOptions{}, false, &copyDiagnostics);
    EXPECT_EQ(derived.holeAzimuth, io::SectionTable::HoleAzimuth::Derived);
    EXPECT_TRUE(hasWarningContaining(copyDiagnostics, "derived as P1AZ - RB"));
    ASSERT_EQ(derived.rowCount(), original.rowCount());
    ASSERT_EQ(derived.hazi_deg.size(), original.rowCount());
    // P1AZ = HAZI + RB holds on this tool within 0.05 deg on all rows but one,
    // at MD 73.914 m, where the file's own values differ by 1.506 deg.
    std::size_t close = 0, compared = 0;
    for (std::size_t i = 0; i < original.rowCount(); ++i) {
        if (!std::isfinite(original.hazi_deg[i])) continue;
        ++compared;
        const double d = circularDifference(derived.hazi_deg[i], original.hazi_deg[i]);
        EXPECT_LE(d, 1.51) << "MD " << original.depth_m[i];
        close += d <= 0.05;
    }
    EXPECT_EQ(compared, original.rowCount());
    EXPECT_GE(close, compared - 1);
}

TEST(HoleAzimuthTest, UnknownToolKeepsNoIdentityAndWarns) {
    // The same curves from a service company whose convention is not known.
    const auto file = test::sharedData() / "real" / "1AA063409108W400_FMI_SONIC_MAIN.las";
    CALIPER3D_REQUIRE_DATA(file);
    const io::SectionTable stripped =
        withoutHoleAzimuth(loadWellTable(file.string(), io::ReadOptions{}, false, nullptr));
    io::LasWriteOptions options;
    options.parameters.push_back({"SRVC", "", "Another Vendor", "service company"});
    const auto copy = test::scratch("unknown_tool_without_hazi.las");
    io::writeLasFile(copy.string(), stripped, options);
    io::Diagnostics diagnostics;
    const io::SectionTable t = loadWellTable(copy.string(), io::ReadOptions{}, false, &diagnostics);
    EXPECT_EQ(t.holeAzimuth, io::SectionTable::HoleAzimuth::Unknown);
    EXPECT_TRUE(t.hazi_deg.empty());
    EXPECT_TRUE(hasWarningContaining(diagnostics, "hole azimuth unknown"));
}

// A 20 degree hole of unknown azimuth: its TVD is that of any 20 degree hole, its departure is
// not drawn in any direction (the STAR log used to lean 0.73 m north over 180 m).
TEST(HoleAzimuthTest, UnknownAzimuthDrawsNoDeparture) {
    io::SectionTable t;
    t.armCount = 3;
    for (int i = 0; i <= 100; ++i) {
        t.depth_m.push_back(100.0 + i);
        for (int k = 0; k < 3; ++k) t.radius_mm.push_back(100.0);
        t.devi_deg.push_back(20.0);
        t.p1az_deg.push_back(0.0);
    }
    t.holeAzimuth = io::SectionTable::HoleAzimuth::Unknown;
    const WellGeometry g(std::make_shared<const io::SectionTable>(t), GeometryOptions{});
    ASSERT_FALSE(g.holeAzimuthKnown());
    const Ned bottom = g.centre(100);
    EXPECT_EQ(bottom.x, 0.0);
    EXPECT_EQ(bottom.y, 0.0);
    // The tie-in bends from vertical at the wellhead to 20 degrees at 100 m, then straight.
    const double straight = 100.0 * std::cos(20.0 * 3.14159265358979323846 / 180.0);
    EXPECT_NEAR(bottom.z - g.centre(0).z, straight, 1e-6);

    // With a survey (azimuth 90) it departs east.
    GeometryOptions survey;
    survey.survey = {{0.0, 0.0, 90.0}, {100.0, 20.0, 90.0}, {200.0, 20.0, 90.0}};
    const WellGeometry surveyed(std::make_shared<const io::SectionTable>(t), survey);
    EXPECT_GT(surveyed.centre(100).y, 30.0);
}

TEST(HoleAzimuthTest, StarLogHasNoHoleAzimuthAndTheReportSaysNoData) {
    const auto file = test::sharedData() / "real" / "1AA072209208W400_WL_0477502_STAR_FIELD.las";
    CALIPER3D_REQUIRE_DATA(file);
    io::Diagnostics diagnostics;
    auto table = std::make_shared<const io::SectionTable>(
        loadWellTable(file.string(), io::ReadOptions{}, false, &diagnostics));
    EXPECT_EQ(table->holeAzimuth, io::SectionTable::HoleAzimuth::Unknown);
    EXPECT_TRUE(hasWarningContaining(diagnostics, "hole azimuth unknown"));

    const WellGeometry geometry(table, GeometryOptions{});
    EXPECT_FALSE(geometry.holeAzimuthKnown());
    const WellAnalysis a = analyseWell(geometry, AnalysisOptions{});
    EXPECT_TRUE(a.holeAzimuthUnknown);
    std::size_t empty = 0, vertical = 0;
    for (const SectionResult& r : a.sections) {
        EXPECT_TRUE(std::isnan(r.azi_deg));
        EXPECT_TRUE(std::isfinite(r.tvd_m));
        if (std::isnan(r.north_m)) {
            ++empty;
            EXPECT_TRUE(std::isnan(r.east_m));
        } else {
            // Only where the path above has not leaned at all is the departure known: none.
            ++vertical;
            EXPECT_EQ(r.north_m, 0.0);
            EXPECT_EQ(r.east_m, 0.0);
        }
    }
    EXPECT_GT(empty, 1000u);  // the log leans up to 0.54 deg
    // With a survey the path's azimuth is known.
    GeometryOptions withSurvey;
    withSurvey.survey = {{0.0, 0.0, 0.0}, {200.0, 0.0, 0.0}};
    EXPECT_TRUE(WellGeometry(table, withSurvey).holeAzimuthKnown());
}

TEST(HoleAzimuthTest, PlanNamesTheSourceForInfo) {
    io::LogInfo info;
    info.curves = {{"DEPT", "M", "depth", 0, {}},
                   {"P1AZ", "DEG", "pad-1 azimuth", 0, {}},
                   {"DEVI", "DEG", "deviation", 0, {}},
                   {"RB", "DEG", "relative bearing", 0, {}}};
    info.location.serviceCompany = "Schlumberger";
    EXPECT_EQ(io::holeAzimuthPlan(info).kind, io::SectionTable::HoleAzimuth::Derived);
    EXPECT_EQ(io::holeAzimuthPlan(info, true).kind, io::SectionTable::HoleAzimuth::Read);
    info.location.serviceCompany = "Baker Hughes";
    EXPECT_EQ(io::holeAzimuthPlan(info).kind, io::SectionTable::HoleAzimuth::Unknown);
    info.curves.push_back({"HAZI", "DEG", "hole azimuth", 0, {}});
    EXPECT_EQ(io::holeAzimuthPlan(info).description, "from HAZI");
}

}  // namespace
}  // namespace caliper3d::reconstruction
