#include "reconstruction/section/periodic_spline.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include "reconstruction/section/arm_geometry.h"
#include "reconstruction/synthetic/synthetic_well.h"

using namespace caliper3d::reconstruction;

TEST(PeriodicSplineTest, CyclicSolverMatchesDenseProduct) {
    const std::vector<double> sub{1, 2, 1, 1, 0.5}, diag{5, 6, 7, 5, 4}, super{1, 1, 2, 0.5, 1};
    const std::vector<double> x{1, -2, 3, 0.5, -1};
    const std::size_t n = x.size();
    std::vector<double> rhs(n);
    for (std::size_t i = 0; i < n; ++i)
        rhs[i] = sub[i] * x[(i + n - 1) % n] + diag[i] * x[i] + super[i] * x[(i + 1) % n];
    const std::vector<double> solved = solveCyclicTridiagonal(sub, diag, super, rhs);
    for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(solved[i], x[i], 1e-12);
}

TEST(PeriodicSplineTest, PassesThroughEveryPad) {
    const std::vector<double> pads{108.0, 112.5, 104.2, 109.9, 121.0, 107.3};
    PeriodicSpline spline(pads);
    for (std::size_t k = 0; k < pads.size(); ++k)
        EXPECT_NEAR(spline(static_cast<double>(k)), pads[k], 1e-12);
    PeriodicSplineSampler sampler(6, 48);
    std::vector<double> out(48);
    sampler.sample(pads.data(), out.data());
    for (std::size_t k = 0; k < pads.size(); ++k) EXPECT_NEAR(out[k * 8], pads[k], 1e-12);
}

TEST(PeriodicSplineTest, IsC2AcrossTheSeam) {
    PeriodicSpline spline({3.0, 7.0, 1.0, 4.0, 9.0, 2.0});
    const double eps = 1e-9;
    const double n = spline.size();
    EXPECT_NEAR(spline(n - eps), spline(0.0), 1e-7);
    EXPECT_NEAR(spline.derivative(n - eps), spline.derivative(eps), 1e-6);
    EXPECT_NEAR(spline.secondDerivative(n - eps), spline.secondDerivative(eps), 1e-6);
    // and at an interior knot
    EXPECT_NEAR(spline.derivative(2.0 - eps), spline.derivative(2.0 + eps), 1e-6);
    EXPECT_NEAR(spline.secondDerivative(2.0 - eps), spline.secondDerivative(2.0 + eps), 1e-6);
    // A cubic spline is not a straight interpolant: the second derivative is not zero.
    EXPECT_GT(std::abs(spline.secondDerivative(0.0)), 1.0);
}

namespace {
// Distance from a point to a circle, relative to the circle's radius.
double circleError(glm::dvec2 p, glm::dvec2 centre, double radius) {
    return std::abs(glm::length(p - centre) - radius) / radius;
}
// Samples the section spline (polar radius about the tool axis) as 2D points.
std::vector<glm::dvec2> sampleSection(const std::vector<double>& pads, int samples) {
    PeriodicSplineSampler sampler(static_cast<int>(pads.size()), samples);
    std::vector<double> r(static_cast<std::size_t>(samples));
    sampler.sample(pads.data(), r.data());
    std::vector<glm::dvec2> pts;
    for (int j = 0; j < samples; ++j) {
        const double toolAngle = -glm::two_pi<double>() * j / samples;
        pts.push_back(r[static_cast<std::size_t>(j)] *
                      glm::dvec2(std::cos(toolAngle), std::sin(toolAngle)));
    }
    return pts;
}
}  // namespace

TEST(PeriodicSplineTest, CircleFromSixPadsStaysWithinHalfPercent) {
    const double radius = 108.0;
    // Centred tool: every pad reads the radius, the spline is the circle.
    for (const glm::dvec2& p : sampleSection(std::vector<double>(6, radius), 360))
        EXPECT_LT(circleError(p, {0, 0}, radius), 1e-12);
    // Off-centre tool (12 mm): pads are true wall points seen from the tool axis.
    const glm::dvec2 centre(12.0, -5.0);
    std::vector<double> pads;
    for (int k = 1; k <= 6; ++k) {
        const double a = glm::radians(armToolAngle_deg(k, 6));
        const glm::dvec2 d(std::cos(a), std::sin(a));
        // Ray from the tool axis (origin) along d meets the circle |x - c| = R.
        const double b = glm::dot(d, centre);
        pads.push_back(b + std::sqrt(b * b - glm::dot(centre, centre) + radius * radius));
    }
    double worst = 0.0;
    for (const glm::dvec2& p : sampleSection(pads, 360))
        worst = std::max(worst, circleError(p, centre, radius));
    EXPECT_LT(worst, 0.005);
}

TEST(PeriodicSplineTest, EllipseFromSixPadsStaysWithinTwoPercent) {
    const double dmax = 240.0, dmin = 216.0;
    for (double majorToolAngle : {0.0, 17.0, 30.0, 45.0, 72.0}) {
        std::vector<double> pads;
        for (int k = 1; k <= 6; ++k)
            pads.push_back(ellipseRadius_mm(dmax, dmin, armToolAngle_deg(k, 6) - majorToolAngle));
        const std::vector<glm::dvec2> pts = sampleSection(pads, 360);
        double worst = 0.0;
        for (const glm::dvec2& p : pts) {
            const double angle = glm::degrees(std::atan2(p.y, p.x));
            const double truth = ellipseRadius_mm(dmax, dmin, angle - majorToolAngle);
            worst = std::max(worst, std::abs(glm::length(p) - truth) / truth);
        }
        EXPECT_LT(worst, 0.02) << "major axis at tool angle " << majorToolAngle;
    }
}
