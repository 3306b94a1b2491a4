#include "reconstruction/analysis/rule_settings.h"

#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

using namespace caliper3d::reconstruction;

TEST(RuleSettingsTest, EverySettingSetsItsOwnFieldOnly) {
    std::vector<double ClassificationRules::*> fields;
    for (const RuleSetting& s : ruleSettings()) {
        ClassificationRules rules;
        const ClassificationRules defaults;
        applyRuleSetting(rules, std::string(s.name) + "=123.5");
        EXPECT_EQ(rules.*s.field, 123.5) << s.name;
        for (const RuleSetting& other : ruleSettings()) {
            if (other.field != s.field) {
                EXPECT_EQ(rules.*other.field, defaults.*other.field) << s.name;
            }
        }
        for (auto field : fields) EXPECT_NE(field, s.field) << s.name << " names a field twice";
        fields.push_back(s.field);
    }
    // One setting per threshold: every double of ClassificationRules is named.
    EXPECT_EQ(fields.size(), sizeof(ClassificationRules) / sizeof(double));
}

TEST(RuleSettingsTest, UnknownNameOrBadValueIsRefusedWithTheKnownNames) {
    ClassificationRules rules;
    try {
        applyRuleSetting(rules, "washout=12");
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("washout_mm"), std::string::npos) << e.what();
    }
    EXPECT_THROW(applyRuleSetting(rules, "washout_mm=abc"), std::invalid_argument);
    EXPECT_THROW(applyRuleSetting(rules, "washout_mm=-1"), std::invalid_argument);
    EXPECT_THROW(applyRuleSetting(rules, "washout_mm"), std::invalid_argument);
    applyRuleSetting(rules, "washout_mm=15,5");  // decimal comma, as everywhere in input
    EXPECT_EQ(rules.washout_mm, 15.5);
}

TEST(RuleSettingsTest, DescriptionListsDefaults) {
    const std::string text = describeRules(ClassificationRules{});
    EXPECT_NE(text.find("washout_mm=12.7 "), std::string::npos) << text;
    EXPECT_NE(text.find("min_breakout_length_m=1 "), std::string::npos) << text;
}
