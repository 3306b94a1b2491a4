#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "io/section_table.h"
#include "reconstruction/well_geometry.h"

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
    // a dark outline a pixel wide, which keeps it legible over a lit wall.
    std::function<float(const glm::vec3&)> pixelSize;
};

// The annotation view of a picture taken by `camera` (its direction, right and projection)
// over measured depths [top_m, bottom_m].
AnnotationView pictureAnnotationView(const SoCamera& camera, int width, int height, double top_m,
                                     double bottom_m);

// One depth tick: at `md_m` on the path (scene frame), its mark out to `end`, its label
// there (empty when left out to keep labels apart).
struct DepthTick {
    double md_m = 0.0;
    glm::vec3 position{0.0f};
    glm::vec3 end{0.0f};
    std::string label;
};

// The ticks of `geometry` every spacing (AnnotationView::tickSpacing_m) over the annotated
// depths, MD 0 (the wellhead, which carries the well's name) left out.
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

// A well's unlogged path and annotations for a view that shows it whole with the default
// direction of a viewer's camera (looking north), in one group: what a window adds beside
// each well's WellScene.
SoSeparator* makeWholeWellAnnotations(const reconstruction::WellGeometry& geometry,
                                      double radialExaggeration);

// The path above the logged interval (reconstruction::unloggedPathLine), dashed and
// thinner than the logged path; null when the log starts at the wellhead.
SoSeparator* makeUnloggedPath(const reconstruction::WellGeometry& geometry, double spacing_m = 1.0);

}  // namespace caliper3d::scenegraph
