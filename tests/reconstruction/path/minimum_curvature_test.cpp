#include "reconstruction/path/minimum_curvature.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

using namespace caliper3d::reconstruction;

// The published single-step example (e.g. Bourgoyne et al., Applied Drilling
// Engineering; SPE directional survey calculation examples), in feet.
TEST(MinimumCurvatureTest, PublishedSingleStepExample) {
    const MinimumCurvatureStep s = minimumCurvatureStep({3500.0, 15.0, 20.0}, {3600.0, 25.0, 45.0});
    EXPECT_NEAR(glm::degrees(s.dogleg_rad), 12.95, 0.005);
    EXPECT_NEAR(s.dNorth, 27.22, 0.005);
    EXPECT_NEAR(s.dEast, 19.45, 0.005);
    EXPECT_NEAR(s.dTvd, 94.01, 0.005);
}

TEST(MinimumCurvatureTest, VerticalBuildHoldMatchesExactArc) {
    const double kickoff = 100.0, rate = 3.0 / 30.0;  // degrees per metre
    const double endBuild = 400.0, td = 700.0, azimuth = 30.0;
    std::vector<SurveyStation> stations;
    for (double md = 0.0; md <= td + 1e-9; md += 30.0 / 3.0) {
        const double inc = md <= kickoff ? 0.0 : (std::min(md, endBuild) - kickoff) * rate;
        stations.push_back({md, inc, azimuth});
    }
    const auto path = minimumCurvaturePath(stations);
    const double R = 1.0 / glm::radians(rate);  // radius of curvature, m
    for (const PathPoint& p : path) {
        double horizontal = 0.0, tvd = p.md;
        if (p.md > kickoff) {
            const double theta = glm::radians((std::min(p.md, endBuild) - kickoff) * rate);
            horizontal = R * (1.0 - std::cos(theta));
            tvd = kickoff + R * std::sin(theta);
            if (p.md > endBuild) {
                horizontal += (p.md - endBuild) * std::sin(theta);
                tvd += (p.md - endBuild) * std::cos(theta);
            }
        }
        const double az = glm::radians(azimuth);
        EXPECT_NEAR(p.tvd, tvd, 1e-9) << "md " << p.md;
        EXPECT_NEAR(p.north, horizontal * std::cos(az), 1e-9) << "md " << p.md;
        EXPECT_NEAR(p.east, horizontal * std::sin(az), 1e-9) << "md " << p.md;
    }
}

TEST(MinimumCurvatureTest, TinyDoglegUsesSeriesWithoutLosingDigits) {
    const MinimumCurvatureStep s =
        minimumCurvatureStep({0.0, 10.0, 50.0}, {0.0025, 10.0000001, 50.0});
    EXPECT_GT(s.dTvd, 0.0);
    EXPECT_NEAR(s.dTvd, 0.0025 * std::cos(glm::radians(10.0)), 1e-12);
}

TEST(MinimumCurvatureTest, AStepsDoglegIsTheAngleBetweenItsTangents) {
    // From a hundred-thousandth of a degree (rows 2.5 mm apart) to five degrees a step, either
    // side of the half-angle sine's series (below 0.01 rad, about 1.15 degrees), and across
    // north: the dogleg is the angle between the two unit tangents (atan2 of their cross and
    // dot products, in long double), to 1e-12 of itself.
    auto tangent = [](double inc_deg, double azi_deg) {
        const long double i = glm::radians(inc_deg), a = glm::radians(azi_deg);
        return std::vector<long double>{std::sin(i) * std::cos(a), std::sin(i) * std::sin(a),
                                        std::cos(i)};
    };
    for (const double inc : {0.3, 12.5, 87.0})
        for (const double azi : {0.002, 140.0, 359.999})
            for (const double step : {1e-5, 3e-4, 0.02, 1.1, 1.2, 2.3, 5.0}) {
                const SurveyStation a{100.0, inc, azi}, b{100.0025, inc + step, azi - 0.7 * step};
                const std::vector<long double> t = tangent(a.inc_deg, a.azi_deg),
                                               u = tangent(b.inc_deg, b.azi_deg);
                const long double cx = t[1] * u[2] - t[2] * u[1], cy = t[2] * u[0] - t[0] * u[2],
                                  cz = t[0] * u[1] - t[1] * u[0];
                const long double dot = t[0] * u[0] + t[1] * u[1] + t[2] * u[2];
                const double angle =
                    static_cast<double>(std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), dot));
                EXPECT_NEAR(minimumCurvatureStep(a, b).dogleg_rad, angle, 1e-12 * angle)
                    << "inc " << inc << " azi " << azi << " step " << step;
            }
}

TEST(MinimumCurvatureTest, DoglegSeverityPer30Metres) {
    EXPECT_DOUBLE_EQ(doglegSeverity_degPer30m(3.0, 30.0), 3.0);
    EXPECT_DOUBLE_EQ(doglegSeverity_degPer30m(1.0, 10.0), 3.0);
    EXPECT_DOUBLE_EQ(doglegSeverity_degPer30m(1.0, 0.0), 0.0);
}

TEST(MinimumCurvatureTest, StepFromSinesAndCosinesIsTheStepFromAngles) {
    const SurveyStation a{1000.0, 12.5, 359.0}, b{1000.0025, 12.5004, 0.25};
    const MinimumCurvatureStep fromAngles = minimumCurvatureStep(a, b);
    const MinimumCurvatureStep fromTrig = minimumCurvatureStep(
        a.md, HoleDirection(a.inc_deg, a.azi_deg), b.md, HoleDirection(b.inc_deg, b.azi_deg));
    EXPECT_EQ(fromTrig.dNorth, fromAngles.dNorth);
    EXPECT_EQ(fromTrig.dEast, fromAngles.dEast);
    EXPECT_EQ(fromTrig.dTvd, fromAngles.dTvd);
    EXPECT_EQ(fromTrig.dogleg_rad, fromAngles.dogleg_rad);
}

TEST(MinimumCurvatureTest, HoleDirectionKeepsAnUnchangedAngleAndItsSignOfZero) {
    HoleDirection d(0.0, 45.0);
    d.update(-0.0, 45.0);  // sin(-0) is -0: a different value for the formulas
    EXPECT_TRUE(std::signbit(d.sinInc));
    d.update(30.0, 45.0);
    EXPECT_EQ(d.sinInc, std::sin(glm::radians(30.0)));
    EXPECT_EQ(d.cosAzi, std::cos(glm::radians(45.0)));
    d.update(30.0, 46.0);
    EXPECT_EQ(d.sinAzi, std::sin(glm::radians(46.0)));
    EXPECT_EQ(d.cosInc, std::cos(glm::radians(30.0)));
}
