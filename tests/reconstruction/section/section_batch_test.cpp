#include "reconstruction/section/section_batch.h"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <glm/trigonometric.hpp>

#include "reconstruction/section/section_analysis.h"
#include "reconstruction/synthetic/synthetic_well.h"

using namespace caliper3d::reconstruction;

namespace {

constexpr int kLanes = SectionBatchAnalyzer::kLanes;

// Pads of one test section of `n` arms, shape `kind` (varied so that every
// branch of the analysis runs: fitted ellipses, circles, failed fits, zero area).
std::vector<double> pads(int n, int kind, std::mt19937& random) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<double> r(static_cast<std::size_t>(n));
    const double a = 100.0 + 40.0 * u(random), b = a * (0.7 + 0.3 * u(random)),
                 theta = 180.0 * u(random);
    for (int k = 0; k < n; ++k) {
        const double phi = 360.0 * k / n;
        switch (kind % 6) {
            case 0:
                r[k] = ellipseRadius_mm(2 * a, 2 * b, phi - theta);
                break;
            case 1:
                r[k] = 107.95;
                break;  // gauge circle
            case 2:
                r[k] = ellipseRadius_mm(2 * a, 2 * b, phi - theta) + 5.0 * u(random);
                break;
            case 3:
                r[k] = k % (n / 2 > 0 ? n / 2 : 1) == 0 ? 200.0 : 1e-3;
                break;  // a slot: no ellipse
            case 4:
                r[k] = 0.0;
                break;  // zero area
            case 5:
                r[k] = 50.0 + 250.0 * u(random);
                break;  // anything
        }
    }
    return r;
}

}  // namespace

TEST(SectionBatchTest, EveryLaneIsSectionAnalyzerBitForBitWhateverTheVectorWidth) {
    for (const auto width :
         {SectionBatchAnalyzer::Width::Widest, SectionBatchAnalyzer::Width::FourLanes}) {
        std::mt19937 random(7);
        std::size_t sections = 0, unfitted = 0;
        for (int knots : {3, 4, 6, 24, 40}) {
            for (int samples : {3, 4, 5, 7, 48, 300}) {
                const SectionAnalyzer reference(knots, samples);
                const SectionBatchAnalyzer batch(knots, samples, width);
                SectionBatchAnalyzer::Workspace workspace(batch);
                std::vector<double> sampled(static_cast<std::size_t>(samples));
                for (int round = 0; round < 12; ++round) {
                    std::vector<std::vector<double>> lanes;
                    std::vector<double> interleaved(static_cast<std::size_t>(knots) * kLanes);
                    for (int l = 0; l < kLanes; ++l) {
                        lanes.push_back(pads(knots, round * kLanes + l, random));
                        for (int k = 0; k < knots; ++k)
                            interleaved[static_cast<std::size_t>(k * kLanes + l)] = lanes[l][k];
                    }
                    BatchShape shapes[kLanes];
                    batch.analyse(interleaved.data(), shapes, workspace);
                    for (int l = 0; l < kLanes; ++l) {
                        const SectionShape s = reference.analyse(lanes[l].data(), sampled.data());
                        const BatchShape& b = shapes[l];
                        SCOPED_TRACE(::testing::Message()
                                     << knots << " pads, " << samples << " samples, lane " << l);
                        EXPECT_EQ(b.area_mm2, s.area_mm2);
                        EXPECT_EQ(b.equivalentDiameter_mm, s.equivalentDiameter_mm);
                        EXPECT_EQ(b.centroidU_mm, s.centroidU_mm);
                        EXPECT_EQ(b.centroidV_mm, s.centroidV_mm);
                        EXPECT_EQ(b.centreOffset_mm, s.centreOffset_mm);
                        EXPECT_EQ(b.dmax_mm, s.dmax_mm);
                        EXPECT_EQ(b.dmin_mm, s.dmin_mm);
                        EXPECT_EQ(b.ellipticity, s.ellipticity);
                        EXPECT_EQ(b.ellipseFitted, s.ellipseFitted);
                        EXPECT_EQ(majorAngle_deg(b), s.majorAngle_deg);
                        // The direction is the angle's, as an axis (the cosines without
                        // trigonometry).
                        const double angle = glm::radians(s.majorAngle_deg);
                        EXPECT_NEAR(b.majorU * std::sin(angle) - b.majorV * std::cos(angle), 0.0,
                                    1e-12);
                        EXPECT_NEAR(std::hypot(b.majorU, b.majorV), 1.0, 1e-15);
                        EXPECT_GE(b.majorV, 0.0);
                        ++sections;
                        unfitted += s.ellipseFitted ? 0 : 1;
                    }
                }
            }
        }
        EXPECT_EQ(sections, 5u * 6u * 12u * kLanes);
        EXPECT_GT(unfitted, 100u);  // the second-moment fallback ran too
    }
}
