// The table every per-well option is declared in: each row reads back what it writes, every
// manifest column is one of its options, and the command line, manifest and option texts all
// go through it.
#include "app/well_option_table.h"

#include <algorithm>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/batch_manifest.h"

using namespace caliper3d;

namespace {

// Representative texts for each row, none of them the default: a row missing here fails
// EveryRowReadsBackWhatItWrites, so a new option comes with its values.
const std::map<std::string, std::vector<std::string>>& samples() {
    static const std::map<std::string, std::vector<std::string>> kSamples = {
        {"arms", {"2", "8", "256"}},
        {"depth-unit", {"m", "ft"}},
        {"radius-unit", {"in", "mm", "cm"}},
        {"radii", {"RAD1,RAD2,RAD3,RAD4", " R1 , R2 ", "RAD[]"}},
        {"diameters", {"CALI", "C1,C2,C3"}},
        {"row-step", {"0.0254", "2,5", "1e-3"}},
        {"file", {"2", "1", "17"}},
        {"nulls", {"declared"}},
        {"bit-size", {"8.5in", "215.9mm", "6.125", "21.59cm", "155.575mm"}},
        {"casing", {"88.3,7in,17lb/ft", "30,177.8mm,166.1mm;1200,9.625,47lb/ft", "100,7"}},
        {"pad-azimuth", {"P1AZ", "none"}},
        {"relative-bearing", {"RB", "IRBR"}},
        {"inclination", {"DEVI", "INCLINATION"}},
        {"hole-azimuth", {"HAZI", "none"}},
        {"picks", {"picks/breakouts.las", "/data/bo picks.csv"}},
        {"declination", {"14.38033", "-3.25", "0.1"}},
        {"grid-convergence", {"0.75", "-1.5"}},
        {"azimuth-north", {"true", "magnetic", "grid"}},
        {"points", {"3", "36", "1024"}},
        {"segment-length", {"2.5", "0.1"}},
        {"shape-tolerance", {"0.3", "100"}},
        {"exaggerate", {"37.5", "1000"}},
        {"steep-inclination", {"0", "22.25", "90"}},
        {"tool-reach", {"10in", "84.66666666666667mm"}},
        {"colour-by", {"GR", "ellipticity", " dls "}},
        {"colour-range", {"-10.125,13.333333333333334", "0,0.5"}},
        {"compare-with", {"run1.las", "/data/first run.las"}},
        {"survey", {"surveys/a survey.csv", "/data/-odd.csv"}},
        {"wellhead", {"512300.25,6801200.5,25.5", "0,0,-3", "1e6,-2.5,0"}},
        {"casing-each", {"88.3,7in,17lb/ft", "30,177.8mm,166.1mm;1200,9.625,47lb/ft"}},
    };
    return kSamples;
}

struct Parsed {
    app::WellSource well;
    app::LoadOptions options;
};

Parsed parse(const app::WellOption& option, const std::string& text) {
    Parsed out;
    option.parse(text, out.well, out.options);
    return out;
}

}  // namespace

TEST(WellOptionTableTest, EveryRowReadsBackWhatItWrites) {
    const Parsed defaults;
    for (const app::WellOption& option : app::wellOptions()) {
        SCOPED_TRACE(option.name);
        EXPECT_FALSE(option.format(defaults.well, defaults.options))
            << "the default is written as no option";
        const auto texts = samples().find(option.name);
        ASSERT_NE(texts, samples().end()) << "no representative values for --" << option.name;
        for (const std::string& text : texts->second) {
            SCOPED_TRACE(text);
            const Parsed x = parse(option, text);
            EXPECT_FALSE(x.well == defaults.well && x.options == defaults.options)
                << "the sample is the default";
            const std::optional<std::string> written = option.format(x.well, x.options);
            ASSERT_TRUE(written);
            const Parsed y = parse(option, *written);
            EXPECT_EQ(y.well, x.well);
            EXPECT_TRUE(y.options == x.options) << *written;
            EXPECT_EQ(option.format(y.well, y.options), written);
        }
    }
}

TEST(WellOptionTableTest, NamesAndColumnsAreUniqueAndEveryRowIsDescribed) {
    std::vector<std::string> names, columns;
    for (const app::WellOption& option : app::wellOptions()) {
        names.push_back(option.name);
        if (!option.column.empty()) columns.push_back(option.column);
        EXPECT_NE(std::string(option.help), "") << option.name;
        EXPECT_NE(std::string(option.valueName), "") << option.name;
        if (!option.field.empty()) {
            EXPECT_FALSE(option.blank.empty()) << option.name;
        }
        if (option.value == app::OptionValue::Choice) {
            EXPECT_FALSE(option.choices.empty());
        }
        if (option.value == app::OptionValue::Count) {
            EXPECT_LT(option.minCount, option.maxCount);
        }
        EXPECT_EQ(app::findWellOption(option.name), &option);
    }
    for (auto* list : {&names, &columns}) {
        std::sort(list->begin(), list->end());
        EXPECT_EQ(std::adjacent_find(list->begin(), list->end()), list->end());
    }
    EXPECT_EQ(app::findWellOption("no-such-option"), nullptr);
}

