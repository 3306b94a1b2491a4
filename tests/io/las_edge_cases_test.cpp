// Walks every file of the LAS edge-case collection in ../shared/data: each is
// either read with the right curves and values or refused with a precise
// message. Skips when the folder is absent.
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include <gtest/gtest.h>

#include "io/log_reader.h"
#include "io/parse_error.h"
#include "support/curve_lookup.h"
#include "test_support.h"

using namespace caliper3d::io;

namespace {

std::filesystem::path edgeCases() {
    return caliper3d::test::sharedData() / "las_edge_cases";
}

LoadedLog load(const std::string& name) {
    return loadCaliperLog((edgeCases() / name).string(), ReadOptions{});
}

using caliper3d::test::curve;
using caliper3d::test::extra;

bool warned(const LogInfo& info, const std::string& text) {
    for (const Warning& w : info.diagnostics.warnings)
        if (w.message.find(text) != std::string::npos) return true;
    return false;
}

// The eight-curve lasio sample most files derive from, after sorting by depth.
void expectSample(const LoadedLog& log) {
    ASSERT_EQ(log.table.rowCount(), 3u);
    EXPECT_DOUBLE_EQ(log.table.depth_m.front(), 1669.75);
    EXPECT_DOUBLE_EQ(log.table.depth_m.back(), 1670.0);
    EXPECT_EQ(log.table.armCount, 0);  // no caliper in these files
    const ExtraCurve* sflu = extra(log.table, "SFLU");
    ASSERT_NE(sflu, nullptr);
    EXPECT_DOUBLE_EQ(sflu->values[0], 123.45);
    EXPECT_TRUE(warned(log.info, "log recorded upwards"));
}

}  // namespace

