#include "scenegraph/well_annotations.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <Inventor/SbViewVolume.h>
#include <Inventor/SbViewportRegion.h>
#include <Inventor/nodes/SoAnnotation.h>
#include <Inventor/nodes/SoBaseColor.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoDrawStyle.h>
#include <Inventor/nodes/SoFont.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoLineSet.h>
#include <Inventor/nodes/SoMarkerSet.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoText2.h>
#include <Inventor/nodes/SoTranslation.h>

#include <glm/geometric.hpp>

#include "reconstruction/section/section_frame.h"
#include "reconstruction/well_path.h"
#include "scenegraph/camera_setup.h"
#include "scenegraph/drawn_only.h"
#include "scenegraph/label_style.h"
#include "scenegraph/main_thread.h"
#include "scenegraph/picture_scale.h"

namespace caliper3d::scenegraph {

namespace {

// A tick mark stands this much of the annotated length clear of the drawn wall.
constexpr double kTickLength = 0.025;
// A name keeps this far clear of its well's top (the wellhead marker is 9 px across).
constexpr float kNameClearance_px = 8.0f;

struct Span {
    double top = 0.0;
    double bottom = 0.0;
    double spacing = 1.0;
};

Span annotatedSpan(const reconstruction::WellGeometry& geometry, const AnnotationView& view) {
    Span s;
    const double last = geometry.table().depth_m.back();
    s.top = std::clamp(view.top_m, 0.0, last);
    s.bottom = std::clamp(view.bottom_m, s.top, last);
    s.spacing = view.tickSpacing_m > 0.0 ? view.tickSpacing_m : tickSpacing_m(s.bottom - s.top);
    return s;
}

glm::vec3 toScene(const reconstruction::Ned& v) {
    return glm::vec3(reconstruction::toScene(v));
}

// Across the path and the view, on the picture's right (or its top, for a path that runs
// left-right); the picture's right where the path runs along the view.
glm::vec3 sideOf(const reconstruction::PathSample& at, const AnnotationView& view) {
    const glm::vec3 tangent = toScene(reconstruction::holeTangent(at.inc_deg, at.azi_deg));
    glm::vec3 side = glm::cross(tangent, view.look);
    if (glm::length(side) < 0.05f) return view.right;
    side = glm::normalize(side);
    const float along = glm::dot(side, view.right);
    const glm::vec3 up = glm::cross(view.right, view.look);
    if (along < 0.0f || (std::abs(along) < 1e-3f && glm::dot(side, up) < 0.0f)) side = -side;
    return side;
}

// `radius`: the span's typical radius (typicalRadius_m), NaN for none.
double standOffOf(double radius, const AnnotationView& view, const Span& span) {
    if (!view.tickMarks) return 0.0;
    if (!std::isfinite(radius)) radius = 0.0;
    return radius * view.radialExaggeration + kTickLength * (span.bottom - span.top);
}

// A label whose text starts at `at`; when the view says how large a pixel is there, centred
// on the height of `at` and outlined in the background colour.
SoSeparator* labelNode(const glm::vec3& at, const std::string& text, const AnnotationView& view,
                       const float colour[3], float size_px) {
    auto* group = new SoSeparator;
    const glm::vec3 up = glm::cross(view.right, view.look);
    const float pixel = view.pixelSize ? view.pixelSize(at) : 0.0f;
    // SoText2 stands on its point: down by half the height of digits and capitals.
    const glm::vec3 anchor = at - up * (pixel * kCapHeight_em * size_px / 2.0f);
    auto* move = new SoTranslation;
    move->translation.setValue(anchor.x, anchor.y, anchor.z);
    group->addChild(move);
    auto* label = new SoText2;
    // A space keeps the text clear of the tick mark's end.
    label->string.setValue((" " + text).c_str());
    if (view.pixelSize) {
        auto* dark = new SoBaseColor;
        dark->rgb.setValue(kBackgroundColour);
        group->addChild(dark);
        for (const glm::vec2 d :
             {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(-1, 1), glm::vec2(1, 1)}) {
            auto* halo = new SoSeparator;
            auto* shift = new SoTranslation;
            const glm::vec3 offset = (view.right * d.x + up * d.y) * pixel;
            shift->translation.setValue(offset.x, offset.y, offset.z);
            auto* copy = new SoText2;
            copy->string = label->string;
            halo->addChild(shift);
            halo->addChild(copy);
            group->addChild(halo);
        }
    }
    auto* rgb = new SoBaseColor;
    rgb->rgb.setValue(colour);
    group->addChild(rgb);
    group->addChild(label);
    return group;
}

}  // namespace

AnnotationView pictureAnnotationView(const SoCamera& camera, int width, int height, double top_m,
                                     double bottom_m) {
    AnnotationView view;
    view.top_m = top_m;
    view.bottom_m = bottom_m;
    view.width_px = width;
    view.height_px = height;
    const SbRotation orientation = camera.orientation.getValue();
    SbVec3f look, right;
    orientation.multVec(SbVec3f(0.0f, 0.0f, -1.0f), look);
    orientation.multVec(SbVec3f(1.0f, 0.0f, 0.0f), right);
    view.look = glm::vec3(look[0], look[1], look[2]);
    view.right = glm::vec3(right[0], right[1], right[2]);
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const SbViewVolume volume = shownViewVolume(camera, aspect);
    const SbVec3f eye = camera.position.getValue();
    const float nearest = camera.nearDistance.getValue();
    const glm::vec3 eyeAt(eye[0], eye[1], eye[2]), lookAlong = view.look;
    const float heightAngle =
        camera.isOfType(SoPerspectiveCamera::getClassTypeId())
            ? static_cast<const SoPerspectiveCamera&>(camera).heightAngle.getValue()
            : 0.0f;
    if (heightAngle > 0.0f)
        view.pixelSize = [eyeAt, lookAlong, heightAngle, aspect, height](const glm::vec3& p) {
            // A tall picture's volume is widened (above): its height spans more.
            const float spanned = 2.0f * std::max(glm::dot(p - eyeAt, lookAlong), 0.0f) *
                                  std::tan(heightAngle / 2.0f) / std::min(aspect, 1.0f);
            return spanned / static_cast<float>(height);
        };
    view.toPixels = [volume, eyeAt, lookAlong, nearest, width,
                     height](const glm::vec3& p) -> std::optional<glm::vec2> {
        if (glm::dot(p - eyeAt, lookAlong) <= nearest) return std::nullopt;
        SbVec3f screen;
        volume.projectToScreen(SbVec3f(p.x, p.y, p.z), screen);
        return glm::vec2(screen[0] * static_cast<float>(width),
                         (1.0f - screen[1]) * static_cast<float>(height));
    };
    return view;
}

std::string depthLabel(double md_m, double spacing_m) {
    int decimals = 0;
    while (decimals < 3 && std::abs(spacing_m * std::pow(10.0, decimals) -
                                    std::round(spacing_m * std::pow(10.0, decimals))) > 1e-6)
        ++decimals;
    char text[48];
    std::snprintf(text, sizeof text, "%.*f m", decimals, md_m);
    return text;
}

std::string wellLabel(const io::SectionTable& table) {
    const std::string& name = table.wellName;
    const auto first = name.find_first_not_of(" \t");
    if (first != std::string::npos)
        return name.substr(first, name.find_last_not_of(" \t") - first + 1);
    return std::filesystem::path(table.source).filename().string();
}

WellLabels wellLabels(const reconstruction::WellGeometry& geometry, const AnnotationView& view) {
    WellLabels labels;
    if (geometry.table().rowCount() == 0) return labels;
    const Span span = annotatedSpan(geometry, view);
    const double radius = view.tickMarks ? typicalRadius_m(geometry, span.top, span.bottom) : 0.0;
    const double standOff = standOffOf(radius, view, span);
    if (view.tickMarks) {
        const reconstruction::PathSample top = reconstruction::pathAt(geometry, span.top);
        WellName name;
        name.text = wellLabel(geometry.table());
        name.position = toScene(top.position);
        name.labelAt = name.position + sideOf(top, view) * static_cast<float>(standOff);
        name.wellhead = span.top <= 0.0;
        name.drawnRadius_m =
            std::isfinite(radius) ? static_cast<float>(radius * view.radialExaggeration) : 0.0f;
        labels.name = name;
    }
    if (!view.depthTicks) return labels;
    const auto firstTick = static_cast<long long>(std::ceil(span.top / span.spacing - 1e-9));
    const auto lastTick = static_cast<long long>(std::floor(span.bottom / span.spacing + 1e-9));
    for (long long k = std::max(firstTick, 1LL); k <= lastTick; ++k) {
        DepthTick tick;
        tick.md_m = static_cast<double>(k) * span.spacing;
        const reconstruction::PathSample at = reconstruction::pathAt(geometry, tick.md_m);
        tick.position = toScene(at.position);
        tick.end = tick.position + sideOf(at, view) * static_cast<float>(standOff);
        tick.label = depthLabel(tick.md_m, span.spacing);
        tick.labelAt = tick.end;
        labels.ticks.push_back(std::move(tick));
    }
    return labels;
}

namespace {

// One label to place: the scene point its candidates are measured from, and where its text
// starts (left end, middle of the capitals) for each candidate box, in pixels.
struct LabelToPlace {
    const AnnotationView* view = nullptr;
    std::string* text = nullptr;  // cleared when left out
    glm::vec3* labelAt = nullptr;
    glm::vec3 anchor{0.0f};
    glm::vec2 anchorPixel{0.0f};
    std::vector<ScreenBox> boxes{};
    std::vector<glm::vec2> starts{};
};

// The box of `text` (as drawn: after a space) whose capitals' middle starts at `start`.
ScreenBox boxFrom(glm::vec2 start, const std::string& text, float size_px) {
    return labelBox(start + glm::vec2(0.0f, kCapHeight_em * size_px / 2.0f), " " + text, size_px);
}

// Adds the candidate whose box is `box` to `label`.
void addCandidate(LabelToPlace& label, const ScreenBox& box, const std::string& text,
                  float size_px) {
    const ScreenBox at0 = boxFrom(glm::vec2(0.0f), text, size_px);
    label.boxes.push_back(box);
    label.starts.emplace_back(box.x0 - at0.x0, box.y0 - at0.y0);
}

// A well's name to place, the name itself, and how far from its top it keeps (pixels; 0: a
// name not to be moved).
struct NameToPlace {
    LabelToPlace label;
    WellName* name = nullptr;
    float clearance_px = 0.0f;
    std::vector<Callout> apart{};  // where it may go apart from its well, nearest first
};

// Each well's name with its places beside the top of its well.
std::vector<NameToPlace> namesToPlace(std::vector<WellLabels>& wells,
                                      const std::vector<AnnotationView>& views) {
    std::vector<NameToPlace> names;
    for (std::size_t w = 0; w < wells.size(); ++w) {
        if (!wells[w].name) continue;
        WellName& name = *wells[w].name;
        const AnnotationView& view = views[w];
        NameToPlace place{{&view, &name.text, &name.labelAt, name.position}, &name};
        LabelToPlace& label = place.label;
        const std::optional<glm::vec2> head = view.toPixels(name.position);
        const std::optional<glm::vec2> start = view.toPixels(name.labelAt);
        if (head && start && !view.pixelSize) {
            // Not to be moved: where it first went, or nowhere.
            label.anchorPixel = *head;
            addCandidate(label, boxFrom(*start, name.text, kNameSize_px), name.text, kNameSize_px);
        } else if (head) {
            // Beside the top, clear of the tube drawn there (seen end on in a map).
            label.anchorPixel = *head;
            const float pixel = view.pixelSize(name.position);
            const float radius_px = pixel > 0.0f ? name.drawnRadius_m / pixel : 0.0f;
            place.clearance_px = std::max(kNameClearance_px, radius_px + 4.0f);
            const ScreenBox box = boxFrom(glm::vec2(0.0f), name.text, kNameSize_px);
            const glm::vec2 size(box.width(), box.height());
            for (const LabelSide side : kLabelSides)
                addCandidate(label, boxBeside(*head, size, side, place.clearance_px), name.text,
                             kNameSize_px);
        }
        names.push_back(std::move(place));
    }
    return names;
}

// Where each name that may move can go apart from its well: out from the middle of the wells'
// tops (so the leaders of a crowded field fan out rather than cross), up to `reach_px` away.
void addPlacesApart(std::vector<NameToPlace>& names, float reach_px) {
    glm::vec2 middle(0.0f);
    int movable = 0;
    for (const NameToPlace& name : names)
        if (name.clearance_px > 0.0f) middle += name.label.anchorPixel, ++movable;
    if (movable == 0 || reach_px <= 0.0f) return;
    middle /= static_cast<float>(movable);
    for (NameToPlace& name : names) {
        if (name.clearance_px <= 0.0f) continue;
        const ScreenBox at0 = boxFrom(glm::vec2(0.0f), name.name->text, kNameSize_px);
        name.apart =
            calloutCandidates(name.label.anchorPixel, name.label.anchorPixel - middle,
                              glm::vec2(at0.width(), at0.height()), name.clearance_px + 12.0f,
                              reach_px, std::max(name.clearance_px, 10.0f));
    }
}

// The names placed in one layout: each name's box beside its well or callout apart from it
// (-1: none).
struct NameRound {
    LabelLayout layout;
    std::vector<int> beside;
    std::vector<int> apart;
    std::size_t placed = 0;
};

// Every name beside its well where there is room, then the rest apart; the names marked in
// `apartFirst` apart before any other.
NameRound placeNames(const LabelLayout& empty, const std::vector<NameToPlace>& names,
                     const std::vector<char>& apartFirst) {
    NameRound r{empty, std::vector<int>(names.size(), -1), std::vector<int>(names.size(), -1)};
    for (std::size_t i = 0; i < names.size(); ++i)
        if (apartFirst[i]) r.apart[i] = r.layout.place(names[i].apart);
    for (std::size_t i = 0; i < names.size(); ++i)
        if (!apartFirst[i]) r.beside[i] = r.layout.place(names[i].label.boxes);
    for (std::size_t i = 0; i < names.size(); ++i)
        if (!apartFirst[i] && r.beside[i] < 0) r.apart[i] = r.layout.place(names[i].apart);
    for (std::size_t i = 0; i < names.size(); ++i)
        r.placed += r.beside[i] >= 0 || r.apart[i] >= 0 ? 1 : 0;
    return r;
}

// A name enclosed by its neighbours' names (a pad of wells seen from above) has no way out for
// its leader, so the names left out go first in the next round, apart from the start; the round
// that places the most names is kept (the first of equals: deterministic).
NameRound placeNamesInRounds(const LabelLayout& empty, const std::vector<NameToPlace>& names) {
    std::vector<char> apartFirst(names.size(), 0);
    NameRound best = placeNames(empty, names, apartFirst);
    for (int again = 0; again < 3 && best.placed < names.size(); ++again) {
        bool grew = false;
        for (std::size_t i = 0; i < names.size(); ++i)
            if (best.beside[i] < 0 && best.apart[i] < 0 && !names[i].apart.empty() &&
                !apartFirst[i])
                apartFirst[i] = 1, grew = true;
        if (!grew) break;
        NameRound next = placeNames(empty, names, apartFirst);
        if (next.placed > best.placed) best = std::move(next);
    }
    return best;
}

// A name placed apart: where its text starts and its leader, across the view at its well's
// top's distance from the eye (as a moved label is).
void setApart(const NameToPlace& place, const Callout& callout) {
    const LabelToPlace& label = place.label;
    const AnnotationView& view = *label.view;
    const ScreenBox at0 = boxFrom(glm::vec2(0.0f), place.name->text, kNameSize_px);
    const glm::vec3 up = glm::cross(view.right, view.look);
    const float pixel = view.pixelSize(label.anchor);
    const auto toScene = [&](glm::vec2 at) {
        const glm::vec2 shift = at - label.anchorPixel;
        return label.anchor + (view.right * shift.x - up * shift.y) * pixel;
    };
    place.name->labelAt = toScene(glm::vec2(callout.box.x0 - at0.x0, callout.box.y0 - at0.y0));
    place.name->leader = std::pair(toScene(callout.leader.a), toScene(callout.leader.b));
}

// Each well's depth labels, down the well: at the mark's end, else just above or below it.
std::vector<LabelToPlace> depthLabelsToPlace(std::vector<WellLabels>& wells,
                                             const std::vector<AnnotationView>& views) {
    std::vector<LabelToPlace> depths;
    for (std::size_t w = 0; w < wells.size(); ++w)
        for (DepthTick& tick : wells[w].ticks) {
            LabelToPlace label{&views[w], &tick.label, &tick.labelAt, tick.end};
            if (const std::optional<glm::vec2> end = views[w].toPixels(tick.end)) {
                label.anchorPixel = *end;
                const ScreenBox box = boxFrom(*end, tick.label, kLabelSize_px);
                addCandidate(label, box, tick.label, kLabelSize_px);
                if (views[w].pixelSize) {
                    const float half = box.height() / 2.0f + 1.0f;
                    for (const float dy : {-half, half})
                        addCandidate(label, {box.x0, box.y0 + dy, box.x1, box.y1 + dy}, tick.label,
                                     kLabelSize_px);
                }
            }
            depths.push_back(std::move(label));
        }
    return depths;
}

// A label at the candidate it took, or cleared when it took none.
void settle(LabelToPlace& label, int chosen) {
    if (chosen < 0) {
        label.text->clear();
        return;
    }
    const auto k = static_cast<std::size_t>(chosen);
    const AnnotationView& view = *label.view;
    if (!view.pixelSize) return;  // where it first went
    // Moved across the view, at the anchor's distance from the eye.
    const glm::vec2 shift = label.starts[k] - label.anchorPixel;
    const glm::vec3 up = glm::cross(view.right, view.look);
    *label.labelAt =
        label.anchor + (view.right * shift.x - up * shift.y) * view.pixelSize(label.anchor);
}

}  // namespace

void placeWellLabels(std::vector<WellLabels>& wells, const std::vector<AnnotationView>& views,
                     const std::vector<ScreenBox>& obstacles) {
    if (wells.empty() || views.size() != wells.size() || !views.front().toPixels) return;
    constexpr float kUnbounded = 1.0e9f;
    constexpr float kGap_px = 2.0f;
    const AnnotationView& first = views.front();
    const bool bounded = first.width_px > 0 && first.height_px > 0;
    const ScreenBox frame = bounded ? ScreenBox{0.0f, 0.0f, static_cast<float>(first.width_px),
                                                static_cast<float>(first.height_px)}
                                    : ScreenBox{-kUnbounded, -kUnbounded, kUnbounded, kUnbounded};
    // Names first: a well's name says which well the rest belongs to.
    std::vector<NameToPlace> names = namesToPlace(wells, views);
    addPlacesApart(names, bounded ? 0.25f * std::hypot(frame.width(), frame.height()) : 0.0f);
    // The wellheads' markers stay visible.
    std::vector<ScreenBox> blocked = obstacles;
    for (std::size_t w = 0; w < wells.size(); ++w)
        if (wells[w].name && wells[w].name->wellhead)
            if (const auto head = views[w].toPixels(wells[w].name->position))
                blocked.push_back({head->x - 4.5f, head->y - 4.5f, head->x + 4.5f, head->y + 4.5f});
    // The wells' labels in one layout, so that no two wells' labels meet either.
    NameRound placed = placeNamesInRounds(LabelLayout(frame, std::move(blocked), kGap_px), names);
    for (std::size_t i = 0; i < names.size(); ++i)
        if (placed.apart[i] >= 0)
            setApart(names[i], names[i].apart[static_cast<std::size_t>(placed.apart[i])]);
        else
            settle(names[i].label, placed.beside[i]);
    // Then the depth labels.
    std::vector<LabelToPlace> depths = depthLabelsToPlace(wells, views);
    for (LabelToPlace& label : depths) settle(label, placed.layout.place(label.boxes));
}

PlacedAnnotations placeAnnotations(const std::vector<AnnotatedWell>& wells, const SoCamera& camera,
                                   int width, int height, double bottom_m, bool tickMarks,
                                   const std::vector<ScreenBox>& obstacles) {
    PlacedAnnotations placed;
    for (const AnnotatedWell& well : wells) {
        AnnotationView view = pictureAnnotationView(camera, width, height, well.top_m, bottom_m);
        view.radialExaggeration = well.radialExaggeration;
        view.tickMarks = tickMarks;
        view.depthTicks = well.depthTicks;
        placed.labels.push_back(wellLabels(*well.geometry, view));
        placed.views.push_back(std::move(view));
    }
    placeWellLabels(placed.labels, placed.views, obstacles);
    return placed;
}

NamesInView namesInView(const PlacedAnnotations& placed) {
    NamesInView names;
    for (std::size_t i = 0; i < placed.labels.size() && i < placed.views.size(); ++i) {
        const std::optional<WellName>& name = placed.labels[i].name;
        const AnnotationView& view = placed.views[i];
        if (!name || !view.toPixels) continue;
        const std::optional<glm::vec2> at = view.toPixels(name->position);
        if (!at || at->x < 0.0f || at->y < 0.0f ||
            (view.width_px > 0 && at->x > static_cast<float>(view.width_px)) ||
            (view.height_px > 0 && at->y > static_cast<float>(view.height_px)))
            continue;
        ++names.inView;
        if (name->text.empty()) ++names.leftOut;
    }
    return names;
}

std::string namesLeftOutCaption(const NamesInView& names) {
    if (names.leftOut == 0) return {};
    return std::to_string(names.leftOut) + " of " + std::to_string(names.inView) +
           (names.inView == 1 ? " name" : " names") + " left out: no room";
}

NamesInView placeClearOfNamesLine(std::size_t wells,
                                  const std::function<NamesInView(const std::string&)>& place) {
    const NamesInView names = place({});
    if (names.leftOut == 0) return names;
    return place(namesLeftOutCaption({wells, wells}));
}

std::vector<DepthTick> depthTicks(const reconstruction::WellGeometry& geometry,
                                  const AnnotationView& view) {
    std::vector<WellLabels> labels{wellLabels(geometry, view)};
    placeWellLabels(labels, {view});
    return labels.front().ticks;
}

SoSeparator* makeWellAnnotations(const reconstruction::WellGeometry& geometry,
                                 const AnnotationView& view) {
    std::vector<WellLabels> labels{wellLabels(geometry, view)};
    placeWellLabels(labels, {view});
    return makeWellAnnotations(geometry, view, labels.front());
}

SoSeparator* makeWellAnnotations(const reconstruction::WellGeometry& geometry,
                                 const AnnotationView& view, const WellLabels& wellLabels) {
    assertMainThread("makeWellAnnotations");
    auto* content = new SoSeparator;
    auto* unlit = new SoLightModel;
    unlit->model = SoLightModel::BASE_COLOR;
    content->addChild(unlit);
    if (geometry.table().rowCount() == 0) return makeDrawnOnly(content);
    const std::vector<DepthTick>& ticks = wellLabels.ticks;

    if (view.tickMarks && !ticks.empty()) {
        auto* marks = new SoSeparator;
        marks->setName("tick_marks");
        auto* style = new SoDrawStyle;
        style->lineWidth = 1.5f;
        auto* colour = new SoBaseColor;
        colour->rgb.setValue(kTickColour);
        auto* points = new SoCoordinate3;
        auto* lines = new SoLineSet;
        lines->numVertices.setNum(0);  // its default, -1, joins every point into one line
        int n = 0;
        for (const DepthTick& tick : ticks) {
            points->point.set1Value(n++, tick.position.x, tick.position.y, tick.position.z);
            points->point.set1Value(n++, tick.end.x, tick.end.y, tick.end.z);
            lines->numVertices.set1Value(lines->numVertices.getNum(), 2);
        }
        marks->addChild(style);
        marks->addChild(colour);
        marks->addChild(points);
        marks->addChild(lines);
        content->addChild(marks);
    }

    // Labels over everything, so a wall never hides them.
    auto* labels = new SoAnnotation;
    labels->setName("labels");
    labels->addChild(makeLabelFont(kLabelSize_px));
    for (const DepthTick& tick : ticks)
        if (!tick.label.empty()) {
            SoSeparator* label =
                labelNode(tick.labelAt, tick.label, view, kLabelColour, kLabelSize_px);
            label->setName("depth_label");
            labels->addChild(label);
        }
    if (wellLabels.name) {
        const WellName& name = *wellLabels.name;
        auto* nameColour = new SoBaseColor;
        nameColour->rgb.setValue(kNameColour);
        labels->addChild(nameColour);
        if (name.wellhead) {
            auto* at = new SoCoordinate3;
            at->point.setValue(name.position.x, name.position.y, name.position.z);
            auto* marker = new SoMarkerSet;
            marker->markerIndex = SoMarkerSet::CIRCLE_FILLED_9_9;
            labels->addChild(at);
            labels->addChild(marker);
        }
        if (!name.text.empty() && name.leader) {
            // A dimmer line than the name, from its well to the name placed apart.
            auto* leader = new SoSeparator;
            leader->setName("name_leader");
            auto* colour = new SoBaseColor;
            colour->rgb.setValue(kLeaderColour);
            auto* ends = new SoCoordinate3;
            ends->point.set1Value(0, name.leader->first.x, name.leader->first.y,
                                  name.leader->first.z);
            ends->point.set1Value(1, name.leader->second.x, name.leader->second.y,
                                  name.leader->second.z);
            auto* line = new SoLineSet;
            line->numVertices.setValue(2);
            leader->addChild(colour);
            leader->addChild(ends);
            leader->addChild(line);
            labels->addChild(leader);
        }
        if (!name.text.empty()) {
            labels->addChild(makeLabelFont(kNameSize_px));
            SoSeparator* nameLabel =
                labelNode(name.labelAt, name.text, view, kNameColour, kNameSize_px);
            nameLabel->setName("well_name");
            labels->addChild(nameLabel);
        }
    }
    content->addChild(labels);
    SoSeparator* root = makeDrawnOnly(content);
    root->setName("annotations");
    return root;
}

SoSeparator* makeWholeWellAnnotations(const reconstruction::WellGeometry& geometry,
                                      double radialExaggeration, bool depthTicks) {
    AnnotationView view;
    view.radialExaggeration = radialExaggeration;
    view.depthTicks = depthTicks;
    return makeWholeWellAnnotations(geometry, view, wellLabels(geometry, view));
}

SoSeparator* makeWholeWellAnnotations(const reconstruction::WellGeometry& geometry,
                                      const AnnotationView& view, const WellLabels& labels) {
    auto* group = new SoSeparator;
    group->setName("well_annotations");
    if (SoSeparator* above = makeUnloggedPath(geometry)) group->addChild(above);
    group->addChild(makeWellAnnotations(geometry, view, labels));
    return group;
}

SoSeparator* makeUnloggedPath(const reconstruction::WellGeometry& geometry, double spacing_m) {
    assertMainThread("makeUnloggedPath");
    const std::vector<glm::vec3> line = reconstruction::unloggedPathLine(geometry, spacing_m);
    if (line.size() < 2) return nullptr;
    auto* root = new SoSeparator;
    root->setName("unlogged_path");
    auto* style = new SoDrawStyle;
    style->lineWidth = 1.5f;
    style->linePattern = 0xF0F0;  // dashed: drawn from the tie-in, not from the log
    auto* unlit = new SoLightModel;
    unlit->model = SoLightModel::BASE_COLOR;
    auto* colour = new SoBaseColor;
    colour->rgb.setValue(0.2f, 0.55f, 0.9f);  // the logged path's (well_scene.cpp)
    auto* points = new SoCoordinate3;
    for (std::size_t i = 0; i < line.size(); ++i)
        points->point.set1Value(static_cast<int>(i), line[i].x, line[i].y, line[i].z);
    auto* strip = new SoLineSet;
    strip->numVertices.setValue(static_cast<int>(line.size()));
    root->addChild(style);
    root->addChild(unlit);
    root->addChild(colour);
    root->addChild(points);
    root->addChild(strip);
    return root;
}

}  // namespace caliper3d::scenegraph
