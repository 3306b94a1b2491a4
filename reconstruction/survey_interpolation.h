#pragma once

#include <vector>

#include "io/survey_reader.h"
#include "reconstruction/minimum_curvature.h"

namespace caliper3d::reconstruction {

// The stations of a read survey (metres, degrees).
std::vector<SurveyStation> surveyStations(const io::SurveyTable& survey);

// The well path at each measured depth of `md` (ascending), from the survey's
// stations: between two stations the point lies on the minimum-curvature arc
// that joins them (its tangent turns at a constant rate in the plane of the
// two station tangents), so interpolating never moves the path off the arcs
// that the survey itself defines. Above the first station and below the last
// the path runs straight along the end tangent. Each point carries the
// dogleg severity of the survey course it lies in and its dogleg from the
// previous output point.
std::vector<PathPoint> interpolateSurveyPath(const std::vector<SurveyStation>& survey,
                                             const std::vector<double>& md);

// The station at measured depth md on the arc between stations a and b
// (a.md <= md <= b.md): inclination and azimuth of the arc's tangent there.
SurveyStation stationOnArc(const SurveyStation& a, const SurveyStation& b, double md);

}  // namespace caliper3d::reconstruction
