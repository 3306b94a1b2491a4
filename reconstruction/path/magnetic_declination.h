#pragma once

#include <string>

namespace caliper3d::reconstruction {

// The magnetic declination the World Magnetic Model gives for a place and date
// (docs/conventions.md, "North"): NOAA's WMM2015v2, WMM2020 and WMM2025
// coefficients, shipped converted in data/magnetic (scripts/wmm-to-geographiclib.py),
// evaluated with GeographicLib::MagneticModel.
struct ModelDeclination {
    double deg = 0.0;   // east positive; NaN when `why` says why there is none
    std::string model;  // "WMM2020" (the model that covers the date)
    std::string why;    // empty, or why no declination could be computed
    bool found() const { return why.empty(); }
};

// Latitude and longitude in degrees (south and west negative), `year` fractional
// (2014.15 for 23 February 2014), `height_m` above the WGS84 ellipsoid (a log's
// declination is taken at 0: a kilometre changes it by about 0.005 degrees). Each model is used
// over its five years only (2015.0 to 2030.0 in all): a date outside, a place off the globe or a
// missing model file gives no declination and says why.
ModelDeclination modelDeclination(double latitude_deg, double longitude_deg, double year,
                                  double height_m = 0.0);

// Where the model files are read from: $CALIPER3D_MAGNETIC_DIR when set, else the
// data/magnetic folder of the source tree the program was built from.
std::string magneticModelDirectory();

}  // namespace caliper3d::reconstruction