TEST(WellOptionTableTest, EveryManifestColumnIsTheBatchsOwnOrAnOptionOfTheTable) {
    const std::vector<std::string> own = {"file", "verb", "output", "options"};
    std::size_t options = 0;
    for (const std::string& column : app::manifestColumns()) {
        if (std::find(own.begin(), own.end(), column) != own.end()) continue;
        const auto option =
            std::find_if(app::wellOptions().begin(), app::wellOptions().end(),
                         [&column](const app::WellOption& o) { return o.column == column; });
        EXPECT_NE(option, app::wellOptions().end()) << column << " names no option";
        ++options;
    }
    const auto withColumn =
        std::count_if(app::wellOptions().begin(), app::wellOptions().end(),
                      [](const app::WellOption& o) { return !o.column.empty(); });
    EXPECT_EQ(options, static_cast<std::size_t>(withColumn));
}

TEST(WellOptionTableTest, AManifestRowPassesEachOptionCellToTheVerbsThatTakeIt) {
    // One row with a sample in every option column, as CSV.
    std::string header = "file,verb", row = "logs/w.las,info report render";
    for (const app::WellOption& option : app::wellOptions()) {
        if (option.column.empty()) continue;
        header += "," + option.column;
        row += ",\"" + samples().at(option.name).front() + "\"";
    }
    std::istringstream in(header + "\n" + row + "\n");
    const app::Manifest manifest = app::parseManifest("/field/m.csv", in);
    ASSERT_EQ(manifest.rows.size(), 1u);
    const app::ManifestRow& parsed = manifest.rows.front();
    EXPECT_EQ(parsed.problem, "");
    for (const std::string verb : {"info", "report", "render"}) {
        const std::vector<std::string> args = app::verbArguments(parsed, verb, "out/w.x", "");
        for (const app::WellOption& option : app::wellOptions()) {
            if (option.column.empty()) continue;
            SCOPED_TRACE(verb + " --" + option.name);
            const auto at = std::find(args.begin(), args.end(), std::string("--") + option.name);
            ASSERT_EQ(at != args.end(), app::takes(verb, option.group));
            if (at == args.end()) continue;
            const std::string& sample = samples().at(option.name).front();
            // Paths are the manifest folder's.
            EXPECT_EQ(*(at + 1),
                      option.value == app::OptionValue::Path ? "/field/" + sample : sample);
        }
    }
}

TEST(WellOptionTableTest, OptionTextsRoundTripAWellAndItsOptions) {
    app::WellSource well{"w.las", "/data/s.csv", reconstruction::Wellhead{1.5, -2.25, 3.0}, {}};
    app::LoadOptions options;
    options.read.armCount = 8;
    options.read.depthUnit = io::LengthUnit::Foot;
    options.read.roles.radii = {"RAD1", "RAD2", "RAD3"};
    options.read.bitSize_mm = 155.575;
    options.toolReach_mm = 254.0 / 3.0;
    options.colour.range = std::make_pair(-10.125, 40.0 / 3.0);
    const app::OptionTexts texts = app::optionTexts(well, options);
    EXPECT_EQ(texts.at("arms"), "8");
    EXPECT_EQ(texts.at("bit-size"), "155.575mm");
    EXPECT_EQ(texts.count("nulls"), 0u) << "a default is not written";
    app::WellSource backWell{"w.las", "", {}, {}};
    app::LoadOptions backOptions;
    app::applyOptionTexts(texts, backWell, backOptions);
    EXPECT_EQ(backWell, well);
    EXPECT_TRUE(backOptions == options);
    backOptions.read.armCount = 6;
    EXPECT_FALSE(backOptions == options);
}

TEST(WellOptionTableTest, OptionTextsKeepTheCommandLinesMessagesAndRefuseUnknownNames) {
    app::WellSource well;
    app::LoadOptions options;
    auto message = [&](const app::OptionTexts& texts) -> std::string {
        try {
            app::applyOptionTexts(texts, well, options);
        } catch (const app::UsageError& e) {
            return e.what();
        }
        return "";
    };
    EXPECT_EQ(message({{"bit-size", "eight"}}),
              "--bit-size: expected a positive length such as 8.5in or 215.9mm, found 'eight'");
    EXPECT_EQ(message({{"arms", "1"}}), "--arms: expected a whole number from 2 to 256");
    EXPECT_EQ(message({{"radii", "ONLYONE"}}),
              "--radii: expected 2 to 256 curve names separated by commas, or one array NAME[]");
    EXPECT_EQ(message({{"depth-unit", "yd"}}), "--depth-unit: unknown unit 'yd'");
    EXPECT_EQ(message({{"wellhead", "1,2"}}),
              "--wellhead: expected easting,northing,elevation in metres (three numbers with a "
              "decimal point), found '1,2'");
    EXPECT_EQ(message({{"bogus", "1"}}), "unknown option '--bogus'");
    EXPECT_EQ(message({{"bit-size", "  "}}), "") << "a blank text is no option";
}

TEST(WellOptionTableTest, UsageListsEveryOptionWithItsValue) {
    const std::string usage = app::optionsUsage();
    for (const app::WellOption& option : app::wellOptions())
        EXPECT_NE(usage.find(std::string("--") + option.name + " " + option.valueName),
                  std::string::npos)
            << option.name << "\n"
            << usage;
    std::istringstream lines(usage);
    for (std::string line; std::getline(lines, line);) EXPECT_LE(line.size(), 96u) << line;
}
