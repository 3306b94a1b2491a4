#include <algorithm>
#include <cstddef>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

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

TEST(LabelPlacementTest, ALineMeetsABoxItPassesThroughOrComesWithinTheGapOf) {
    const ScreenBox box{10, 10, 20, 20};
    EXPECT_TRUE(crosses({{0, 0}, {30, 30}}, box));    // through it, corner to corner
    EXPECT_TRUE(crosses({{15, 0}, {15, 12}}, box));   // into it and stops
    EXPECT_TRUE(crosses({{0, 10}, {30, 10}}, box));   // along its edge
    EXPECT_FALSE(crosses({{0, 25}, {30, 25}}, box));  // below it
    EXPECT_FALSE(crosses({{0, 25}, {30, 25}}, box, 4.0f));
    EXPECT_TRUE(crosses({{0, 25}, {30, 25}}, box, 5.0f));  // within a 5 px gap
    EXPECT_FALSE(crosses({{0, 0}, {9, 30}}, box));         // past its left edge
    EXPECT_FALSE(crosses({{22, 0}, {40, 19}}, box));       // past its upper right corner
    EXPECT_TRUE(crosses({{12, 12}, {12, 12}}, box));       // a point inside
}

TEST(LabelPlacementTest, TwoLinesCrossOnlyWhereTheyShareAPoint) {
    EXPECT_TRUE(crosses(ScreenSegment{{0, 0}, {10, 10}}, ScreenSegment{{0, 10}, {10, 0}}));
    EXPECT_FALSE(crosses(ScreenSegment{{0, 0}, {10, 0}}, ScreenSegment{{0, 1}, {10, 1}}));
    EXPECT_TRUE(crosses(ScreenSegment{{0, 0}, {10, 0}}, ScreenSegment{{5, 0}, {5, 8}}));  // a T
    EXPECT_FALSE(crosses(ScreenSegment{{0, 0}, {10, 0}}, ScreenSegment{{5, 1}, {5, 8}}));
    EXPECT_TRUE(crosses(ScreenSegment{{0, 0}, {10, 0}}, ScreenSegment{{8, 0}, {20, 0}}));
    EXPECT_FALSE(crosses(ScreenSegment{{0, 0}, {10, 0}}, ScreenSegment{{11, 0}, {20, 0}}));
    EXPECT_FALSE(crosses(ScreenSegment{{0, 0}, {10, 10}}, ScreenSegment{{6, 0}, {20, 0}}));
}

TEST(LabelPlacementTest, CalloutsGoOutwardFirstNearestFirstAndFaceTheirAnchor) {
    const glm::vec2 anchor(200.0f, 150.0f), size(40.0f, 10.0f);
    const std::vector<Callout> callouts =
        calloutCandidates(anchor, glm::vec2(3.0f, 0.0f), size, 20.0f, 60.0f, 10.0f);
    // 20, 28, ... 60 px: 6 distances, 14 rays at each.
    ASSERT_EQ(callouts.size(), 6u * 14u);
    // The first straight out (right): its left edge at the ray's end, centred on its height;
    // its leader along the ray from 10 px out.
    expectBox(callouts[0].box, 220, 145, 260, 155);
    EXPECT_FLOAT_EQ(callouts[0].leader.a.x, 210.0f);
    EXPECT_FLOAT_EQ(callouts[0].leader.b.x, 220.0f);
    EXPECT_FLOAT_EQ(callouts[0].leader.b.y, 150.0f);
    // Straight back (the 14th ray): right edge at the end.
    EXPECT_NEAR(callouts[13].box.x1, 180.0f, 1e-3f);
    float last = 0.0f;
    for (std::size_t i = 0; i < callouts.size(); ++i) {
        const Callout& c = callouts[i];
        const float reach = glm::length(c.leader.b - anchor);
        EXPECT_GE(reach, last - 1e-3f) << i;  // nearest first
        last = reach;
        EXPECT_NEAR(glm::length(c.leader.a - anchor), 10.0f, 1e-3f) << i;
        // The leader's end is the box's point nearest the anchor, on its edge.
        const glm::vec2 nearest(std::clamp(anchor.x, c.box.x0, c.box.x1),
                                std::clamp(anchor.y, c.box.y0, c.box.y1));
        EXPECT_LT(glm::length(nearest - c.leader.b), 1e-3f) << i;
        EXPECT_NEAR(c.box.width(), size.x, 1e-4f);
        EXPECT_NEAR(c.box.height(), size.y, 1e-4f);
    }
}

