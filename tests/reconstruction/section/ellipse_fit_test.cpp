#include "reconstruction/section/ellipse_fit.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <glm/trigonometric.hpp>

using namespace caliper3d::reconstruction;

TEST(EllipseFitTest, RecoversAxesAngleAndCentreOfAnExactEllipse) {
    const double a = 130.0, b = 105.0, theta = glm::radians(35.0), cx = 12.0, cy = -7.0;
    std::vector<double> x, y;
    for (int i = 0; i < 48; ++i) {
        const double t = 2.0 * M_PI * i / 48.0;
        x.push_back(cx + a * std::cos(t) * std::cos(theta) - b * std::sin(t) * std::sin(theta));
        y.push_back(cy + a * std::cos(t) * std::sin(theta) + b * std::sin(t) * std::cos(theta));
    }
    const Ellipse e = fitEllipse(x.data(), y.data(), 48);
    ASSERT_TRUE(e.valid);
    EXPECT_NEAR(e.major, 2 * a, 1e-7);
    EXPECT_NEAR(e.minor, 2 * b, 1e-7);
    EXPECT_NEAR(glm::degrees(e.majorAngle_rad), 35.0, 1e-7);
    EXPECT_NEAR(e.centreX, cx, 1e-7);
    EXPECT_NEAR(e.centreY, cy, 1e-7);
}

TEST(EllipseFitTest, MajorAxisAngleStaysInZeroToPi) {
    std::vector<double> x, y;
    for (int i = 0; i < 24; ++i) {
        const double t = 2.0 * M_PI * i / 24.0;
        const double th = glm::radians(170.0);
        x.push_back(100 * std::cos(t) * std::cos(th) - 50 * std::sin(t) * std::sin(th));
        y.push_back(100 * std::cos(t) * std::sin(th) + 50 * std::sin(t) * std::cos(th));
    }
    const Ellipse e = fitEllipse(x.data(), y.data(), 24);
    ASSERT_TRUE(e.valid);
    EXPECT_NEAR(glm::degrees(e.majorAngle_rad), 170.0, 1e-7);
}

TEST(EllipseFitTest, TooFewOrCollinearPointsAreNotAnEllipse) {
    const double x[] = {0, 1, 2, 3, 4, 5}, y[] = {0, 1, 2, 3, 4, 5};
    EXPECT_FALSE(fitEllipse(x, y, 4).valid);
    EXPECT_FALSE(fitEllipse(x, y, 6).valid);
}
