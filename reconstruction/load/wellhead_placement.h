#pragma once

#include <optional>
#include <string>

#include "io/well_location.h"
#include "reconstruction/path/wellhead.h"

namespace caliper3d::reconstruction {

struct WellSource;

// The field frame of a scene whose first well's header gives map coordinates that name no
// coordinate reference system: the other wells' unnamed map coordinates are taken to be in
// the same grid; latitude and longitude cannot be put in it.
inline const char* const kHeaderGrid = "the first well's header grid";

// How a well is placed in its field (docs/conventions.md, "Depth reference, tie-in and well
// location"): its wellhead in the field frame, or none, and why, in words.
struct WellPlacement {
    // Easting, northing (metres in the field frame) and elevation of the depth reference
    // (NaN when the header gives none); nullopt when the well is not placed.
    std::optional<Wellhead> wellhead;
    // "from the header's lat/long, UTM zone 31N (EPSG:32631): E 456789.12 N 6745678.90,
    // elevation KB 25.00 m (EKB)", "by --wellhead ...", or why not placed.
    std::string description;
};

// The field frame a header defines: the projected coordinate reference system it names
// (PROJ, EPSG, CRS, HZCS: "EPSG:32631"), else the UTM zone (WGS 84) of its latitude and
// longitude, else kHeaderGrid when it gives map coordinates without a system; "" when it
// gives no location. The frame is not checked here (placeFromHeader says when PROJ does not
// know it).
std::string fieldFrameOf(const io::WellLocation& location);

// "UTM zone 31N (EPSG:32631)", "RGF93 v1 / Lambert-93 (EPSG:2154)": the frame in words.
std::string describeFrame(const std::string& frame);

// Places a well from its header in `frame` with PROJ: its map coordinates, transformed from
// the system the header names when that is not the frame (or taken as they are when the frame
// is kHeaderGrid and the header names none), else its latitude and longitude (on the datum
// GDAT names, WGS 84 when none) projected.
WellPlacement placeFromHeader(const io::WellLocation& location, const std::string& frame);

// The grid azimuth of true north (degrees clockwise from the frame's grid north; minus the
// meridian convergence) at a point of `frame`, by PROJ; 0 for kHeaderGrid or a frame PROJ
// does not know.
double trueNorthGridAzimuth(const std::string& frame, double easting_m, double northing_m);

// How `source` is placed in the scene whose origin is `origin` (sceneOrigin): by --wellhead
// when given, else from its header (readWellLocationOf) in origin.frame, its elevation level
// with the origin's when the header gives none. The offset is from the origin.
WellPlacement placeWell(const WellSource& source, const Wellhead& origin);

}  // namespace caliper3d::reconstruction
