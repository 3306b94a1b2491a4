#pragma once

#include <string>

#include "io/log_info.h"
#include "io/section_table.h"

namespace caliper3d::test {

// The curve `info` lists under `mnemonic`; nullptr when none.
inline const io::CurveInfo* curve(const io::LogInfo& info, const std::string& mnemonic) {
    for (const io::CurveInfo& c : info.curves)
        if (c.mnemonic == mnemonic) return &c;
    return nullptr;
}

// The extra curve (one without a role) of `t` named `mnemonic`; nullptr when none.
inline const io::ExtraCurve* extra(const io::SectionTable& t, const std::string& mnemonic) {
    for (const io::ExtraCurve& c : t.extraCurves)
        if (c.mnemonic == mnemonic) return &c;
    return nullptr;
}

}  // namespace caliper3d::test
