#include "reconstruction/survey_interpolation.h"

#include <cmath>
#include <vector>

#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

using namespace caliper3d::reconstruction;

namespace {
constexpr double kRate = 3.0 / 30.0;  // degrees per metre

// Exact build arc from vertical at kickoff 100 m, azimuth 30 deg.
PathPoint exactBuild(double md) {
    const double R = 1.0 / glm::radians(kRate);
    PathPoint p;
    p.md = md;
    double horizontal = 0.0, tvd = md;
    if (md > 100.0) {
        const double theta = glm::radians((md - 100.0) * kRate);
        horizontal = R * (1.0 - std::cos(theta));
        tvd = 100.0 + R * std::sin(theta);
        p.inc_deg = (md - 100.0) * kRate;
    }
    p.north = horizontal * std::cos(glm::radians(30.0));
    p.east = horizontal * std::sin(glm::radians(30.0));
    p.tvd = tvd;
    return p;
}
}  // namespace

TEST(SurveyInterpolationTest, PointsBetweenSparseStationsLieOnTheExactArc) {
    // Stations 100 m apart on a constant-rate build: minimum curvature is
    // exact on circular arcs, so interpolation must be exact too, where a
    // linear interpolation of the angles would not be.
    const std::vector<SurveyStation> survey{{0, 0, 30}, {100, 0, 30}, {200, 10, 30}, {300, 20, 30}, {400, 30, 30}};
    std::vector<double> md;
    for (double d = 0.0; d <= 400.0; d += 2.5) md.push_back(d);
    const std::vector<PathPoint> path = interpolateSurveyPath(survey, md);
    for (const PathPoint& p : path) {
        const PathPoint e = exactBuild(p.md);
        EXPECT_NEAR(p.tvd, e.tvd, 1e-6) << p.md;
        EXPECT_NEAR(p.north, e.north, 1e-6) << p.md;
        EXPECT_NEAR(p.east, e.east, 1e-6) << p.md;
        EXPECT_NEAR(p.inc_deg, e.inc_deg, 1e-9) << p.md;
        if (p.md > 100.0) {
            EXPECT_NEAR(p.dls_degPer30m, 3.0, 1e-9) << p.md;
        }
    }
}

TEST(SurveyInterpolationTest, TurnInterpolatesAzimuthAcrossNorth) {
    const SurveyStation a{0, 90, 350}, b{100, 90, 10};
    const SurveyStation mid = stationOnArc(a, b, 50.0);
    EXPECT_NEAR(mid.inc_deg, 90.0, 1e-9);
    EXPECT_NEAR(std::min(mid.azi_deg, 360.0 - mid.azi_deg), 0.0, 1e-9);
}

TEST(SurveyInterpolationTest, ExtrapolatesStraightBeyondTheEnds) {
    const std::vector<SurveyStation> survey{{10, 0, 0}, {20, 90, 90}};
    const std::vector<PathPoint> path = interpolateSurveyPath(survey, {0.0, 30.0});
    EXPECT_NEAR(path[0].tvd, -10.0, 1e-12);  // above the first station, straight up
    const std::vector<PathPoint> stations = minimumCurvaturePath(survey);
    EXPECT_NEAR(path[1].east, stations[1].east + 10.0, 1e-9);
    EXPECT_NEAR(path[1].tvd, stations[1].tvd, 1e-9);
}

TEST(SurveyInterpolationTest, NeedsTwoStations) {
    EXPECT_THROW(interpolateSurveyPath({{0, 0, 0}}, {0.0}), std::invalid_argument);
}
