#pragma once

#include <vector>

#include <glm/vec2.hpp>

namespace caliper3d::scenegraph {

// Where the labels of a picture go (docs/architecture.md, "Annotations"): plain boxes in
// pixels, no Coin, so the rule is tested on its own.

// A box on the picture, in pixels from its top-left corner (x right, y down).
struct ScreenBox {
    float x0 = 0.0f;
    float y0 = 0.0f;
    float x1 = 0.0f;
    float y1 = 0.0f;
    float width() const { return x1 - x0; }
    float height() const { return y1 - y0; }
};

// Whether `a` and `b` come closer than `gap_px` (0: whether they share any area; boxes that
// only touch do not overlap).
bool overlaps(const ScreenBox& a, const ScreenBox& b, float gap_px = 0.0f);
// Whether `inner` lies wholly inside `outer`.
bool contains(const ScreenBox& outer, const ScreenBox& inner);

// The places around an anchor a label may take, as a cartographer orders them: beside it on
// the right (reading on from the anchor), on the left, above, below, then the corners.
enum class LabelSide { Right, Left, Above, Below, AboveRight, BelowRight, AboveLeft, BelowLeft };
constexpr LabelSide kLabelSides[] = {
    LabelSide::Right,      LabelSide::Left,       LabelSide::Above,     LabelSide::Below,
    LabelSide::AboveRight, LabelSide::BelowRight, LabelSide::AboveLeft, LabelSide::BelowLeft};

// The box of a label `size` pixels across and high on `side` of `anchor`, `clearance_px`
// from it: Right has its left edge clearance_px right of the anchor, centred on its height;
// Above has its bottom edge clearance_px above it, centred across; AboveRight has both its
// bottom edge above and its left edge right of the anchor by clearance_px; and so on.
ScreenBox boxBeside(glm::vec2 anchor, glm::vec2 size, LabelSide side, float clearance_px);

// What the greedy placement is given.
struct LabelLayoutRequest {
    // Per label, most important first: the boxes it may take, in order of preference.
    std::vector<std::vector<ScreenBox>> candidates;
    ScreenBox frame;                   // the picture: a label lies wholly inside it
    std::vector<ScreenBox> obstacles;  // what is already drawn there (the overlay, a legend)
    float gap_px = 2.0f;               // kept clear between any two labels, and obstacles
};

// Places labels one at a time in the order given: each takes the first of its candidate
// boxes that lies inside the frame and keeps gap_px clear of every obstacle and of every box
// taken before; a label none of whose boxes does is left out. Returns, per label, the index
// of the box taken, or -1. Deterministic (the same request, the same answer), and no two
// boxes taken come within gap_px of each other.
std::vector<int> placeLabels(const LabelLayoutRequest& request);

}  // namespace caliper3d::scenegraph
