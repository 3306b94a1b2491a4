#pragma once

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/log_info.h"
#include "reconstruction/load/load_well.h"

namespace caliper3d::app {

// A well's options, declared once (PDAL's Stage::addArgs): the command line's options and
// help, the batch manifest's columns, the Open dialog's fields, recent files and the child
// processes' arguments are all made from this table, so adding a per-well option is one row
// here plus its line in the docs. No Qt: the manifest reader and its fuzzer use it too.

using reconstruction::LoadOptions;
using reconstruction::WellSource;

// Thrown for bad command-line usage (exit status 2).
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Which verbs take an option, and how often.
enum class OptionGroup {
    Reading,  // how the logs are read and the wells shaped: once, for every file
    Colour,   // what the wall is coloured by: once, by the verbs that draw
    PerWell,  // once per FILE, in the order of the files (or not at all)
};

// What an option changes: a verb refuses the options it cannot use rather than ignore them.
enum class OptionEffect {
    Log,       // how the log is read (info describes the file as read)
    Geometry,  // how the well is reconstructed (report measures it)
    Picture,   // how it is drawn: level of detail, exaggeration, colouring
};

// What a value looks like, where a reader or a form must know it.
enum class OptionValue {
    Text,
    Path,       // a manifest resolves it against its folder; the Open dialog offers Browse
    CommaList,  // items separated by commas; a JSON manifest may give an array
    Count,      // a whole number from minCount to maxCount (a spin box)
    Choice,     // one of `choices` (a combo box)
};

struct WellOption {
    const char* name = "";       // --NAME on the command line; the key of OptionTexts
    const char* valueName = "";  // what the help calls the value
    OptionGroup group = OptionGroup::Reading;
    const char* help = "";
    // Applies the option's text to a well; throws UsageError ("--NAME: ...") when malformed.
    void (*parse)(const std::string& text, WellSource& well, LoadOptions& options) = nullptr;
    // The text that parses back to the well's value; nullopt where the value is the default
    // (the option not given).
    std::optional<std::string> (*format)(const WellSource& well,
                                         const LoadOptions& options) = nullptr;

    OptionEffect effect = OptionEffect::Log;
    OptionValue value = OptionValue::Text;
    std::vector<std::string> choices;  // Choice
    int minCount = 0, maxCount = 0;    // Count
    std::string column;                // the batch manifest's column (and JSON key); "" none
    std::string field;                 // the Open dialog's label; "" not shown there
    std::string blank;                 // what an empty field means (the dialog's placeholder)
    // What an empty field means for a file described (the dialog's placeholder once the
    // file is read); nullptr: `blank`.
    std::string (*blankFor)(const io::LogInfo& info) = nullptr;
    bool columnTextOnly = false;  // read from column text only (a LAS names its curves)
    // May be given several times on the command line: the values reach `parse` as one text,
    // joined by ';' (how a manifest cell or the Open dialog writes several).
    bool repeatable = false;
};

// Every option, in the order the help lists them.
const std::vector<WellOption>& wellOptions();
// The row of --NAME; nullptr when there is none.
const WellOption* findWellOption(const std::string& name);
// The verbs that take the options of `group` (the help of each lists them).
const std::vector<std::string>& verbsTaking(OptionGroup group);
bool takes(const std::string& verb, OptionGroup group);

// A well's options as text by option name ("bit-size" -> "8.5in"): the Open dialog's fields,
// a recent file, a manifest row's cells. Options not given are absent (or empty).
using OptionTexts = std::map<std::string, std::string>;

// Applies `texts` in the table's order; an empty (or blank) text is no option. Throws
// UsageError for a malformed value, with the command line's message, or an unknown name.
void applyOptionTexts(const OptionTexts& texts, WellSource& well, LoadOptions& options);
// The texts of every option whose value is not the default: applyOptionTexts gives back
// `well` and `options` (but the well's path) as far as the table holds them.
OptionTexts optionTexts(const WellSource& well, const LoadOptions& options);

// The options for `caliper3d help`: the Reading and PerWell options on "common:" lines,
// the Colour ones on a line naming the verbs that draw, each "--NAME VALUE", 96 columns.
std::string optionsUsage();

// A length such as "8.5in", "215.9mm" or "21.59cm" (a bare number is inches),
// in millimetres; throws UsageError naming `option` unless it is positive.
double parseLength_mm(const std::string& text, const std::string& option);
// "E,N,ELEV" in metres; throws UsageError.
reconstruction::Wellhead parseWellhead(const std::string& text);

}  // namespace caliper3d::app
