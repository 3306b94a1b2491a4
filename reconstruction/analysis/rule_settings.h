#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "reconstruction/analysis/borehole_classifier.h"

namespace caliper3d::reconstruction {

// The classification thresholds by name, as the command line sets them
// (`--rule washout_mm=15`): every field of ClassificationRules, named after
// the field with its unit.
struct RuleSetting {
    std::string_view name;
    std::string_view meaning;
    double ClassificationRules::*field;
};
const std::vector<RuleSetting>& ruleSettings();

// Sets one threshold from "NAME=VALUE". Throws std::invalid_argument naming
// the known settings when NAME is unknown, or when VALUE is not a finite
// number at least 0.
void applyRuleSetting(ClassificationRules& rules, std::string_view assignment);

// "name=value (meaning)" lines of every setting with its value in `rules`.
std::string describeRules(const ClassificationRules& rules);

}  // namespace caliper3d::reconstruction
