#include "io/las_header.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <utility>

#include "io/number_parsing.h"
#include "io/parse_error.h"
#include "io/text.h"

namespace caliper3d::io {

namespace {

enum class Section { Version, Well, Curves, Parameters, Other, Data, Ignored };

// Section kinds by name: LAS 2.0 uses the first letter (~V ~W ~C ~P ~O ~A);
// LAS 3.0 names groups (~Log_Parameter, ~Log_Definition, ~Log_Data) and
// adds others (~Drilling_*, ~Core_*, ...) that a caliper reader skips.
Section classify(std::string_view title) {
    // Only the first word names the section: "~A  DEPT  P1NO_FBST ..." lists
    // curve names after it, "~Log_Data | Log_Definition" an association.
    std::string name = lower(trim(title.substr(1)));
    const std::size_t end = name.find_first_of(" \t|");
    if (end != std::string::npos) name.resize(end);
    if (name.rfind("log_parameter", 0) == 0 || name.rfind("parameter", 0) == 0)
        return Section::Parameters;
    if (name.rfind("log_definition", 0) == 0 || name.rfind("curve", 0) == 0) return Section::Curves;
    if (name.rfind("log_data", 0) == 0 || name.rfind("ascii", 0) == 0) return Section::Data;
    // Any other LAS 3.0 group (~Core_Data, ~Perforations_Definition, ...) is not a log.
    if (name.find('_') != std::string::npos) return Section::Ignored;
    switch (name.empty() ? '\0' : name.front()) {
        case 'v':
            return Section::Version;
        case 'w':
            return Section::Well;
        case 'c':
            return Section::Curves;
        case 'p':
            return Section::Parameters;
        case 'o':
            return Section::Other;
        case 'a':
            return Section::Data;
        default:
            return Section::Ignored;
    }
}

const LasItem* find(const std::vector<LasItem>& items, std::string_view mnemonic) {
    const std::string wanted = upper(mnemonic);
    for (const LasItem& item : items)
        if (upper(item.mnemonic) == wanted) return &item;
    return nullptr;
}

}  // namespace

bool isLasDataTitle(std::string_view title) {
    return classify(title) == Section::Data;
}

const LasItem* LasHeader::wellItem(std::string_view mnemonic) const {
    return find(well, mnemonic);
}
const LasItem* LasHeader::parameter(std::string_view mnemonic) const {
    return find(parameters, mnemonic);
}

bool splitLasItem(std::string_view line, LasItem& item, bool curveLine) {
    // The description follows the last colon (LAS 2.0, section 5.4); a line
    // without one has no description.
    std::string_view left = line;
    std::string_view description;
    const std::size_t colon = line.rfind(':');
    if (colon != std::string_view::npos) {
        left = line.substr(0, colon);
        description = line.substr(colon + 1);
    }
    left = trim(left);
    // A mnemonic written with a leading period (".ILM .OHMM") is read without
    // it, as lasio reads it; a lone period is the separator of a nameless item.
    if (left.size() > 1 && left.front() == '.' && left.find('.', 1) != std::string_view::npos)
        left.remove_prefix(1);
    // Mnemonic and unit are split by the first '.', except that a curve's
    // mnemonic may itself end in a dot ("Cond..MS/M", "I. Res..OHM-M"): then
    // the split is at the second dot of the first ".." that follows a
    // non-blank. "DEPT  ..1IN" is DEPT in the unit ".1IN" (lasio's rule).
    std::size_t dot = std::string_view::npos;
    if (curveLine) {
        const std::size_t twin = left.find("..");
        if (twin != std::string_view::npos && twin > 0 &&
            !std::isspace(static_cast<unsigned char>(left[twin - 1])))
            dot = twin + 1;
    }
    if (dot == std::string_view::npos) dot = left.find('.');
    if (dot == std::string_view::npos) return false;
    item.mnemonic = std::string(trim(left.substr(0, dot)));
    std::string_view rest = left.substr(dot + 1);
    std::size_t unitEnd = 0;
    while (unitEnd < rest.size() && !std::isspace(static_cast<unsigned char>(rest[unitEnd])))
        ++unitEnd;
    item.unit = std::string(rest.substr(0, unitEnd));
    item.value = std::string(trim(rest.substr(unitEnd)));
    std::string_view d = trim(description);
    // LAS 3.0: "{F}" format and "| association" ride in the description.
    const std::size_t bar = d.find('|');
    if (bar != std::string_view::npos) d = trim(d.substr(0, bar));
    item.description = std::string(d);
    return true;
}

namespace {

// "~A DEPTH DT ..." names the columns; LAS 3.0 "~Log_Data | Log_Definition" does not.
std::vector<std::string> dataTitleNames(std::string_view line) {
    std::string_view names = line.substr(1);
    std::size_t first = 0;
    while (first < names.size() && !std::isspace(static_cast<unsigned char>(names[first]))) ++first;
    names = names.substr(first);
    std::vector<std::string> out;
    if (names.find('|') != std::string_view::npos) return out;
    std::size_t i = 0;
    while (i < names.size()) {
        while (i < names.size() && std::isspace(static_cast<unsigned char>(names[i]))) ++i;
        std::size_t j = i;
        while (j < names.size() && !std::isspace(static_cast<unsigned char>(names[j]))) ++j;
        if (j > i) out.emplace_back(names.substr(i, j - i));
        i = j;
    }
    return out;
}

// The version, wrap, delimiter and null items, once the sections are read.
template <typename Warn>
void readVersionAndNull(LasHeader& header, const Warn& warn) {
    const std::string& file = header.file;
    if (const LasItem* vers = find(header.versionItems, "VERS")) {
        double v = 0.0;
        if (parseNumber(vers->value, v))
            header.version = v;
        else
            warn(vers->line, "VERS '" + vers->value + "' is not a number; reading as LAS 2.0");
    } else {
        warn(1, "no VERS item; reading as LAS 2.0");
    }
    if (header.version < 2.0) {
        // LAS 1.2 writes a ~W item's value after the colon, its description
        // before it ("WELL.  WELL: ANY ET AL OIL WELL #12"), except STRT,
        // STOP, STEP and NULL (LAS 1.2, section 3.2; lasio reads it so).
        for (LasItem& item : header.well) {
            const std::string m = upper(item.mnemonic);
            if (m == "STRT" || m == "STOP" || m == "STEP" || m == "NULL") continue;
            if (!item.description.empty()) std::swap(item.value, item.description);
        }
    }
    if (const LasItem* wrap = find(header.versionItems, "WRAP"))
        header.wrap = upper(wrap->value) == "YES";
    if (const LasItem* dlm = find(header.versionItems, "DLM")) {
        const std::string d = upper(dlm->value);
        if (d == "COMMA")
            header.delimiter = ',';
        else if (d == "TAB")
            header.delimiter = '\t';
        else if (d == "SPACE" || d.empty())
            header.delimiter = ' ';
        else
            throw ParseError(file, dlm->line, 1,
                             "expected DLM SPACE, TAB or COMMA, found '" + dlm->value + "'");
    }
    if (const LasItem* nulls = header.parameter("NULLS"))
        header.onlyDeclaredNull = upper(nulls->value) == "DECLARED";
    if (const LasItem* null = header.wellItem("NULL")) {
        double v = 0.0;
        if (parseNumber(null->value, v)) {
            header.hasNull = true;
            header.null = v;
        } else if (!null->value.empty()) {
            warn(null->line,
                 "NULL '" + null->value + "' is not a number; using the common null values");
        }
    }
}

// One item line of a header section, stored in its section's list. Outside ~C a line that
// is not an item is skipped with a warning; inside ~C it is refused.
template <typename Warn>
void addItem(LasHeader& header, Section section, std::string_view line, std::size_t lineNumber,
             const Warn& warn) {
    const std::string& file = header.file;
    LasItem item;
    item.line = lineNumber;
    if (!splitLasItem(line, item, section == Section::Curves)) {
        // Outside ~C a bad line can be skipped safely; inside, every later
        // column would shift onto the wrong curve.
        if (section != Section::Curves) {
            warn(lineNumber, "header line without 'MNEM.UNIT' skipped: '" +
                                 std::string(line.substr(0, 60)) + "'");
            return;
        }
        throw ParseError(file, lineNumber, 1,
                         "expected a header line 'MNEM.UNIT VALUE : DESCRIPTION', found '" +
                             std::string(line.substr(0, 60)) + "'");
    }
    if (line.size() > 1 && line.front() == '.' && !item.mnemonic.empty())
        warn(lineNumber, "mnemonic '" + item.mnemonic +
                             "' is written with a leading period; read as '" + item.mnemonic + "'");
    switch (section) {
        case Section::Version:
            header.versionItems.push_back(item);
            break;
        case Section::Well:
            header.well.push_back(item);
            break;
        case Section::Curves:
            header.curves.push_back(item);
            break;
        case Section::Parameters:
            header.parameters.push_back(item);
            break;
        default:
            break;
    }
}

}  // namespace

LasHeader parseLasHeader(std::string_view text, const std::string& file, Diagnostics* diagnostics) {
    LasHeader header;
    header.file = file;
    if (text.size() >= 2 && ((static_cast<unsigned char>(text[0]) == 0xFF &&
                              static_cast<unsigned char>(text[1]) == 0xFE) ||
                             (static_cast<unsigned char>(text[0]) == 0xFE &&
                              static_cast<unsigned char>(text[1]) == 0xFF)))
        throw ParseError(file, 1, 1,
                         "expected LAS text in ASCII or UTF-8, found UTF-16 (convert it first)");
    if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);

