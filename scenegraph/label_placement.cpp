#include "scenegraph/label_placement.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>

namespace caliper3d::scenegraph {

bool overlaps(const ScreenBox& a, const ScreenBox& b, float gap_px) {
    return a.x0 < b.x1 + gap_px && b.x0 < a.x1 + gap_px && a.y0 < b.y1 + gap_px &&
           b.y0 < a.y1 + gap_px;
}

bool contains(const ScreenBox& outer, const ScreenBox& inner) {
    return inner.x0 >= outer.x0 && inner.x1 <= outer.x1 && inner.y0 >= outer.y0 &&
           inner.y1 <= outer.y1;
}

ScreenBox boxBeside(glm::vec2 anchor, glm::vec2 size, LabelSide side, float clearance_px) {
    // The box's left edge and top edge for each side, from the anchor.
    float left = anchor.x - size.x / 2.0f;  // centred across
    float top = anchor.y - size.y / 2.0f;   // centred on its height
    const float rightOf = anchor.x + clearance_px, leftOf = anchor.x - clearance_px - size.x;
    const float above = anchor.y - clearance_px - size.y, below = anchor.y + clearance_px;
    switch (side) {
        case LabelSide::Right:
            left = rightOf;
            break;
        case LabelSide::Left:
            left = leftOf;
            break;
        case LabelSide::Above:
            top = above;
            break;
        case LabelSide::Below:
            top = below;
            break;
        case LabelSide::AboveRight:
            left = rightOf, top = above;
            break;
        case LabelSide::BelowRight:
            left = rightOf, top = below;
            break;
        case LabelSide::AboveLeft:
            left = leftOf, top = above;
            break;
        case LabelSide::BelowLeft:
            left = leftOf, top = below;
            break;
    }
    return {left, top, left + size.x, top + size.y};
}

std::vector<int> placeLabels(const LabelLayoutRequest& request) {
    std::vector<int> chosen(request.candidates.size(), -1);
    LabelLayout layout(request.frame, request.obstacles, request.gap_px);
    for (std::size_t label = 0; label < request.candidates.size(); ++label)
        chosen[label] = layout.place(request.candidates[label]);
    return chosen;
}

bool crosses(const ScreenSegment& line, const ScreenBox& box, float gap_px) {
    // Liang-Barsky: the part of the line inside the grown box, as a range of its parameter.
    const float lo[2] = {box.x0 - gap_px, box.y0 - gap_px};
    const float hi[2] = {box.x1 + gap_px, box.y1 + gap_px};
    const glm::vec2 d = line.b - line.a;
    float enter = 0.0f, leave = 1.0f;
    for (int axis = 0; axis < 2; ++axis) {
        const float start = line.a[axis], step = d[axis];
        if (step == 0.0f) {
            if (start < lo[axis] || start > hi[axis]) return false;
            continue;
        }
        float t0 = (lo[axis] - start) / step, t1 = (hi[axis] - start) / step;
        if (t0 > t1) std::swap(t0, t1);
        enter = std::max(enter, t0);
        leave = std::min(leave, t1);
        if (enter > leave) return false;
    }
    return true;
}

namespace {

// Twice the signed area of the triangle a, b, c: which side of a->b the point c lies on.
float turn(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Whether c, on the line through a and b, lies between them.
bool within(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
    return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
           c.y <= std::max(a.y, b.y);
}

}  // namespace

bool crosses(const ScreenSegment& s, const ScreenSegment& t) {
    const float d1 = turn(t.a, t.b, s.a), d2 = turn(t.a, t.b, s.b);
    const float d3 = turn(s.a, s.b, t.a), d4 = turn(s.a, s.b, t.b);
    if (((d1 > 0.0f && d2 < 0.0f) || (d1 < 0.0f && d2 > 0.0f)) &&
        ((d3 > 0.0f && d4 < 0.0f) || (d3 < 0.0f && d4 > 0.0f)))
        return true;
    return (d1 == 0.0f && within(t.a, t.b, s.a)) || (d2 == 0.0f && within(t.a, t.b, s.b)) ||
           (d3 == 0.0f && within(s.a, s.b, t.a)) || (d4 == 0.0f && within(s.a, s.b, t.b));
}

std::vector<Callout> calloutCandidates(glm::vec2 anchor, glm::vec2 outward, glm::vec2 size,
                                       float from_px, float to_px, float leaderFrom_px) {
    constexpr float kStep_px = 8.0f;
    constexpr float kTurns_deg[] = {0,  20,  -20, 40,   -40, 60,   -60,
                                    90, -90, 120, -120, 150, -150, 180};
    constexpr float kDegree = 3.14159265358979f / 180.0f;
    const float length = std::hypot(outward.x, outward.y);
    const float base = length > 0.0f ? std::atan2(outward.y, outward.x) : 0.0f;
    std::vector<Callout> out;
    for (float reach = from_px; reach <= to_px; reach += kStep_px)
        for (const float turnBy : kTurns_deg) {
            const float angle = base + turnBy * kDegree;
            const glm::vec2 ray(std::cos(angle), std::sin(angle));
            const glm::vec2 end = anchor + ray * reach;
            // The edge that faces the anchor: a ray mostly across puts the box beside its end,
            // one mostly up or down above or below it, one between at a corner.
            float left = end.x - size.x / 2.0f, top = end.y - size.y / 2.0f;
            if (ray.x > 0.25f) left = end.x;
            if (ray.x < -0.25f) left = end.x - size.x;
            if (ray.y > 0.25f) top = end.y;
            if (ray.y < -0.25f) top = end.y - size.y;
            const ScreenBox box{left, top, left + size.x, top + size.y};
            out.push_back({box, {anchor + ray * std::min(leaderFrom_px, reach), end}});
        }
    return out;
}

LabelLayout::LabelLayout(const ScreenBox& frame, std::vector<ScreenBox> obstacles, float gap_px)
    : m_frame(frame), m_taken(std::move(obstacles)), m_gap_px(gap_px) {}

bool LabelLayout::free(const ScreenBox& box) const {
    if (!contains(m_frame, box)) return false;
    for (const ScreenBox& other : m_taken)
        if (overlaps(box, other, m_gap_px)) return false;
    for (const ScreenSegment& leader : m_leaders)
        if (crosses(leader, box, m_gap_px)) return false;
    return true;
}

bool LabelLayout::free(const ScreenSegment& leader) const {
    for (const ScreenBox& other : m_taken)
        if (crosses(leader, other, m_gap_px)) return false;
    for (const ScreenSegment& other : m_leaders)
        if (crosses(leader, other)) return false;
    return true;
}

int LabelLayout::place(const std::vector<ScreenBox>& boxes) {
    for (std::size_t k = 0; k < boxes.size(); ++k)
        if (free(boxes[k])) {
            m_taken.push_back(boxes[k]);
            return static_cast<int>(k);
        }
    return -1;
}

int LabelLayout::place(const std::vector<Callout>& callouts) {
    for (std::size_t k = 0; k < callouts.size(); ++k)
        if (free(callouts[k].box) && free(callouts[k].leader)) {
            m_taken.push_back(callouts[k].box);
            m_leaders.push_back(callouts[k].leader);
            return static_cast<int>(k);
        }
    return -1;
}

}  // namespace caliper3d::scenegraph
