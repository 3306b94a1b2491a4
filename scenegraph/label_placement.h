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

// A straight line on the picture, in pixels: a label's leader to the point it names.
struct ScreenSegment {
    glm::vec2 a{0.0f};
    glm::vec2 b{0.0f};
};

// Whether `line` comes within `gap_px` of `box` (0: whether it meets it, an edge included).
bool crosses(const ScreenSegment& line, const ScreenBox& box, float gap_px = 0.0f);
// Whether two lines share a point.
bool crosses(const ScreenSegment& s, const ScreenSegment& t);

// A label placed apart from its anchor when every place beside it is taken: its box, and the
// leader drawn from near the anchor to the box's nearest point.
struct Callout {
    ScreenBox box;
    ScreenSegment leader;
};

// The places apart from `anchor` a label `size` pixels across and high may take, nearest
// first: at distances from `from_px` to `to_px` (every 8 px) along the ray from the anchor
// towards `outward` and the rays turned from it by 20, 40, 60, 90, 120, 150 and 180 degrees
// either way, in that order at each distance. The ray ends on the box's edge that faces the
// anchor (its left edge for a ray pointing right, its top for one pointing down, a corner
// between them); the leader runs along the ray from `leaderFrom_px` out to that end. With a
// zero `outward` the rays turn from the right.
std::vector<Callout> calloutCandidates(glm::vec2 anchor, glm::vec2 outward, glm::vec2 size,
                                       float from_px, float to_px, float leaderFrom_px);

// The picture's labels placed one at a time, most important first (what placeLabels does
// for one request, here in stages: a caller can offer a label further places once the labels
// that come before it have taken theirs). A box is free when it lies inside the frame and
// keeps `gap_px` clear of every obstacle, every box taken and every leader drawn; a callout
// when its box is free and its leader keeps `gap_px` clear of every box taken (obstacles
// included) and meets no leader drawn.
class LabelLayout {
public:
    LabelLayout(const ScreenBox& frame, std::vector<ScreenBox> obstacles, float gap_px);
    // Takes the first free box of `boxes` and returns its index; -1 when none is free.
    int place(const std::vector<ScreenBox>& boxes);
    // Takes the first free callout of `callouts` (box and leader) and returns its index; -1
    // when none is free.
    int place(const std::vector<Callout>& callouts);

private:
    bool free(const ScreenBox& box) const;
    bool free(const ScreenSegment& leader) const;

    ScreenBox m_frame;
    std::vector<ScreenBox> m_taken;  // the obstacles, then every box taken
    std::vector<ScreenSegment> m_leaders;
    float m_gap_px;
};

}  // namespace caliper3d::scenegraph