    auto warn = [&](std::size_t line, std::string message) {
        if (diagnostics) diagnostics->warn(file, line, std::move(message));
    };

    Section section = Section::Ignored;
    bool inData = false;
    bool seen[7] = {false, false, false, false, false, false, false};
    bool skipping = false;  // inside a repeated section, ignored
    bool sawSection = false;
    std::size_t pos = 0, lineNumber = 0;
    while (pos < text.size()) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = text.size();
        const std::size_t lineStart = pos;
        std::string_view raw = text.substr(pos, end - pos);
        pos = end + 1;
        ++lineNumber;
        if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
        const std::string_view line = trim(raw);

        if (!line.empty() && line.front() == '~') {
            if (inData) {
                header.dataEnd = lineStart;
                inData = false;
            }
            sawSection = true;
            section = classify(line);
            const int index = static_cast<int>(section);
            skipping = false;
            if (section == Section::Ignored) {
                warn(lineNumber,
                     "section '" + std::string(line) + "' is not used by caliper3d; skipped");
                continue;
            }
            if (seen[index]) {
                warn(lineNumber,
                     "section '" + std::string(line) + "' appears again; the first one is used");
                skipping = true;
                continue;
            }
            seen[index] = true;
            if (section == Section::Data) {
                header.hasData = true;
                inData = true;
                header.dataBegin = std::min(pos, text.size());
                header.dataEnd = text.size();
                header.dataFirstLine = lineNumber + 1;
                header.dataNames = dataTitleNames(line);
            }
            continue;
        }
        if (inData || skipping) continue;
        if (!sawSection) {
            if (line.empty() || line.front() == '#') continue;
            throw ParseError(file, lineNumber, 1,
                             "expected a LAS section such as ~VERSION, found '" +
                                 std::string(line.substr(0, 40)) + "'");
        }
        if (line.empty() || line.front() == '#') continue;
        if (section == Section::Other) {
            header.other += std::string(line) + "\n";
            continue;
        }
        if (section == Section::Ignored) continue;
        addItem(header, section, line, lineNumber, warn);
    }
    if (!sawSection)
        throw ParseError(file, 1, 1,
                         "expected a LAS file (sections starting with '~'), found none");

    readVersionAndNull(header, warn);
    return header;
}

}  // namespace caliper3d::io
