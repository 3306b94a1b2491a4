#pragma once

#include <string>
#include <vector>

#include "io/azimuth_north.h"
#include "io/read_options.h"
#include "io/section_table.h"
#include "io/well_location.h"

namespace caliper3d::reconstruction {

// How a log's azimuths are brought to true north (docs/conventions.md, "North"):
// the angle added to each azimuth curve, and what every output says about it.
struct NorthCorrection {
    // Added to the azimuths of each CurvePlan angle slot (0 P1AZ, 2 HAZI; 1 and 3,
    // inclination and relative bearing, are not from north and stay 0).
    double add_deg[4] = {0.0, 0.0, 0.0, 0.0};
    // Which north every azimuth is from and which declination or convergence was applied
    // (value and source): one line for `info`, the report and the window. Empty when the
    // log has no azimuth curve.
    std::string summary;
    // Each a counted warning: an azimuth whose north is unknown (taken as true north), a
    // magnetic azimuth without a declination, a --declination nothing needed.
    std::vector<std::string> warnings;
};

// Settles the correction of each azimuth curve of `north` (read by io::readAzimuthNorth):
//  - true north: none;
//  - magnetic north: the declination of --declination, else the header's (MDEC, DECL, ...,
//    a ~Other remark), else the World Magnetic Model's at the header's latitude, longitude
//    and log date; none known: left from magnetic north, warned;
//  - grid north: the convergence of --grid-convergence, else the header's; none: warned;
//  - unknown (no description, header item or --azimuth-north says): taken as true north,
//    warned.
NorthCorrection resolveNorth(const io::AzimuthNorth& north, const io::WellLocation& location,
                             const io::ReadOptions& options);

// Adds the correction to p1az_deg and hazi_deg (kept in [0, 360); NaN stays NaN) and sets
// table.north to its summary.
void applyNorth(io::SectionTable& table, const NorthCorrection& correction);

// "14.38 E", "3.10 W", "0.00".
std::string eastAngleText(double deg);

}  // namespace caliper3d::reconstruction
