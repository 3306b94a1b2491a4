#include "io/hole_azimuth_plan.h"

#include <algorithm>
#include <cctype>

#include "io/text.h"

namespace caliper3d::io {

namespace {

const CurveInfo* curveWithRole(const LogInfo& info, const char* role) {
    for (const CurveInfo& c : info.curves)
        if (c.role == role) return &c;
    return nullptr;
}

}  // namespace

HoleAzimuthPlan holeAzimuthPlan(const LogInfo& info, bool surveyGiven) {
    using Kind = SectionTable::HoleAzimuth;
    const CurveInfo* hazi = curveWithRole(info, "hole azimuth");
    if (hazi) return {Kind::Read, "from " + hazi->mnemonic};
    if (surveyGiven) return {Kind::Read, "from the survey (--survey)"};
    const CurveInfo* p1az = curveWithRole(info, "pad-1 azimuth");
    const CurveInfo* rb = curveWithRole(info, "relative bearing");
    const bool schlumberger =
        upper(info.location.serviceCompany).find("SCHLUMBERGER") != std::string::npos;
    if (schlumberger && p1az && rb && upper(p1az->mnemonic) == "P1AZ" &&
        upper(rb->mnemonic) == "RB")
        return {Kind::Derived,
                "derived as P1AZ - RB (Schlumberger pad imager: P1AZ = HAZI + RB; no HAZI curve)"};
    if (!curveWithRole(info, "deviation"))
        return {Kind::Read, "none (no inclination curve: the path is drawn vertical)"};
    return {Kind::Unknown,
            "unknown: no HAZI curve, and " +
                std::string(p1az && rb ? "P1AZ - RB is a convention of known tools only (service "
                                         "company '" +
                                             info.location.serviceCompany + "', curves " +
                                             p1az->mnemonic + ", " + rb->mnemonic + ")"
                                       : "no pad-1 azimuth and relative bearing to derive it") +
                "; give --survey"};
}

}  // namespace caliper3d::io
