#include <cstddef>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "scenegraph/label_placement.h"

namespace caliper3d::scenegraph {
namespace {

constexpr ScreenBox kFrame{0.0f, 0.0f, 640.0f, 480.0f};

void expectBox(const ScreenBox& box, float x0, float y0, float x1, float y1) {
    EXPECT_FLOAT_EQ(box.x0, x0);
    EXPECT_FLOAT_EQ(box.y0, y0);
    EXPECT_FLOAT_EQ(box.x1, x1);
    EXPECT_FLOAT_EQ(box.y1, y1);
}

TEST(LabelPlacementTest, BoxesBesideAnAnchorStandClearOfItOnEachSide) {
    const glm::vec2 anchor(100.0f, 50.0f), size(40.0f, 10.0f);
    expectBox(boxBeside(anchor, size, LabelSide::Right, 5.0f), 105, 45, 145, 55);
    expectBox(boxBeside(anchor, size, LabelSide::Left, 5.0f), 55, 45, 95, 55);
    expectBox(boxBeside(anchor, size, LabelSide::Above, 5.0f), 80, 35, 120, 45);
    expectBox(boxBeside(anchor, size, LabelSide::Below, 5.0f), 80, 55, 120, 65);
    expectBox(boxBeside(anchor, size, LabelSide::AboveRight, 5.0f), 105, 35, 145, 45);
    expectBox(boxBeside(anchor, size, LabelSide::BelowLeft, 5.0f), 55, 55, 95, 65);
    // No side's box covers the anchor's surroundings within the clearance.
    const ScreenBox around{95.0f, 45.0f, 105.0f, 55.0f};
    for (const LabelSide side : kLabelSides)
        EXPECT_FALSE(overlaps(boxBeside(anchor, size, side, 5.0f), around));
}

TEST(LabelPlacementTest, BoxesThatOnlyTouchDoNotOverlapUnlessAGapIsKept) {
    const ScreenBox a{0, 0, 10, 10}, b{10, 0, 20, 10}, c{5, 5, 15, 15};
    EXPECT_FALSE(overlaps(a, b));
    EXPECT_TRUE(overlaps(a, b, 1.0f));
    EXPECT_TRUE(overlaps(a, c));
    EXPECT_TRUE(overlaps(c, a));
    EXPECT_TRUE(contains(kFrame, a));
    EXPECT_FALSE(contains(kFrame, ScreenBox{630, 0, 650, 10}));
}

TEST(LabelPlacementTest, AnEarlierLabelKeepsItsPlaceAndALaterOneMovesToItsNextCandidate) {
    LabelLayoutRequest request;
    request.frame = kFrame;
    request.gap_px = 0.0f;
    const ScreenBox right{100, 100, 150, 110}, left{30, 100, 80, 110};
    request.candidates = {{right}, {right, left}, {right, left}};
    const std::vector<int> chosen = placeLabels(request);
    ASSERT_EQ(chosen.size(), 3u);
    EXPECT_EQ(chosen[0], 0);   // first come, first placed
    EXPECT_EQ(chosen[1], 1);   // its first choice taken: its second
    EXPECT_EQ(chosen[2], -1);  // nowhere left: left out
}

TEST(LabelPlacementTest, LabelsStayInsideThePictureAndOffObstacles) {
    LabelLayoutRequest request;
    request.frame = kFrame;
    request.obstacles = {{0, 360, 130, 480}};  // an overlay in the bottom-left corner
    request.gap_px = 2.0f;
    request.candidates = {
        {{620, 10, 660, 20}, {560, 10, 600, 20}},  // off the right edge, then inside
        {{10, 400, 60, 410}, {10, 345, 60, 357}},  // on the overlay, then 3 px above it
        {{70, 350, 110, 359}},                     // within the gap of the overlay
    };
    const std::vector<int> chosen = placeLabels(request);
    EXPECT_EQ(chosen, (std::vector<int>{1, 1, -1}));
}

TEST(LabelPlacementTest, RandomLabelsNeverOverlapAndOnlyBlockedOnesAreLeftOut) {
    std::mt19937 random(20261124u);
    std::uniform_real_distribution<float> x(-40.0f, 680.0f), y(-20.0f, 500.0f);
    std::uniform_real_distribution<float> width(20.0f, 120.0f), height(10.0f, 18.0f);
    std::uniform_real_distribution<float> gap(0.0f, 4.0f);
    for (int trial = 0; trial < 200; ++trial) {
        LabelLayoutRequest request;
        request.frame = kFrame;
        request.gap_px = gap(random);
        request.obstacles = {{0, 380, 120, 480}};
        const int labels = 5 + trial % 60;
        for (int i = 0; i < labels; ++i) {
            const glm::vec2 anchor(x(random), y(random)), size(width(random), height(random));
            std::vector<ScreenBox> boxes;
            for (const LabelSide side : kLabelSides)
                boxes.push_back(boxBeside(anchor, size, side, 4.0f));
            request.candidates.push_back(boxes);
        }
        const std::vector<int> chosen = placeLabels(request);
        ASSERT_EQ(chosen.size(), request.candidates.size());
        EXPECT_EQ(placeLabels(request), chosen) << "trial " << trial;  // deterministic
        std::vector<ScreenBox> taken;
        std::size_t placed = 0;
        for (std::size_t i = 0; i < chosen.size(); ++i) {
            if (chosen[i] < 0) continue;
            const ScreenBox& box = request.candidates[i][static_cast<std::size_t>(chosen[i])];
            EXPECT_TRUE(contains(kFrame, box)) << "trial " << trial << " label " << i;
            EXPECT_FALSE(overlaps(box, request.obstacles[0], request.gap_px));
            for (const ScreenBox& other : taken)
                EXPECT_FALSE(overlaps(box, other, request.gap_px))
                    << "trial " << trial << " label " << i;
            taken.push_back(box);
            ++placed;
        }
        EXPECT_GT(placed, 0u) << "trial " << trial;
        // A label left out had no free candidate: each is outside the picture or meets a box
        // taken (or the obstacle).
        for (std::size_t i = 0; i < chosen.size(); ++i) {
            if (chosen[i] >= 0) continue;
            for (const ScreenBox& box : request.candidates[i]) {
                bool blocked =
                    !contains(kFrame, box) || overlaps(box, request.obstacles[0], request.gap_px);
                for (const ScreenBox& other : taken)
                    blocked = blocked || overlaps(box, other, request.gap_px);
                EXPECT_TRUE(blocked) << "trial " << trial << " label " << i;
            }
        }
    }
}

}  // namespace
}  // namespace caliper3d::scenegraph
