#pragma once

#include <ostream>
#include <string>

#include "io/section_table.h"
#include "io/units.h"

namespace caliper3d::io {

// Writes the reference tool's column text (depth R1..RN P1AZ DEVI HAZI),
// depth in metres and radii in `radiusUnit`, with a '#' header comment.
void writeColumnText(std::ostream& out, const SectionTable& table,
                     LengthUnit radiusUnit = LengthUnit::Inch);
void writeColumnTextFile(const std::string& path, const SectionTable& table,
                         LengthUnit radiusUnit = LengthUnit::Inch);

}  // namespace caliper3d::io
