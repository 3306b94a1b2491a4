#pragma once

#include <string>

#include "io/diagnostics.h"
#include "io/hole_azimuth_plan.h"
#include "io/section_table.h"

namespace caliper3d::reconstruction {

// HAZI = P1AZ - RB, wrapped to [0, 360), on every row that has both (NaN
// elsewhere: the path carries the last value forward, as for a null HAZI).
void deriveHoleAzimuth(io::SectionTable& table);

// Applies the plan to a read table: derives HAZI or marks it unknown, and
// says so in `diagnostics` (one counted warning, against the file).
void resolveHoleAzimuth(io::SectionTable& table, const io::HoleAzimuthPlan& plan,
                        io::Diagnostics* diagnostics);

}  // namespace caliper3d::reconstruction
