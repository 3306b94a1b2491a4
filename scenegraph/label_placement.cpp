#include "scenegraph/label_placement.h"

#include <cstddef>

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
    std::vector<ScreenBox> taken = request.obstacles;
    taken.reserve(taken.size() + request.candidates.size());
    for (std::size_t label = 0; label < request.candidates.size(); ++label) {
        const std::vector<ScreenBox>& boxes = request.candidates[label];
        for (std::size_t k = 0; k < boxes.size(); ++k) {
            const ScreenBox& box = boxes[k];
            if (!contains(request.frame, box)) continue;
            bool free = true;
            for (const ScreenBox& other : taken)
                if (overlaps(box, other, request.gap_px)) {
                    free = false;
                    break;
                }
            if (!free) continue;
            chosen[label] = static_cast<int>(k);
            taken.push_back(box);
            break;
        }
    }
    return chosen;
}

}  // namespace caliper3d::scenegraph
