#pragma once

#include <optional>
#include <vector>

#include "io/casing_string.h"

#include "io/azimuth_north.h"
#include "io/curve_roles.h"
#include "io/units.h"

namespace caliper3d::io {

// Which values mean "no reading" in a LAS data section. Never applied to the
// depth index (index_null.las holds a real depth equal to its NULL value).
enum class NullPolicy {
    Declared,  // the header's NULL only, plus text overflow ("****")
    Common     // also -999.25, 999.25, +-9999.25, +-9999, -999, ERR, NaN, dashes
};

// What to do with a row whose depth goes back up in a log recorded downwards
// (a log recorded upwards as a whole is always sorted, with a warning).
enum class DepthOrder {
    SkipBackwards,  // the row is skipped, counted in one warning
    Reject          // ParseError at the first such row
};

// A column-text line of at least this many numbers (and no more than kMaxArms),
// but not armCount + 4, is taken for the radii of a multi-finger tool alone.
inline constexpr int kMinRadiiOnlyColumns = 8;

// How to read a caliper log of any supported format. Every lenient behaviour
// is a named option here with its default.
struct ReadOptions {
    int armCount = 6;                      // column text: radii per line
    std::optional<LengthUnit> depthUnit;   // overrides the file's (column text default: metres)
    std::optional<LengthUnit> radiusUnit;  // overrides the file's (column text default: inches,
                                           //   millimetres when inches would be implausible)
    bool allowRadiiOnly = true;            // column text of radii only: depth = row x rowStep_m
    double rowStep_m = 0.01;               // column text with radii only: depth step per row
    NullPolicy nullPolicy = NullPolicy::Common;
    DepthOrder depthOrder = DepthOrder::SkipBackwards;
    RoleOverrides roles;
    std::optional<double> bitSize_mm;  // overrides the file's BS
    // docs/conventions.md, "North": the magnetic declination (east positive) applied to
    // azimuths from magnetic north, overriding the header's and the magnetic model's; the
    // grid convergence (grid north clockwise from true north) applied to azimuths from grid
    // north; the north of azimuth curves whose description does not say.
    std::optional<double> declination_deg;
    std::optional<double> gridConvergence_deg;
    North azimuthNorth = North::Unknown;
    std::vector<CasingString> casing;  // --casing: replaces the file's casing program
    // DLIS: the logical file to read (1-based, --file N); 0 reads the first that holds
    // caliper curves (docs/formats.md, "DLIS").
    int logicalFile = 0;
};
// Two wells read alike: the window compares the options its wells were opened with.
inline bool operator==(const ReadOptions& a, const ReadOptions& b) {
    return a.armCount == b.armCount && a.depthUnit == b.depthUnit && a.radiusUnit == b.radiusUnit &&
           a.allowRadiiOnly == b.allowRadiiOnly && a.rowStep_m == b.rowStep_m &&
           a.nullPolicy == b.nullPolicy && a.depthOrder == b.depthOrder && a.roles == b.roles &&
           a.bitSize_mm == b.bitSize_mm && a.declination_deg == b.declination_deg &&
           a.gridConvergence_deg == b.gridConvergence_deg && a.azimuthNorth == b.azimuthNorth &&
           a.casing == b.casing && a.logicalFile == b.logicalFile;
}
inline bool operator!=(const ReadOptions& a, const ReadOptions& b) {
    return !(a == b);
}

}  // namespace caliper3d::io
