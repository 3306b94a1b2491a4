#include "reconstruction/path/survey_interpolation.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <glm/trigonometric.hpp>

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
    const std::vector<SurveyStation> survey{
        {0, 0, 30}, {100, 0, 30}, {200, 10, 30}, {300, 20, 30}, {400, 30, 30}};
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

namespace {
// The exact build arc as a survey file would write it: stations at the
// surface, the kick-off and every 30 m below, with TVD, north and east, the horizontal ones turned
// `turn_deg` clockwise about the wellhead and scaled by `scale` (a grid), from grid origin (E0,
// N0).
caliper3d::io::SurveyTable writtenBuild(double turn_deg, double scale) {
    caliper3d::io::SurveyTable t;
    const double c = std::cos(glm::radians(turn_deg)), s = std::sin(glm::radians(turn_deg));
    for (double md : {0.0,   100.0, 130.0, 160.0, 190.0, 220.0, 250.0, 280.0, 310.0, 340.0, 370.0,
                      400.0, 430.0, 460.0, 490.0, 520.0, 550.0, 580.0, 610.0, 640.0, 670.0}) {
        const PathPoint p = exactBuild(md);
        t.md_m.push_back(md);
        t.inc_deg.push_back(p.inc_deg);
        t.azi_deg.push_back(30.0);
        t.tvd_m.push_back(p.tvd);
        // Clockwise seen from above (north up, east right) turns north towards east.
        t.north_m.push_back(6.8e6 + scale * (p.north * c - p.east * s));
        t.east_m.push_back(5.1e5 + scale * (p.east * c + p.north * s));
    }
    return t;
}
}  // namespace

TEST(SurveyPositionCheckTest, TheExactArcAgreesAndAGridIsFoundAsATurnAndAScale) {
    const SurveyPositionCheck exact = checkSurveyPositions(writtenBuild(0.0, 1.0));
    EXPECT_EQ(exact.tvdStations, 21u);
    EXPECT_EQ(exact.horizontalStations, 21u);
    EXPECT_LT(exact.maxTvdDifference_m, 1e-6);
    EXPECT_LT(exact.maxHorizontalDifference_m, 1e-6);
    EXPECT_EQ(describeSurveyPositionCheck(exact).find("turned"), std::string::npos);

    // Grid north 0.5 deg off true, grid scale 0.9996: 570 m of build reach
    // 199 m of departure, so the raw difference is about 1.7 m.
    const SurveyPositionCheck grid = checkSurveyPositions(writtenBuild(0.5, 0.9996));
    EXPECT_GT(grid.maxHorizontalDifference_m, 1.0);
    EXPECT_NEAR(grid.maxHorizontalAt_m, 670.0, 1e-9);
    EXPECT_NEAR(grid.rotation_deg, 0.5, 1e-9);
    EXPECT_NEAR(grid.scale, 0.9996, 1e-12);
    EXPECT_LT(grid.maxHorizontalAfterFit_m, 1e-6);
    EXPECT_NE(describeSurveyPositionCheck(grid).find(
                  "once turned 0.5000 deg clockwise and scaled by 0.999600"),
              std::string::npos)
        << describeSurveyPositionCheck(grid);

    // A TVD written 0.3 m off at one station is found there.
    caliper3d::io::SurveyTable wrong = writtenBuild(0.0, 1.0);
    wrong.tvd_m[10] += 0.3;
    const SurveyPositionCheck off = checkSurveyPositions(wrong);
    EXPECT_NEAR(off.maxTvdDifference_m, 0.3, 1e-6);
    EXPECT_NEAR(off.maxTvdAt_m, 370.0, 1e-9);
}
