#pragma once

#include <ostream>
#include <string>

#include "io/section_table.h"

namespace caliper3d::io {

struct LasWriteOptions {
    std::string wellName = "CALIPER3D";
    double null = -999.25;  // written for NaN; a true value equal to it reads back as null
};

// Writes LAS 2.0, one line per depth: DEPT (M), R1..RN (MM, radii), then the
// optional P1AZ, DEVI, HAZI, RB (DEG), BS (MM) and every extra curve in its
// own unit. Values are the shortest text that reads back to the same double,
// so readCaliperLog returns exactly the table written (round trip).
void writeLas(std::ostream& out, const SectionTable& table, const LasWriteOptions& options = {});
void writeLasFile(const std::string& path, const SectionTable& table, const LasWriteOptions& options = {});

}  // namespace caliper3d::io
