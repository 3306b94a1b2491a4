// Dogleg severity over a 30 m course (docs/analysis.md, "Dogleg severity").
#include "reconstruction/path/course_dogleg.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "reconstruction/analysis/well_analysis.h"
#include "reconstruction/load/well_input.h"
#include "reconstruction/path/hole_direction.h"
#include "test_support.h"

using namespace caliper3d;
using namespace caliper3d::reconstruction;

namespace {
std::vector<PathPoint> stations(double top, double bottom, double step, double (*inc)(double),
                                double (*azi)(double)) {
    std::vector<PathPoint> path;
    for (double md = top; md <= bottom + 1e-9; md += step) {
        PathPoint p;
        p.md = md;
        p.inc_deg = inc(md);
        p.azi_deg = azi(md);
        path.push_back(p);
    }
    return path;
}
}  // namespace

// A build of 3 deg/30 m at a fixed azimuth: 3.000 wherever the course lies inside it, and the
// hold after it 0 once the course has left the build.
TEST(CourseDoglegTest, ConstantBuildGivesItsRateAndAHoldGivesNone) {
    std::vector<PathPoint> path = stations(
        0.0, 300.0, 0.1, [](double md) { return md < 150.0 ? md / 10.0 : 15.0; },
        [](double) { return 30.0; });
    setCourseLengthDls(path);
    for (const PathPoint& p : path) {
        if (p.md >= 20.0 && p.md <= 130.0) {
            EXPECT_NEAR(p.dls_degPer30m, 3.0, 1e-6) << p.md;
        }
        if (p.md >= 170.0) {
            EXPECT_NEAR(p.dls_degPer30m, 0.0, 1e-6) << p.md;
        }
    }
}

// The tangents a path's placement took from its angles give the same severities bit for bit; a
// path with a tangent too few is refused.
TEST(CourseDoglegTest, GivenTangentsGiveTheSeveritiesTheAnglesGive) {
    std::vector<PathPoint> path = stations(
        0.0, 200.0, 0.1, [](double md) { return md / 8.0; },
        [](double md) { return 10.0 + md / 5.0; });
    std::vector<glm::dvec3> tangents;
    for (const PathPoint& p : path) {
        const HoleDirection d(p.inc_deg, p.azi_deg);
        tangents.emplace_back(d.sinInc * d.cosAzi, d.sinInc * d.sinAzi, d.cosInc);
    }
    std::vector<PathPoint> given = path;
    setCourseLengthDls(path);
    setCourseLengthDls(given, tangents);
    for (std::size_t i = 0; i < path.size(); ++i)
        ASSERT_EQ(given[i].dls_degPer30m, path[i].dls_degPer30m) << i;
    EXPECT_GT(path[1000].dls_degPer30m, 1.0);
    tangents.pop_back();
    EXPECT_THROW(setCourseLengthDls(given, tangents), std::invalid_argument);
}

// Builds whose courses turn by less than the 5.73 degrees below which the angle between the
// ends' directions is taken by a series, and by more: each gives its rate to 1e-11 of it.
TEST(CourseDoglegTest, BuildsEitherSideOfTheSeriesGiveTheirRates) {
    for (const double rate : {0.05, 1.0, 5.5, 6.0, 12.0}) {
        static double perMetre = 0.0;
        perMetre = rate / 30.0;
        std::vector<PathPoint> path = stations(
            0.0, 200.0, 0.1, [](double md) { return 5.0 + md * perMetre; },
            [](double) { return 120.0; });
        setCourseLengthDls(path);
        for (const PathPoint& p : path)
            if (p.md >= 20.0 && p.md <= 180.0) {
                ASSERT_NEAR(p.dls_degPer30m, rate, 1e-11 * rate) << rate << " at " << p.md;
            }
    }
}

// A turn of 3 deg/30 m in azimuth at 30 degrees inclination: 1.5 deg/30 m (= 3 sin 30).
TEST(CourseDoglegTest, TurnAtThirtyDegreesGivesHalfItsRate) {
    std::vector<PathPoint> path = stations(
        0.0, 300.0, 0.1, [](double) { return 30.0; }, [](double md) { return 10.0 + md / 10.0; });
    setCourseLengthDls(path);
    EXPECT_NEAR(path[1500].dls_degPer30m, 1.5, 1e-3);
}

