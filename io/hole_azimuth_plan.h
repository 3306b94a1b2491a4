#pragma once

#include <string>

#include "io/log_info.h"
#include "io/section_table.h"

namespace caliper3d::io {

// How a log's hole azimuth is found (docs/conventions.md, "Hole azimuth").
// P1AZ = HAZI + RB is a tool's convention, not a law: Schlumberger's FMI
// keeps it within 1.5 degrees on every row of the reference log, another
// vendor's pad imager is offset by about 166 degrees. So the hole azimuth is
// derived only for a tool whose convention is known, and is otherwise unknown.
struct HoleAzimuthPlan {
    SectionTable::HoleAzimuth kind = SectionTable::HoleAzimuth::Read;
    std::string description;  // what `caliper3d info` shows
};

// Decides from the curves' roles and mnemonics and the service company of
// `info` (no rows needed). The known tool: service company Schlumberger, and
// curves named exactly P1AZ and RB read as pad-1 azimuth and relative bearing
// (the FMI/FMS/OBMI channel names). `surveyGiven`: a --survey gives the
// path's azimuth, so the log's does not matter.
HoleAzimuthPlan holeAzimuthPlan(const LogInfo& info, bool surveyGiven = false);

}  // namespace caliper3d::io
