#pragma once

#include <limits>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "reconstruction/well_geometry.h"

namespace caliper3d::scenegraph {

// The rules that size what a picture draws to the length of well it shows
// (docs/architecture.md, "Annotations").

// Depth ticks: the smallest spacing of the 1-2-5 series (..., 0.5, 1, 2, 5, 10, 20, 50, ...
// metres) that puts at most kMaxDepthTicks ticks over `visibleLength_m` of measured depth.
// Consecutive spacings differ at most 2.5 times, so a view gets between 6 and 15 ticks,
// whatever its length: 10 m -> 1 m, 160 m -> 20 m, 1000 m -> 100 m, 4000 m -> 500 m.
constexpr int kMaxDepthTicks = 15;
double tickSpacing_m(double visibleLength_m);

// Radial exaggeration: a whole well framed in a picture is about its length tall, so a
// 200 mm hole 1 km long is a fraction of a pixel across. The default picture draws the
// hole at least kMinDrawnDiameter of the picture's height across (and at least
// kMinDrawnDiameter_px): the factor is
//     max(kMinDrawnDiameter, kMinDrawnDiameter_px / pictureHeight_px) * extent / (2 r)
// with r the hole's typical radius and extent the drawn path's size, rounded up to the
// 1-2-3-5 series (1, 2, 3, 5, 10, 20, ...) so that the picture can state it plainly, and
// kept in [1, kMaxExaggeration]. 1 km of 8.5 in hole -> 100, 4 km -> 300, 10 m -> 1.
constexpr double kMinDrawnDiameter = 0.015;
constexpr double kMinDrawnDiameter_px = 4.0;
constexpr double kMaxExaggeration = 1000.0;  // as --exaggerate allows
double autoExaggeration(double extent_m, double typicalRadius_m, int pictureHeight_px);

// Several wells in one scene (a field): the chosen factor never makes two wells' tubes touch.
// For every two wells A and B it is at most the largest factor F of the 1-2-3-5 series with
//     F (RA + RB) <= kTubeClearance d
// where RA, RB are the largest arm radii logged and d the closest approach of the two logged
// paths (3D, anywhere along them: tubes meet only where their axes come within the sum of
// their drawn radii, whatever the depths, so deviated wells crossing at different measured
// depths are caught too). A section is drawn F times larger about its centroid, which lies
// within R of the path, so a drawn point lies within (2F - 1) R of it (as the level-of-detail
// bound says); with kTubeClearance = 1/2 the tubes keep at least RA + RB between them even
// then, and look apart. Two wells that no factor from 1 keeps apart (the same hole logged
// twice, a sidetrack leaving its parent) share their hole and do not limit it.
constexpr double kTubeClearance = 0.5;
// That largest factor, or 0 when even 1 does not keep them apart.
double separatedExaggeration(double closestApproach_m, double maxRadiusA_m, double maxRadiusB_m);

// The exaggeration a picture `pictureHeight_px` high chooses for `wells` over measured depths
// [top_m, bottom_m]: autoExaggeration of the extent of each well's logged path there (the
// path above the log is not what the picture frames) and the thinnest well's typical radius,
// then at most what separatedExaggeration allows every two of the wells.
// `caliper3d render` and the window, which opens with it, both draw with this.
double chooseExaggeration(
    const std::vector<std::shared_ptr<const reconstruction::WellGeometry>>& wells, double top_m,
    double bottom_m, int pictureHeight_px);

// The smallest of 1, 2, 3, 5 times a power of ten that is at least `value` (> 0).
double roundUpToSeries(double value);
// Every factor chooseExaggeration can choose: 1 and the 1-2-3-5 series up to kMaxExaggeration.
std::vector<double> seriesExaggerations();
// The largest of 1, 2, 3, 5 times a power of ten that is at most `value` (> 0).
double roundDownToSeries(double value);

// The box around a set of points (scene or analysis frame), empty until one is added.
struct Bounds {
    glm::dvec3 lo{std::numeric_limits<double>::infinity()};
    glm::dvec3 hi{-std::numeric_limits<double>::infinity()};
    void add(const glm::dvec3& p);
    bool empty() const { return !(lo.x <= hi.x); }
    double diagonal() const;
};

// Adds the path of `geometry` over measured depths [top_m, bottom_m] to `bounds` (its rows,
// sampled to a few thousand; from the wellhead when top_m lies above the first row).
void addPathBounds(const reconstruction::WellGeometry& geometry, double top_m, double bottom_m,
                   Bounds& bounds);

// The median arm radius, in metres, of the rows with data in [top_m, bottom_m] (sampled to a
// few thousand rows); NaN when there are none.
double typicalRadius_m(const reconstruction::WellGeometry& geometry, double top_m, double bottom_m);

// The largest arm radius, in metres, of the rows with data in [top_m, bottom_m]; NaN when
// there are none.
double maxRadius_m(const reconstruction::WellGeometry& geometry, double top_m, double bottom_m);

// The closest approach, in metres, of the paths of `a` and `b` over measured depths
// [top_m, bottom_m] (their rows, sampled to a few hundred, joined by straight lines);
// infinity when either has no row there.
double closestApproach_m(const reconstruction::WellGeometry& a,
                         const reconstruction::WellGeometry& b, double top_m, double bottom_m);

}  // namespace caliper3d::scenegraph
