// Minimum curvature against published survey tables (ISCWSA examples and
// clearance wells, Suncor final surveys, Petrel and wellpathpy exports).
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "io/survey_reader.h"
#include "reconstruction/path/minimum_curvature.h"
#include "reconstruction/path/survey_interpolation.h"
#include "test_support.h"

using namespace caliper3d;
using namespace caliper3d::reconstruction;

namespace {

std::filesystem::path surveys() {
    return test::sharedData() / "surveys";
}

// Largest |computed - published| over the stations, relative to the first station.
struct Misfit {
    double tvd = 0.0, north = 0.0, east = 0.0;
};
Misfit compare(const io::SurveyTable& s) {
    const std::vector<PathPoint> path = minimumCurvaturePath(surveyStations(s));
    Misfit m;
    for (std::size_t i = 0; i < path.size(); ++i) {
        if (!s.tvd_m.empty() && std::isfinite(s.tvd_m[i]))
            m.tvd = std::max(m.tvd, std::abs(path[i].tvd - (s.tvd_m[i] - s.tvd_m[0])));
        if (!s.north_m.empty() && std::isfinite(s.north_m[i]))
            m.north = std::max(m.north, std::abs(path[i].north - (s.north_m[i] - s.north_m[0])));
        if (!s.east_m.empty() && std::isfinite(s.east_m[i]))
            m.east = std::max(m.east, std::abs(path[i].east - (s.east_m[i] - s.east_m[0])));
    }
    return m;
}

}  // namespace

TEST(PublishedSurveysTest, IscwsaExampleOneTvdWithinOneCentimetre) {
    const auto file = surveys() / "iscwsa1_wellpath_extracted.csv";
    CALIPER3D_REQUIRE_DATA(file);
    const io::SurveyTable s = io::readSurvey(file.string());
    const std::vector<PathPoint> path = minimumCurvaturePath(surveyStations(s));
    EXPECT_NEAR(path.back().tvd, 3521.06, 0.01);
    EXPECT_LT(compare(s).tvd, 0.01);
}

TEST(PublishedSurveysTest, IscwsaExampleTwoInFeetWithinFiveHundredthsOfAFoot) {
    const auto file = surveys() / "iscwsa2_wellpath_extracted.csv";
    CALIPER3D_REQUIRE_DATA(file);
    const io::SurveyTable s = io::readSurvey(file.string());
    EXPECT_LT(compare(s).tvd / 0.3048, 0.05);
}

TEST(PublishedSurveysTest, IscwsaClearanceWellsMatchTvdNorthEast) {
    const auto file = surveys() / "iscwsa_clearance_wells_extracted.csv";
    CALIPER3D_REQUIRE_DATA(file);
    // One table per well: the file flattens twelve wells as well,MD,INC,...
    std::ifstream in(file);
    std::string line, header;
    std::map<std::string, std::string> wells;
    std::vector<std::string> order;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        const std::size_t comma = line.find(',');
        if (header.empty()) {
            header = line.substr(comma + 1) + "\n";
            continue;
        }
        const std::string name = line.substr(0, comma);
        if (!wells.count(name)) order.push_back(name);
        wells[name] += line.substr(comma + 1) + "\n";
    }
    ASSERT_EQ(order.size(), 12u);
    for (const std::string& name : order) {
        SCOPED_TRACE(name);
        const io::SurveyTable s = io::parseSurvey(header + wells[name], name);
        const Misfit m = compare(s);
        EXPECT_LT(m.tvd, 0.01);
        EXPECT_LT(m.north, 0.01);
        EXPECT_LT(m.east, 0.01);
    }
}

TEST(PublishedSurveysTest, SuncorFinalSurveysTvdWithinOneCentimetre) {
    for (const char* name : {"DS_0490457_02-08-31-094-05W4-00_Final_Survey.csv",
                             "DS_0492236_AA-03-04-085-09W4-00_Final_Survey_Slant.csv",
                             "105030309506W400_DS_0484034.csv"}) {
        SCOPED_TRACE(name);
        const auto file = surveys() / name;
        CALIPER3D_REQUIRE_DATA(file);
        const io::SurveyTable s = io::readSurvey(file.string());
        const Misfit m = compare(s);
        EXPECT_LT(m.tvd, 0.01);
        // Offsets are printed to 1 cm (3-03) or 1 mm and accumulate rounding of the angles.
        EXPECT_LT(m.north, 0.03);
        EXPECT_LT(m.east, 0.03);
    }
}

TEST(PublishedSurveysTest, PetrelAndWellpathpyTvdExact) {
    for (const char* name : {"100042209506W400.txt", "well9.csv"}) {
        SCOPED_TRACE(name);
        const auto file = surveys() / name;
        CALIPER3D_REQUIRE_DATA(file);
        const io::SurveyTable s = io::readSurvey(file.string());
        EXPECT_LT(compare(s).tvd, 0.01);
    }
}

TEST(PublishedSurveysTest, InterpolatingIscwsaOneAtItsOwnStationsReproducesThem) {
    const auto file = surveys() / "iscwsa1_wellpath_extracted.csv";
    CALIPER3D_REQUIRE_DATA(file);
    const io::SurveyTable s = io::readSurvey(file.string());
    const std::vector<SurveyStation> stations = surveyStations(s);
    const std::vector<PathPoint> exact = minimumCurvaturePath(stations);
    const std::vector<PathPoint> interpolated = interpolateSurveyPath(stations, s.md_m);
    for (std::size_t i = 0; i < exact.size(); ++i) {
        EXPECT_NEAR(interpolated[i].tvd, exact[i].tvd, 1e-6);
        EXPECT_NEAR(interpolated[i].north, exact[i].north, 1e-6);
        EXPECT_NEAR(interpolated[i].east, exact[i].east, 1e-6);
    }
}

// The Petrel trace writes DX/DY in grid north (UTM zone 12, its header says so) and
// azimuths in true north: the check finds the grid convergence (AZIM_TN - AZIM_GN =
// 0.0721 deg in the file) and a grid scale factor, and nothing else left over.
TEST(PublishedSurveysTest, PositionCheckFindsThePetrelTracesGridNorthAndScale) {
    const auto file = surveys() / "100042209506W400.txt";
    CALIPER3D_REQUIRE_DATA(file);
    const SurveyPositionCheck check = checkSurveyPositions(io::readSurvey(file.string(), {}));
    EXPECT_EQ(check.tvdStations, 391u);
    EXPECT_LT(check.maxTvdDifference_m, 0.001);
    EXPECT_GT(check.maxHorizontalDifference_m, 2.0);
    EXPECT_NEAR(check.rotation_deg, -0.0721, 0.0005);
    EXPECT_NEAR(check.scale, 0.9996, 0.00005);
    EXPECT_LT(check.maxHorizontalAfterFit_m, 0.01);
}
