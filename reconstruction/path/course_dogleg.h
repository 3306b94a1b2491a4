#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "reconstruction/path/minimum_curvature.h"

namespace caliper3d::reconstruction {

// The course length dogleg severity is measured over (docs/analysis.md, "Dogleg severity"):
// 30 m, the course the API and IADC quote DLS per, and about the spacing of survey stations.
constexpr double kDlsCourseLength_m = 30.0;
// Each end's hole direction is the mean of the sections within this of it: a log's DEVI and
// HAZI carry noise of a few tenths of a degree from sample to sample.
constexpr double kDlsDirectionWindow_m = 1.5;

// Sets every point's dls_degPer30m to the dogleg over the course of `course_m` centred on it
// (cut at the path's ends): the angle between the mean hole directions at the course's two
// ends, each averaged over `window_m` either side, per 30 m of the measured depth between
// them. Points must be in increasing md; a path shorter than a metre keeps its values.
// By hand: running sums of the unit tangents in a window sliding down the hole give each mean
// direction for the points entering and leaving it.
void setCourseLengthDls(std::vector<PathPoint>& path, double course_m = kDlsCourseLength_m,
                        double window_m = kDlsDirectionWindow_m);
// The same, with each point's unit tangent (north, east, down) given, as placing the path took
// it from the same sines and cosines: bit for bit the same severities, without taking them again.
void setCourseLengthDls(std::vector<PathPoint>& path, const std::vector<glm::dvec3>& tangents,
                        double course_m = kDlsCourseLength_m,
                        double window_m = kDlsDirectionWindow_m);

}  // namespace caliper3d::reconstruction