TEST(LasEdgeCasesTest, EveryFileIsReadOrRefusedPrecisely) {
    CALIPER3D_REQUIRE_DATA(edgeCases());
    // name -> what must hold
    std::set<std::string> checked;
    auto check = [&](const std::string& name) {
        checked.insert(name);
        SCOPED_TRACE(name);
        return load(name);
    };

    for (const char* name :
         {"sample_v_section_second.las", "sample_2.0_tab_dlm.las", "null_policy_9999.las",
          "null_policy_ERR.las", "null_policy_dashes.las", "comma_decimal_mark.las",
          "duplicate_step.las", "sample_duplicate_sections.las",
          "sample_sections_after_a_section.las", "encodings_utf16lebom.las",
          "mnemonic_duplicate.las", "sample_lastcolblanked.las"}) {
        SCOPED_TRACE(name);
        expectSample(check(name));
    }
    {
        const LoadedLog log = check("comma_decimal_mark.las");
        EXPECT_DOUBLE_EQ(extra(log.table, "SFLU")->values[1], 123.42);  // "123,420"
    }
    {
        const LoadedLog log = check("mnemonic_duplicate.las");
        ASSERT_NE(extra(log.table, "SFLU:2"), nullptr);
        EXPECT_DOUBLE_EQ(extra(log.table, "SFLU:2")->values[0], 125.45);
        EXPECT_DOUBLE_EQ(extra(log.table, "SFLU")->values[0], 123.45);
    }
    {
        const LoadedLog log = check("sample_lastcolblanked.las");
        // Row 1669.875 (the middle one after sorting) lost ILM and ILD to an overflow.
        EXPECT_TRUE(std::isnan(extra(log.table, "ILM")->values[1]));
        EXPECT_TRUE(std::isnan(extra(log.table, "ILD")->values[1]));
        EXPECT_DOUBLE_EQ(extra(log.table, "ILD")->values[0], 105.6);
        EXPECT_TRUE(warned(log.info, "field overflow"));
    }
    {
        const LoadedLog log = check("sample_duplicate_sections.las");
        EXPECT_TRUE(warned(log.info, "appears again"));
    }
    {
        const LoadedLog log = check("sample_sections_after_a_section.las");
        EXPECT_TRUE(warned(log.info, "'~T"));
    }
    // After sorting, row 0 is 1669.750 (DT 10000), row 1 1669.875 (DT 9999), row 2 1670.0 (DT
    // 9998).
    for (const char* name :
         {"null_policy_9999.las", "null_policy_ERR.las", "null_policy_dashes.las"}) {
        SCOPED_TRACE(name);
        const LoadedLog log = check(name);
        const ExtraCurve* dt = extra(log.table, "DT");
        EXPECT_DOUBLE_EQ(dt->values[0], 10000.0);
        EXPECT_TRUE(std::isnan(dt->values[1]));  // 9999 is a common null
        EXPECT_DOUBLE_EQ(dt->values[2], 9998.0);
        EXPECT_TRUE(std::isnan(extra(log.table, "SFLA")->values[0]));  // -999.25
        EXPECT_EQ(curve(log.info, "DT")->nulls, 1u);
    }
    {
        const LoadedLog log = check("null_policy_ERR.las");
        EXPECT_TRUE(std::isnan(extra(log.table, "RHOB")->values[0]));  // ERR
        EXPECT_EQ(curve(log.info, "RHOB")->nulls, 1u);
    }
    {
        const LoadedLog log = check("null_policy_dashes.las");
        const ExtraCurve* rhob = extra(log.table, "RHOB");
        EXPECT_TRUE(std::isnan(rhob->values[0]));    // "--"
        EXPECT_DOUBLE_EQ(rhob->values[1], -2550.0);  // a negative number, not a dash
        EXPECT_TRUE(std::isnan(rhob->values[2]));    // "-"
        EXPECT_EQ(curve(log.info, "RHOB")->nulls, 2u);
    }
    {
        // Under the declared policy, 9999 is a value, and ERR in a curve the reader does not
        // need is a value that is not a number: null, counted in a warning at its line.
        ReadOptions declared;
        declared.nullPolicy = NullPolicy::Declared;
        const LoadedLog log =
            loadCaliperLog((edgeCases() / "null_policy_9999.las").string(), declared);
        EXPECT_DOUBLE_EQ(extra(log.table, "DT")->values[1], 9999.0);
        const LoadedLog err =
            loadCaliperLog((edgeCases() / "null_policy_ERR.las").string(), declared);
        EXPECT_TRUE(std::isnan(extra(err.table, "RHOB")->values[0]));
        EXPECT_TRUE(warned(err.info, "curve RHOB: 1 value is not a number (the first 'ERR')"));
    }
    {
        const LoadedLog log = check("sample_rev.las");
        ASSERT_EQ(log.table.rowCount(), 11u);
        EXPECT_DOUBLE_EQ(log.table.depth_m.front(), 1660.0);
        EXPECT_DOUBLE_EQ(log.table.depth_m.back(), 1670.0);
        EXPECT_TRUE(warned(log.info, "log recorded upwards"));
    }
    {
        const LoadedLog log = check("sample_wrapped.las");
        EXPECT_EQ(log.info.format, "LAS 1.2, wrapped");
        ASSERT_EQ(log.table.rowCount(), 5u);
        EXPECT_EQ(log.info.curves.size(), 36u);
        EXPECT_DOUBLE_EQ(log.table.depth_m.back(), 910.0);
    }
    {
        const LoadedLog log = check("1001178549.las");  // a real Kansas file, wrapped, in feet
        EXPECT_EQ(log.info.format, "LAS 2.0, wrapped");
        EXPECT_EQ(log.info.depthUnit, "FT");
        EXPECT_GT(log.table.rowCount(), 0u);
    }
    {
        const LoadedLog log = check("welly_2.las");  // says WRAP YES, one line per depth
        EXPECT_EQ(log.table.rowCount(), 4u);
        EXPECT_DOUBLE_EQ(log.table.depth_m.front(), 1.0668);
    }
    {
        const LoadedLog log = check("excess_curves.las");
        EXPECT_EQ(log.table.rowCount(), 2u);
        EXPECT_NEAR(log.table.depth_m.front(), 19160.0 * 0.3048, 1e-9);
        EXPECT_TRUE(warned(log.info, "no data for ROP, TEMP"));
    }
    {
        const LoadedLog log = check("index_null.las");  // NULL equals a real depth: kept
        ASSERT_EQ(log.table.rowCount(), 3u);
        EXPECT_DOUBLE_EQ(log.table.depth_m[1], 999.25);
        EXPECT_TRUE(std::isnan(extra(log.table, "DT")->values[0]));  // 999.25 in DT is null
    }
    {
        const LoadedLog log = check("issue-264-dot-delimiter.las");
        EXPECT_NE(curve(log.info, "Cond."), nullptr);
        EXPECT_NE(curve(log.info, "I. Res."), nullptr);
        EXPECT_EQ(curve(log.info, "I. Res.")->unit, "OHM-M");
    }
    {
        const LoadedLog log = check("sample_3.0.las");
        EXPECT_EQ(log.info.format, "LAS 3.0");
        EXPECT_EQ(curve(log.info, "CDES")->role, "text (skipped)");
        ASSERT_NE(extra(log.table, "NMR[5]"), nullptr);
        EXPECT_DOUBLE_EQ(extra(log.table, "NMR[5]")->values[2], 13.0);  // top row after sorting
        EXPECT_DOUBLE_EQ(extra(log.table, "YME")->values[2], 1.45e12);
    }
    {
        checked.insert("missing_a_section.las");
        try {
            load("missing_a_section.las");
            ADD_FAILURE() << "missing_a_section.las: expected a refusal";
        } catch (const ParseError& e) {
            EXPECT_NE(std::string(e.what()).find("expected data rows after ~A"), std::string::npos)
                << e.what();
        }
    }
    {
        checked.insert("missing_well_curves_ascii_section.las");
        try {
            load("missing_well_curves_ascii_section.las");
            ADD_FAILURE() << "missing_well_curves_ascii_section.las: expected a refusal";
        } catch (const ParseError& e) {
            EXPECT_NE(std::string(e.what()).find("~C (curve information)"), std::string::npos)
                << e.what();
        }
    }
    // Every file of the folder was looked at.
    for (const auto& entry : std::filesystem::directory_iterator(edgeCases()))
        EXPECT_TRUE(checked.count(entry.path().filename().string()))
            << "not walked: " << entry.path();
}
