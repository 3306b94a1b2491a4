#include "reconstruction/analysis/rule_settings.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "io/number_parsing.h"

namespace caliper3d::reconstruction {

const std::vector<RuleSetting>& ruleSettings() {
    static const std::vector<RuleSetting> kSettings = {
        {"gauge_tolerance_mm", "in_gauge: dmin and dmax within this of bit size",
         &ClassificationRules::gaugeTolerance_mm},
        {"undergauge_mm", "undergauge: dmax below bit size minus this",
         &ClassificationRules::undergauge_mm},
        {"washout_mm", "washout: dmin above bit size plus this", &ClassificationRules::washout_mm},
        {"elongation_mm", "breakout/keyseat: dmax - dmin at least this",
         &ClassificationRules::elongation_mm},
        {"breakout_min_gauge_mm", "breakout: dmin within this of bit size",
         &ClassificationRules::breakoutMinGauge_mm},
        {"min_breakout_length_m", "breakout zones at least this long",
         &ClassificationRules::minBreakoutLength_m},
        {"max_tool_rotation_deg", "breakout: the tool turns less than this per window",
         &ClassificationRules::maxToolRotation_deg},
        {"rotation_window_m", "length of that window", &ClassificationRules::rotationWindow_m},
        {"deviated_inclination_deg", "above this inclination the high-side test applies",
         &ClassificationRules::deviatedInclination_deg},
        {"high_side_tolerance_deg", "major axis within this of the high/low side: keyseat",
         &ClassificationRules::highSideTolerance_deg},
        {"axis_min_elongation_mm", "below this dmax - dmin a section has no major-axis azimuth",
         &ClassificationRules::axisMinElongation_mm},
        {"min_valid_arm_fraction",
         "a section with fewer valid arms than this fraction of its arms (at least 2) is no_data",
         &ClassificationRules::minValidArmFraction},
        {"arms_closed_fraction",
         "dmax more than this fraction below gauge over a run of sections: no_data, arms not open",
         &ClassificationRules::armsClosedFraction},
        {"arms_closed_min_sections", "... over at least this many sections",
         &ClassificationRules::armsClosedMinSections},
    };
    return kSettings;
}

void applyRuleSetting(ClassificationRules& rules, std::string_view assignment) {
    const std::size_t eq = assignment.find('=');
    const std::string_view name = assignment.substr(0, eq);
    for (const RuleSetting& s : ruleSettings()) {
        if (s.name != name) continue;
        double v = 0.0;
        const std::string text(eq == std::string_view::npos ? std::string_view()
                                                            : assignment.substr(eq + 1));
        if (!io::parseNumber(text, v) || !std::isfinite(v) || v < 0.0)
            throw std::invalid_argument("rule " + std::string(name) +
                                        ": expected a number >= 0, found '" + text + "'");
        rules.*s.field = v;
        return;
    }
    std::string known;
    for (const RuleSetting& s : ruleSettings())
        known += (known.empty() ? "" : ", ") + std::string(s.name);
    throw std::invalid_argument("unknown rule '" + std::string(name) +
                                "'; expected NAME=VALUE with NAME one of " + known);
}

std::string describeRules(const ClassificationRules& rules) {
    std::string out;
    char buf[160];
    for (const RuleSetting& s : ruleSettings()) {
        std::snprintf(buf, sizeof buf, "%s=%g (%.*s)\n", std::string(s.name).c_str(),
                      rules.*s.field, static_cast<int>(s.meaning.size()), s.meaning.data());
        out += buf;
    }
    return out;
}

}  // namespace caliper3d::reconstruction
