#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "io/section_table.h"
#include "reconstruction/well_geometry.h"
#include "scenegraph/label_placement.h"

class SoCamera;
class SoSeparator;

namespace caliper3d::scenegraph {

// What the annotations of a well are drawn for: the measured depths shown and how they are
// seen. The tick spacing and the size of the tick marks follow the length shown.
struct AnnotationView {
    double top_m = 0.0;  // measured depths annotated (clamped to the well's path)
    double bottom_m = 1.0e300;
    double tickSpacing_m = 0.0;  // 0: tickSpacing_m(the length annotated), picture_scale.h
    // Drawn radii / true radii: tick marks start at the drawn wall.
    double radialExaggeration = 1.0;
    // Scene frame: the view direction and the picture's right. Tick marks stand off the path
    // across the view, on the right (labels read from their ends rightwards).
    glm::vec3 look{0.0f, 0.0f, -1.0f};
    glm::vec3 right{1.0f, 0.0f, 0.0f};
    // False looking down the hole: no tick marks (they would pierce the wall), labels on the
    // axis.
    bool tickMarks = true;
    // Where a scene point lands in the picture, in pixels from its top-left corner (nullopt
    // behind the eye). When set, a label that would overlap one placed before is left out and
    // its tick stays unlabelled; without it (a window, whose camera moves) every tick is
    // labelled.
    std::function<std::optional<glm::vec2>(const glm::vec3&)> toPixels;
    // The scene length one pixel of the picture spans at a point. When set, every label gets
    // a dark outline a pixel wide, which keeps it legible over a lit wall, and a label may be
    // moved off its anchor to keep clear of the others.
    std::function<float(const glm::vec3&)> pixelSize;
    // The picture's size in pixels (0: not known): with toPixels, labels stay inside it.
    int width_px = 0;
    int height_px = 0;
    // False: no depth ticks, nor their labels. A picture of several wells ticks the current
    // one only and names the others.
    bool depthTicks = true;
};

// The annotation view of a picture taken by `camera` (its direction, right and projection)
// over measured depths [top_m, bottom_m].
AnnotationView pictureAnnotationView(const SoCamera& camera, int width, int height, double top_m,
                                     double bottom_m);

// One depth tick: at `md_m` on the path (scene frame), its mark out to `end`, its label
// (empty when left out to keep labels apart) starting at `labelAt` (the left end of its text,
// at the middle of its capitals' height): the mark's end, unless moved clear of another label.
struct DepthTick {
    double md_m = 0.0;
    glm::vec3 position{0.0f};
    glm::vec3 end{0.0f};
    std::string label;
    glm::vec3 labelAt{0.0f};
};

// A well's name at the top of what is annotated (`position`, the wellhead when `wellhead`,
// which carries a marker), its text starting at `labelAt` as a tick's label does; `text`
// empty when left out (no room for it in a picture).
struct WellName {
    std::string text;
    glm::vec3 position{0.0f};
    glm::vec3 labelAt{0.0f};
    bool wellhead = false;
    float drawnRadius_m = 0.0f;  // of the tube there: a name placed keeps clear of it
    // A name placed apart from its well (no room beside it) is joined to it by a leader, drawn
    // from near `position` to the name's box: its two ends in the scene frame.
    std::optional<std::pair<glm::vec3, glm::vec3>> leader;
};

// What a well's annotations say and where: its name (with tick marks only: not down the
// hole) and its depth ticks.
struct WellLabels {
    std::optional<WellName> name;
    std::vector<DepthTick> ticks;
};

// A well's labels where they first go: every tick labelled at its mark's end, the name off the
// top of the path on the tick marks' side. Nothing is left out or moved.
WellLabels wellLabels(const reconstruction::WellGeometry& geometry, const AnnotationView& view);

// The labels of a picture's wells placed together (label_placement.h, LabelLayout): every
// well's name first, in the order given, then each well's depth labels down the well; a name
// may take a place all round the top of its well, a depth label its mark's end or just above or
// below it; a label with no free room is left out (its tick stays). A name placed goes beside the
// top of its well (its wellhead in a map), clear of the tube drawn there; a name with no room
// there, once every name has had its turn, is placed apart with a leader to its well
// (calloutCandidates: out from the middle of the wells' tops first, up to a quarter of the
// picture's diagonal away), before any depth label. `views[i]` is how well i
// is seen (toPixels, and pixelSize to move a label; without toPixels nothing is placed);
// `obstacles` are what the picture draws over the scene (the overlay, a legend).
void placeWellLabels(std::vector<WellLabels>& wells, const std::vector<AnnotationView>& views,
                     const std::vector<ScreenBox>& obstacles = {});

// One well of a view whose labels are placed together (placeAnnotations): its geometry as
// drawn, the measured depth its annotations start from (0: its wellhead), and whether it
// carries depth ticks.
struct AnnotatedWell {
    const reconstruction::WellGeometry* geometry = nullptr;
    double top_m = 0.0;
    double radialExaggeration = 1.0;
    bool depthTicks = true;
};

// Each well's annotation view and labels as `camera` sees them in a view of `width` x
// `height` pixels, down to `bottom_m`, with tick marks or not (not down the hole): every
// label of every well placed at once (placeWellLabels), clear of the others and of
// `obstacles`. What a picture and the window, once its camera rests, draw.
struct PlacedAnnotations {
    std::vector<AnnotationView> views;
    std::vector<WellLabels> labels;
};
PlacedAnnotations placeAnnotations(const std::vector<AnnotatedWell>& wells, const SoCamera& camera,
                                   int width, int height, double bottom_m, bool tickMarks,
                                   const std::vector<ScreenBox>& obstacles);

// The wells of `placed` whose name is anchored inside the picture (its wellhead or the top of
// its log in view), and how many of those had no room for their name and went unnamed.
struct NamesInView {
    std::size_t inView = 0;
    std::size_t leftOut = 0;
};
NamesInView namesInView(const PlacedAnnotations& placed);

// The caption's line for names left out: "48 of 100 names left out: no room"; empty
// when none is. namesLeftOutCaption({n, n}) is the widest the line can be for n wells: a
// picture reserves its room before placing the names.
std::string namesLeftOutCaption(const NamesInView& names);

// Places the labels of `wells` wells by `place(namesLine)`, which shows `namesLine` under the
// caption (empty: no line) and places every label clear of the caption, returning namesInView
// of what it placed: once with no line and, when names were left out, again with the line at
// its widest, so that no label lies under the line that then says how many. Returns the names
// of the placement kept; the caller shows namesLeftOutCaption of them.
NamesInView placeClearOfNamesLine(std::size_t wells,
                                  const std::function<NamesInView(const std::string&)>& place);

// The ticks of `geometry` every spacing (AnnotationView::tickSpacing_m) over the annotated
// depths, MD 0 (the wellhead, which carries the well's name) left out; with view.toPixels,
// placed with the well's name as placeWellLabels places one well's.
std::vector<DepthTick> depthTicks(const reconstruction::WellGeometry& geometry,
                                  const AnnotationView& view);

// "500 m", "12.5 m": a tick's measured depth with the decimals its spacing needs.
std::string depthLabel(double md_m, double spacing_m);

// The well's name: the log's WELL header field, else its file name.
std::string wellLabel(const io::SectionTable& table);

// The nodes of a well's annotations: tick marks, their MD labels, and the well's name at
// the top of what is annotated (with a marker when that is the wellhead). Labels are drawn
// over the scene (SoAnnotation) and take no part in bounding boxes (drawn_only.h). Main
// thread only.
SoSeparator* makeWellAnnotations(const reconstruction::WellGeometry& geometry,
                                 const AnnotationView& view);
// The same with its labels as given (placeWellLabels). Each label is a separator named
// "well_name" or "depth_label": an SoTranslation to the left end of its baseline, its outline,
// its colour and its SoText2.
SoSeparator* makeWellAnnotations(const reconstruction::WellGeometry& geometry,
                                 const AnnotationView& view, const WellLabels& labels);

// A well's unlogged path and annotations for a view that shows it whole with the default
// direction of a viewer's camera (looking north), in one group: what a window adds beside
// each well's WellScene. Without `depthTicks`, its name and path only (a window of several
// wells ticks the current one).
SoSeparator* makeWholeWellAnnotations(const reconstruction::WellGeometry& geometry,
                                      double radialExaggeration, bool depthTicks = true);

// The same for `view` with its labels as placed (placeAnnotations): what a window adds
// once its camera rests.
SoSeparator* makeWholeWellAnnotations(const reconstruction::WellGeometry& geometry,
                                      const AnnotationView& view, const WellLabels& labels);

// The path above the logged interval (reconstruction::unloggedPathLine), dashed and
// thinner than the logged path; null when the log starts at the wellhead.
SoSeparator* makeUnloggedPath(const reconstruction::WellGeometry& geometry, double spacing_m = 1.0);

}  // namespace caliper3d::scenegraph
