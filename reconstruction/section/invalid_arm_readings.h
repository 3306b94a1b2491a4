#pragma once

#include <cstddef>
#include <string>

#include "io/section_table.h"

namespace caliper3d::reconstruction {

// Why the sections without a shape have none: their arm readings counted by kind (a
// reading is valid in (minRadius_mm, maxRadius_mm]).
struct InvalidArmReadings {
    std::size_t sections = 0;        // sections without a shape
    std::size_t readings = 0;        // their arm readings
    std::size_t missing = 0;         // NaN: null in the file (its NULL value, ERR, ...)
    std::size_t tooSmall = 0;        // at or below minRadius_mm (zero or negative by default)
    std::size_t beyondReach = 0;     // above maxRadius_mm, the tool's reach
    double firstDepth_m = io::kNaN;  // depth of the first such section in `rows` order
    // Counts the sections of `rows` with fewer than minValidArms(rows.armCount, fraction)
    // valid arms (chunk after chunk: the counts add up).
    void add(const io::SectionTable& rows, double minValidArmFraction, double minRadius_mm,
             double maxRadius_mm);
};

// "every arm reading is null (NaN or the file's NULL value)", or the count of each kind:
// why no section has a shape.
std::string describeInvalidArmReadings(const InvalidArmReadings& counts, double minRadius_mm,
                                       double maxRadius_mm);

}  // namespace caliper3d::reconstruction