// A near-vertical log whose DEVI and HAZI are noisy from sample to sample (DEVI 0.3 +- 0.2 deg,
// HAZI anywhere): between samples the dogleg severity reaches tens of degrees per 30 m, over
// the course the hole is straight to within a fraction of a degree.
TEST(CourseDoglegTest, NoisyNearVerticalLogIsStraightOverTheCourse) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> devi(0.1, 0.5), hazi(0.0, 360.0);
    std::vector<PathPoint> path;
    for (int i = 0; i < 3000; ++i) {
        PathPoint p;
        p.md = 100.0 + 0.0762 * i;
        p.inc_deg = devi(random);
        p.azi_deg = hazi(random);
        path.push_back(p);
    }
    double perSample = 0.0;
    for (std::size_t i = 1; i < path.size(); ++i) {
        const MinimumCurvatureStep s =
            minimumCurvatureStep({path[i - 1].md, path[i - 1].inc_deg, path[i - 1].azi_deg},
                                 {path[i].md, path[i].inc_deg, path[i].azi_deg});
        perSample = std::max(perSample, s.dogleg_rad * 180.0 / 3.14159265358979 * 30.0 / 0.0762);
    }
    EXPECT_GT(perSample, 50.0);
    setCourseLengthDls(path);
    for (const PathPoint& p : path) EXPECT_LT(p.dls_degPer30m, 0.5) << p.md;
}

// The STAR log (inclination at most 0.5 degrees) used to report up to 122.6 deg/30 m.
TEST(CourseDoglegTest, StarLogReportsAStraightHole) {
    const auto file = test::sharedData() / "real" / "1AA072209208W400_WL_0477502_STAR_FIELD.las";
    CALIPER3D_REQUIRE_DATA(file);
    auto table = std::make_shared<const io::SectionTable>(
        loadWellTable(file.string(), io::ReadOptions{}, false, nullptr));
    const WellGeometry geometry(table, GeometryOptions{});
    double worst = 0.0;
    for (const PathPoint& p : geometry.path()) worst = std::max(worst, p.dls_degPer30m);
    EXPECT_LT(worst, 1.0);
}

// Every severity is the one its definition gives, each end's direction the mean of the points
// within the window of it taken afresh (the nearest point's where none is): over a turning,
// building path with a 5 m stretch of no points (both ends' windows empty there) and points
// of uneven spacing.
TEST(CourseDoglegTest, EverySeverityIsTheMeanDirectionsTakenAfresh) {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> step(0.01, 0.2);
    std::vector<PathPoint> path;
    for (double md = 50.0; md < 400.0; md += step(random)) {
        if (md > 200.0 && md < 205.0) continue;
        PathPoint p;
        p.md = md;
        p.inc_deg = 10.0 + md / 12.0;
        p.azi_deg = 40.0 + 20.0 * std::sin(md / 25.0);
        path.push_back(p);
    }
    const auto tangentOf = [](const PathPoint& p) {
        const double inc = p.inc_deg * M_PI / 180.0, azi = p.azi_deg * M_PI / 180.0;
        return glm::dvec3(std::sin(inc) * std::cos(azi), std::sin(inc) * std::sin(azi),
                          std::cos(inc));
    };
    // The mean direction and depth of the points within `window` of `md`.
    const auto mean = [&](double md, double window) {
        glm::dvec3 sum(0.0);
        double depth = 0.0;
        int count = 0;
        for (const PathPoint& p : path)
            if (p.md >= md - window && p.md <= md + window) {
                sum += tangentOf(p);
                depth += p.md;
                ++count;
            }
        if (count > 0) return std::make_pair(glm::normalize(sum), depth / count);
        const auto near =
            std::lower_bound(path.begin(), path.end(), md - window,
                             [](const PathPoint& p, double value) { return p.md < value; });
        const PathPoint& p = near == path.end() ? path.back() : *near;
        return std::make_pair(tangentOf(p), p.md);
    };
    std::vector<PathPoint> computed = path;
    setCourseLengthDls(computed, 30.0, 1.5);
    int emptyWindows = 0;
    for (std::size_t i = 0; i < path.size(); ++i) {
        const double a = std::max(path.front().md, path[i].md - 15.0);
        const double b = std::min(path.back().md, path[i].md + 15.0);
        const auto [ta, mdA] = mean(a, 1.5);
        const auto [tb, mdB] = mean(b, 1.5);
        emptyWindows += (a > 201.5 && a < 203.5) || (b > 201.5 && b < 203.5);
        const double dogleg =
            std::atan2(glm::length(glm::cross(ta, tb)), glm::dot(ta, tb)) * 180.0 / M_PI;
        EXPECT_NEAR(computed[i].dls_degPer30m, dogleg * 30.0 / (mdB - mdA), 1e-9) << path[i].md;
    }
    EXPECT_GT(emptyWindows, 20);
}
