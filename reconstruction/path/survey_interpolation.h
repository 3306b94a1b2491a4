#pragma once

#include <string>
#include <vector>

#include "io/survey_reader.h"
#include "reconstruction/path/minimum_curvature.h"

namespace caliper3d::reconstruction {

// The stations of a read survey (metres, degrees).
std::vector<SurveyStation> surveyStations(const io::SurveyTable& survey);

// Tie-in (docs/conventions.md): measured depth counts from the depth
// reference at the wellhead, where the hole is taken as vertical. The station
// there, for a path whose first station is `first`: MD 0, inclination 0, and
// `first`'s azimuth, so that the minimum-curvature step down to `first` builds
// straight towards it (and is a vertical drop when `first` is vertical).
SurveyStation surfaceTieIn(const SurveyStation& first);
// `stations` with surfaceTieIn prepended when the first lies below MD 0;
// unchanged when it is at (or above) MD 0 or there are none.
std::vector<SurveyStation> tiedToSurface(std::vector<SurveyStation> stations);

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

// How well the positions a survey file writes (TVD, north, east) agree with
// minimum curvature from its own MD, inclination and azimuth: differences are
// taken from the first station that has the value, so grid coordinates and
// wellhead offsets compare alike. Zero stations when the file has no TVD/N/E.
struct SurveyPositionCheck {
    std::size_t tvdStations = 0;
    double maxTvdDifference_m = 0.0;  // largest |file - computed|
    double maxTvdAt_m = 0.0;          // MD where it is
    std::size_t horizontalStations = 0;
    double maxHorizontalDifference_m = 0.0;  // largest horizontal distance
    double maxHorizontalAt_m = 0.0;
    // North/east of a file are often grid coordinates (grid north, grid scale
    // factor) while its azimuths are true: the turn (clockwise, degrees) and
    // scale that best map the computed displacements onto the file's (least
    // squares), and the largest distance left after them.
    double rotation_deg = 0.0;
    double scale = 1.0;
    double maxHorizontalAfterFit_m = 0.0;
};
SurveyPositionCheck checkSurveyPositions(const io::SurveyTable& survey);

// A survey whose written TVD differs from minimum curvature by more than this
// (its positions come from another method, or its columns are misread) gets a
// warning; published tables printed to 0.01 m agree within a few millimetres.
constexpr double kSurveyPositionTolerance_m = 0.1;

// One line that says what checkSurveyPositions found ("" when nothing to check).
std::string describeSurveyPositionCheck(const SurveyPositionCheck& check);

}  // namespace caliper3d::reconstruction
