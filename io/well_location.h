#pragma once

#include <cstddef>
#include <string>

#include "io/diagnostics.h"
#include "io/las_header.h"
#include "io/section_table.h"

namespace caliper3d::io {

// Where a log says its well is, read from the LAS ~Well and ~Parameter
// sections (docs/conventions.md, "Depth reference and well location").
// Everything is optional: NaN or empty when the header does not say.
struct WellLocation {
    std::string uwi;             // UWI (or API)
    std::string serviceCompany;  // SRVC, else LCNM, else PROD
    // The depth reference, as the file names it (LMF, else DREF, else DMF):
    // "KB", "K.B.", "KELLY BUSHING", ...
    std::string depthReference;
    // Elevation of the depth reference above the permanent datum, metres,
    // and which items gave it ("EKB (LMF K.B.)", "EREF", "EPD + APD").
    double referenceElevation_m = kNaN;
    std::string elevationSource;
    double groundElevation_m = kNaN;  // EGL, else GL
    // Projected map coordinates, metres, and the items that gave them.
    double easting_m = kNaN;
    double northing_m = kNaN;
    std::string projectedSource;
    // The coordinate reference system the header names (PROJ, EPSG, CRS, HZCS), as written
    // ("EPSG:32631", "32631", "WGS 84 / UTM zone 31N"), and the item that gave it; the
    // geodetic datum of the latitude and longitude (GDAT, else DATUM), as written ("WGS84").
    std::string crs;
    std::string crsSource;
    std::string geodeticDatum;
    // Geographic coordinates, decimal degrees (south and west negative), and
    // the text they were read from.
    double latitude_deg = kNaN;
    double longitude_deg = kNaN;
    std::string latitudeText;
    std::string longitudeText;

    bool hasProjected() const;
    bool empty() const;
};

// Reads the well's location and depth reference from a LAS header. Items in
// a length unit the product does not know, or whose value is not a number,
// are skipped with a warning; a depth reference elevation that disagrees with
// EPD + APD by more than 5 cm is kept and warned about.
WellLocation readWellLocation(const LasHeader& header, const std::string& file,
                              Diagnostics* diagnostics);

// Reads the location from the header of the LAS file at `path` alone (up to its ~A line),
// or from a DLIS file's parameters (its first logical file that gives a place), without
// reading its rows: empty for column text or a file that cannot be read.
WellLocation readWellLocationOf(const std::string& path, Diagnostics* diagnostics);

// "57.0175 N", "-111.419 W", "56.934500 degrees", "57 1 3.0 N", "57°1'3.0\"N", "N57 01 03"
// as decimal degrees (south and west negative); NaN when the text is none of these.
double parseGeographicDegrees(const std::string& text);

// The lines `caliper3d info` prints ("" when the location is empty).
std::string formatWellLocation(const WellLocation& location);

}  // namespace caliper3d::io
