#include "app/manifest_wells.h"

namespace caliper3d::app {

namespace {

// The row's further options that are well options, as option texts: "--NAME VALUE" or
// "--NAME=VALUE" (a repeatable one may come again: its values joined by ';'). The others are
// for the batch's verbs (report's --step, export's --ascii): their names go to `ignored`, a
// word after one that is not an option taken as its value.
OptionTexts furtherOptions(const std::vector<std::string>& words,
                           std::vector<std::string>& ignored) {
    OptionTexts texts;
    for (std::size_t i = 0; i < words.size(); ++i) {
        const std::string& word = words[i];
        if (word.rfind("--", 0) != 0)
            throw UsageError("'" + word + "' in options: expected --NAME VALUE");
        std::string name = word.substr(2), value;
        const auto equals = name.find('=');
        const bool nextIsValue = i + 1 < words.size() && words[i + 1].rfind("--", 0) != 0;
        if (equals != std::string::npos) {
            value = name.substr(equals + 1);
            name.resize(equals);
        } else if (nextIsValue) {
            value = words[++i];
        }
        const WellOption* option = findWellOption(name);
        if (!option) {
            ignored.push_back("--" + name);
            continue;
        }
        if (value.empty()) throw UsageError("--" + name + " in options has no value");
        std::string& text = texts[name];
        if (text.empty() || !option->repeatable) {
            text = value;
        } else {
            text += ';';
            text += value;
        }
    }
    return texts;
}

}  // namespace

std::vector<ManifestWell> manifestWells(const Manifest& manifest, const LoadOptions& base) {
    std::vector<ManifestWell> wells;
    wells.reserve(manifest.rows.size());
    for (const ManifestRow& row : manifest.rows) {
        ManifestWell well;
        well.line = row.line;
        well.source.path = row.file;
        well.options = base;
        const std::string where = row.line > 0 ? "line " + std::to_string(row.line)
                                               : "row " + std::to_string(row.index + 1);
        if (!row.problem.empty()) {
            well.problem = where + ": " + row.problem;
        } else {
            try {
                applyOptionTexts(row.wellOptions, well.source, well.options);
                applyOptionTexts(furtherOptions(row.options, well.ignored), well.source,
                                 well.options);
            } catch (const UsageError& e) {
                well.problem = where + ": " + e.what();
            }
        }
        wells.push_back(std::move(well));
    }
    return wells;
}

}  // namespace caliper3d::app
