#include "app/input_options.h"

#include <algorithm>
#include <cstdio>

#include "io/warnings_text.h"

namespace caliper3d::app {

namespace {

void addGroup(QCommandLineParser& parser, OptionGroup group) {
    for (const WellOption& option : wellOptions())
        if (option.group == group) parser.addOption({option.name, option.help, option.valueName});
}

// The options of `group` given once for every file (an option not given keeps the default).
void applyGroup(const QCommandLineParser& parser, OptionGroup group, LoadOptions& options) {
    WellSource none;
    for (const WellOption& option : wellOptions())
        if (option.group == group && parser.isSet(option.name))
            option.parse((option.repeatable ? parser.values(option.name).join(';')
                                            : parser.value(option.name))
                             .toStdString(),
                         none, options);
}

}  // namespace

void addInputOptions(QCommandLineParser& parser) {
    addGroup(parser, OptionGroup::Reading);
}

void addColourOptions(QCommandLineParser& parser) {
    addGroup(parser, OptionGroup::Colour);
}

void addWellSourceOptions(QCommandLineParser& parser) {
    addGroup(parser, OptionGroup::PerWell);
}

LoadOptions inputOptionsFrom(const QCommandLineParser& parser) {
    LoadOptions options;
    applyGroup(parser, OptionGroup::Reading, options);
    return options;
}

reconstruction::ColourRequest colourRequestFrom(const QCommandLineParser& parser) {
    LoadOptions options;
    applyGroup(parser, OptionGroup::Colour, options);
    return options.colour;
}

std::vector<WellSource> wellSourcesFrom(const QCommandLineParser& parser,
                                        const std::vector<std::string>& files) {
    const auto count = static_cast<int>(files.size());
    std::vector<WellSource> out(files.size());
    for (std::size_t i = 0; i < files.size(); ++i) out[i].path = files[i];
    if (parser.isSet("casing") && parser.isSet("casing-each"))
        throw UsageError(
            "--casing and --casing-each exclude each other: --casing gives one program for "
            "every file, --casing-each one for each");
    LoadOptions unused;
    for (const WellOption& option : wellOptions()) {
        if (option.group != OptionGroup::PerWell || !parser.isSet(option.name)) continue;
        const QStringList values = parser.values(option.name);
        if (values.size() != count)
            throw UsageError(std::string("--") + option.name + ": given " +
                             std::to_string(values.size()) + " times for " + std::to_string(count) +
                             " file(s); give it once per file, in order");
        for (int i = 0; i < count; ++i)
            option.parse(values[i].toStdString(), out[static_cast<std::size_t>(i)], unused);
    }
    return out;
}

void rejectInapplicable(const QCommandLineParser& parser, const std::string& verb,
                        std::initializer_list<OptionEffect> effects, const std::string& why) {
    const auto given =
        std::find_if(wellOptions().begin(), wellOptions().end(), [&](const WellOption& option) {
            return option.group == OptionGroup::Reading &&
                   std::find(effects.begin(), effects.end(), option.effect) != effects.end() &&
                   parser.isSet(option.name);
        });
    if (given != wellOptions().end())
        throw UsageError("caliper3d " + verb + ": --" + given->name + " does not apply: " + why);
}

void addSummaryOption(QCommandLineParser& parser) {
    parser.addOption({"summary",
                      "Also write one JSON object per input to this file, one a line: file, "
                      "status, error (file, line, reason), rows, depths, classes, zones, "
                      "volumes, warnings, seconds, peak memory (docs/formats.md, \"Summary "
                      "lines\").",
                      "FILE.jsonl"});
}

void printWarnings(const io::Diagnostics& diagnostics) {
    std::fputs(io::formatWarnings(diagnostics).c_str(), stderr);
}

}  // namespace caliper3d::app
