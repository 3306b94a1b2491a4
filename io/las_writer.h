#pragma once

#include <ostream>
#include <string>

#include "io/section_table.h"

namespace caliper3d::io {

struct LasWriteOptions {
    std::string wellName = "CALIPER3D";
    double null = -999.25;  // written for NaN; when a true value equals it, the first of
                            //   -999.25, -9999.25, -99999.25, ... that none equals
};

// Writes LAS 2.0, one line per depth: DEPT (M), R1..RN (MM, radii), then the
// optional P1AZ, DEVI, HAZI, RB (DEG), BS (MM) and every extra curve in its
// own unit. Values are the shortest text that reads back to the same double,
// and ~P says "NULLS. DECLARED" (only NULL marks a missing value, so a true
// 9999 is not taken for a common null): readCaliperLog returns exactly the
// table written (round trip). STEP is 0 when the depth step varies (LAS 2.0).
// Throws std::invalid_argument for a depth that is not finite.
void writeLas(std::ostream& out, const SectionTable& table, const LasWriteOptions& options = {});
void writeLasFile(const std::string& path, const SectionTable& table, const LasWriteOptions& options = {});

}  // namespace caliper3d::io