TEST(LabelPlacementTest, ALabelPlacedApartKeepsItsLeaderClearOfLabelsAndLeaders) {
    LabelLayout layout(kFrame, {}, 2.0f);
    const glm::vec2 anchor(300.0f, 200.0f), size(60.0f, 14.0f);
    // A label right of the anchor, where its first callouts would go.
    ASSERT_EQ(layout.place(std::vector<ScreenBox>{{310, 190, 370, 210}}), 0);
    const std::vector<Callout> callouts =
        calloutCandidates(anchor, glm::vec2(1.0f, 0.0f), size, 20.0f, 200.0f, 10.0f);
    const int k = layout.place(callouts);
    ASSERT_GE(k, 0);
    const Callout& taken = callouts[static_cast<std::size_t>(k)];
    EXPECT_FALSE(crosses(taken.leader, ScreenBox{310, 190, 370, 210}, 2.0f));
    EXPECT_FALSE(overlaps(taken.box, ScreenBox{310, 190, 370, 210}, 2.0f));
    // Every nearer callout was blocked by the label or its gap.
    for (int i = 0; i < k; ++i) {
        const Callout& c = callouts[static_cast<std::size_t>(i)];
        EXPECT_TRUE(crosses(c.leader, ScreenBox{310, 190, 370, 210}, 2.0f) ||
                    overlaps(c.box, ScreenBox{310, 190, 370, 210}, 2.0f) ||
                    !contains(kFrame, c.box))
            << i;
    }
    // A box on the leader is refused; one beside it is not.
    const glm::vec2 mid = (taken.leader.a + taken.leader.b) / 2.0f;
    EXPECT_EQ(layout.place(std::vector<ScreenBox>{{mid.x - 3, mid.y - 3, mid.x + 3, mid.y + 3}}),
              -1);
    // A second callout whose only way out would cross the first leader takes another.
    const std::vector<Callout> crossing{
        {{500, 10, 560, 24},
         {taken.leader.a - glm::vec2(0, 40), taken.leader.b + glm::vec2(0, 40)}},
        {{500, 400, 560, 414}, {{100, 400}, {120, 400}}}};
    ASSERT_TRUE(crosses(crossing[0].leader, taken.leader));  // both through its middle
    EXPECT_FALSE(crosses(crossing[0].leader, ScreenBox{310, 190, 370, 210}, 2.0f));
    EXPECT_EQ(layout.place(crossing), 1);
}

TEST(LabelPlacementTest, RandomCalloutsNeverCrossALabelOrAnotherLeader) {
    std::mt19937 random(20261129u);
    std::uniform_real_distribution<float> x(40.0f, 600.0f), y(40.0f, 440.0f);
    for (int trial = 0; trial < 50; ++trial) {
        LabelLayout layout(kFrame, {{0, 380, 120, 480}}, 2.0f);
        std::vector<ScreenBox> boxes{{0, 380, 120, 480}};
        std::vector<ScreenSegment> leaders;
        for (int i = 0; i < 30; ++i) {
            const glm::vec2 anchor(x(random), y(random));
            const std::vector<Callout> callouts =
                calloutCandidates(anchor, anchor - glm::vec2(320, 240), {50, 14}, 20, 150, 10);
            const int k = layout.place(callouts);
            if (k < 0) continue;
            const Callout& c = callouts[static_cast<std::size_t>(k)];
            for (const ScreenBox& box : boxes) {
                EXPECT_FALSE(overlaps(c.box, box, 2.0f)) << trial << " " << i;
                EXPECT_FALSE(crosses(c.leader, box, 2.0f)) << trial << " " << i;
            }
            for (const ScreenSegment& leader : leaders) {
                EXPECT_FALSE(crosses(c.leader, leader)) << trial << " " << i;
                EXPECT_FALSE(crosses(leader, c.box, 2.0f)) << trial << " " << i;
            }
            boxes.push_back(c.box);
            leaders.push_back(c.leader);
        }
        EXPECT_GT(leaders.size(), 5u) << trial;
    }
}

}  // namespace
}  // namespace caliper3d::scenegraph
