#pragma once

#include <ostream>
#include <string>

#include "io/section_table.h"
#include "io/units.h"

namespace caliper3d::io {

// Writes column text in the reference layout (depth R1..RN P1AZ DEVI HAZI)
// followed by RB, BS and every extra curve the table has, under a line of
// names with units ("depth_m R1_in ... BS_in GR[gAPI]"); depth in metres,
// radii and bit size in `radiusUnit`, angles in degrees, NaN as "nan". A curve
// the table lacks is left out, never written as zeros. The readers read it
// back to the same table.
void writeColumnText(std::ostream& out, const SectionTable& table,
                     LengthUnit radiusUnit = LengthUnit::Inch);
// The same to a file, whole or not at all (io/atomic_output.h).
void writeColumnTextFile(const std::string& path, const SectionTable& table,
                         LengthUnit radiusUnit = LengthUnit::Inch);

}  // namespace caliper3d::io
