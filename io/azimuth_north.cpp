#include "io/azimuth_north.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <initializer_list>
#include <string>
#include <vector>

#include "io/curve_plan.h"
#include "io/diagnostics.h"
#include "io/las_header.h"
#include "io/number_parsing.h"
#include "io/text.h"

namespace caliper3d::io {

namespace {

// The words of `text`, upper case: runs of letters and digits.
std::vector<std::string> words(std::string_view text) {
    std::vector<std::string> out;
    std::string word;
    for (const char c : text) {
        if (std::isalnum(static_cast<unsigned char>(c))) {
            word += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        } else if (!word.empty()) {
            out.push_back(std::move(word));
            word.clear();
        }
    }
    if (!word.empty()) out.push_back(std::move(word));
    return out;
}

bool has(const std::vector<std::string>& w, std::initializer_list<const char*> any) {
    for (const std::string& word : w)
        for (const char* a : any)
            if (word == a) return true;
    return false;
}

// "declination" as logs spell it, misspellings included ("Magnetic Declanation: 13.39 EAST").
bool isDeclinationWord(const std::string& word) {
    return word.rfind("DECLINATION", 0) == 0 || word.rfind("DECLANATION", 0) == 0 ||
           word.rfind("DECLENATION", 0) == 0 || word.rfind("DECLINAT", 0) == 0;
}

bool mentionsDeclination(const std::vector<std::string>& w) {
    for (const std::string& word : w)
        if (isDeclinationWord(word)) return true;
    return false;
}

// A curve description without its LAS format hint ("{F14.5}") and surrounding blanks.
std::string shownDescription(std::string_view description) {
    const std::size_t brace = description.find('{');
    return std::string(trim(description.substr(0, brace)));
}

const LasItem* findItem(const LasHeader& h, std::initializer_list<const char*> mnemonics,
                        const char** section) {
    for (const char* m : mnemonics) {
        if (const LasItem* item = h.parameter(m)) {
            *section = "~Parameter";
            return item;
        }
        if (const LasItem* item = h.wellItem(m)) {
            *section = "~Well";
            return item;
        }
    }
    return nullptr;
}

// The first ~Well or ~Parameter item whose description names `what` (all of its words).
const LasItem* itemDescribed(const LasHeader& h, bool (*matches)(const std::vector<std::string>&),
                             const char** section) {
    for (const LasItem& item : h.parameters)
        if (matches(words(item.description))) {
            *section = "~Parameter";
            return &item;
        }
    for (const LasItem& item : h.well)
        if (matches(words(item.description))) {
            *section = "~Well";
            return &item;
        }
    return nullptr;
}

std::string itemSource(const LasItem& item, const char* section) {
    return item.mnemonic + " (" + section + ", line " + std::to_string(item.line) + ")";
}

// An angle item's value in degrees east: the value, or the value and its unit ("13.4 E"),
// in radians when the unit says so.
double itemAngle(const LasItem& item) {
    double deg = parseEastAngle(item.value);
    if (std::isnan(deg)) deg = parseEastAngle(item.value + " " + item.unit);
    if (!std::isnan(deg) && upper(trim(item.unit)).rfind("RAD", 0) == 0) deg *= 180.0 / M_PI;
    return deg;
}

HeaderAngle readAngle(const LasHeader& h, std::initializer_list<const char*> mnemonics,
                      bool (*described)(const std::vector<std::string>&), const char* what,
                      Diagnostics* diagnostics) {
    HeaderAngle out;
    const char* section = "";
    const LasItem* item = findItem(h, mnemonics, &section);
    if (!item) item = itemDescribed(h, described, &section);
    if (!item) return out;
    const double deg = itemAngle(*item);
    if (std::isnan(deg) || std::fabs(deg) > 180.0) {
        if (diagnostics && !trim(item->value).empty())
            diagnostics->warn(h.file, item->line,
                              std::string(what) + " " + item->mnemonic +
                                  ": expected an angle in degrees (east positive), found '" +
                                  item->value + "': not used");
        return out;
    }
    out.deg = deg;
    out.source = itemSource(*item, section);
    return out;
}

bool describesDeclination(const std::vector<std::string>& w) {
    return mentionsDeclination(w) && !has(w, {"APPLIED", "CORRECTED", "CORRECTION"});
}
bool describesConvergence(const std::vector<std::string>& w) {
    return has(w, {"CONVERGENCE"});
}
bool describesNorthReference(const std::vector<std::string>& w) {
    return (has(w, {"NORTH", "AZIMUTH", "AZI"}) && has(w, {"REFERENCE", "REF"})) ||
           (mentionsDeclination(w) && has(w, {"APPLIED", "CORRECTED", "CORRECTION"}));
}
bool describesLogDate(const std::vector<std::string>& w) {
    return has(w, {"DATE"}) && has(w, {"LOG", "LOGGING", "RUN"});
}

// A declination in the ~Other text: "7) Magnetic Declanation: 13.39  EAST".
HeaderAngle otherDeclination(const LasHeader& h) {
    HeaderAngle out;
    forEachTrimmedLine(h.other, 1, [&](std::string_view line, std::size_t) {
        const std::vector<std::string> w = words(line);
        if (!mentionsDeclination(w) || has(w, {"APPLIED", "CORRECTED"})) return true;
        // The text after the word: the first number there and its direction.
        const std::string up = upper(line);
        std::size_t at = std::string::npos;
        for (const char* spelling : {"DECLINAT", "DECLANAT", "DECLENAT"})
            at = std::min(at, up.find(spelling));
        std::size_t digit = up.find_first_of("+-0123456789", at);
        if (digit == std::string::npos) return true;
        const double deg = parseEastAngle(line.substr(digit));
        if (std::isnan(deg) || std::fabs(deg) > 180.0) return true;
        out.deg = deg;
        out.source = "~Other: '" + std::string(line) + "'";
        return false;
    });
    return out;
}

const char* const kMonths[12] = {"JAN", "FEB", "MAR", "APR", "MAY", "JUN",
                                 "JUL", "AUG", "SEP", "OCT", "NOV", "DEC"};

int monthOf(const std::string& word) {
    if (word.size() < 3) return 0;
    for (int m = 0; m < 12; ++m)
        if (word.compare(0, 3, kMonths[m]) == 0) return m + 1;
    return 0;
}

bool isLeap(int y) {
    return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
}

double fractionalYear(int year, int month, int day) {
    static const int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    if (year < 1900 || year > 2100 || month < 1 || month > 12) return std::nan("");
    const int inMonth = kDays[month - 1] + (month == 2 && isLeap(year) ? 1 : 0);
    if (day < 1 || day > inMonth) return std::nan("");
    int dayOfYear = day;
    for (int m = 1; m < month; ++m) dayOfYear += kDays[m - 1] + (m == 2 && isLeap(year) ? 1 : 0);
    return year + (dayOfYear - 0.5) / (isLeap(year) ? 366.0 : 365.0);
}

int fullYear(int y, std::size_t digits) {
    if (digits == 2) return y < 70 ? 2000 + y : 1900 + y;
    return digits == 4 ? y : -1;
}

bool allDigits(const std::string& s) {
    if (s.empty()) return false;
    for (const char c : s)
        if (!std::isdigit(static_cast<unsigned char>(c))) return false;
    return true;
}

}  // namespace

const char* northName(North north) {
    switch (north) {
        case North::True:
            return "true north";
        case North::Magnetic:
            return "magnetic north";
        case North::Grid:
            return "grid north";
        case North::Unknown:
            break;
    }
    return "unknown north";
}

North parseNorthWord(std::string_view word) {
    const std::string w = lower(trim(word));
    if (w == "true") return North::True;
    if (w == "magnetic") return North::Magnetic;
    if (w == "grid") return North::Grid;
    return North::Unknown;
}

North northFromText(std::string_view text) {
    const std::vector<std::string> w = words(text);
    // "corrected for magnetic declination", "declination applied": from true north, unless
    // the text says it is not ("uncorrected", "declination not applied").
    if (mentionsDeclination(w) && has(w, {"CORRECTED", "APPLIED"}))
        return has(w, {"NOT", "UNCORRECTED", "NO", "WITHOUT"}) ? North::Magnetic : North::True;
    const bool isTrue = has(w, {"TRUE", "GEOGRAPHIC", "GEOGRAPHICAL", "TN"});
    const bool magnetic = has(w, {"MAGNETIC", "MAG", "MN"});
    const bool grid = has(w, {"GRID", "GN"});
    if (isTrue + magnetic + grid != 1) return North::Unknown;
    return isTrue ? North::True : magnetic ? North::Magnetic : North::Grid;
}

double parseEastAngle(std::string_view text) {
    const std::vector<std::string_view> parts = splitBlank(trim(text));
    if (parts.empty()) return std::nan("");
    std::string number(parts[0]);
    std::string direction;
    // "13.39E", "5.2W": a direction letter glued to the number.
    while (!number.empty() && std::isalpha(static_cast<unsigned char>(number.back()))) {
        direction.insert(direction.begin(), number.back());
        number.pop_back();
    }
    double value = 0.0;
    if (!parseNumber(number, value) || !std::isfinite(value)) return std::nan("");
    std::size_t next = 1;
    if (direction.empty() && parts.size() > 1) direction = std::string(parts[next++]);
    const std::string d = upper(direction);
    if (d == "W" || d == "WEST") return -std::fabs(value);
    if (d == "E" || d == "EAST") return std::fabs(value);
    if (d.empty() || d == "DEG" || d == "DEGREES" || d == "DEGREE" || d == "RAD") return value;
    return std::nan("");
}

double parseLogYear(std::string_view text) {
    std::string t = upper(trim(text));
    for (char& c : t)
        if (c == '/' || c == '-' || c == '.' || c == ',' || c == '_') c = ' ';
    std::vector<std::string> f;
    for (std::string_view p : splitBlank(t)) f.emplace_back(p);
    if (f.empty()) return std::nan("");
    auto number = [](const std::string& s) { return std::atoi(s.c_str()); };
    if (f.size() >= 3 && allDigits(f[0]) && f[0].size() == 4 && allDigits(f[1]) &&
        allDigits(f[2]))  // 2014/02/23
        return fractionalYear(number(f[0]), number(f[1]), number(f[2]));
    if (f.size() >= 3 && allDigits(f[0]) && monthOf(f[1]) && allDigits(f[2]))  // 23-Feb-2014
        return fractionalYear(fullYear(number(f[2]), f[2].size()), monthOf(f[1]), number(f[0]));
    if (f.size() >= 3 && monthOf(f[0]) && allDigits(f[1]) && allDigits(f[2]))  // Feb 23 2014
        return fractionalYear(fullYear(number(f[2]), f[2].size()), monthOf(f[0]), number(f[1]));
    if (f.size() >= 3 && allDigits(f[0]) && allDigits(f[1]) && allDigits(f[2]) &&
        f[0].size() <= 2 && f[1].size() <= 2) {  // 23/02/2014, 02/23/2014
        const int a = number(f[0]), b = number(f[1]);
        const int year = fullYear(number(f[2]), f[2].size());
        return a > 12 || b <= 12 ? fractionalYear(year, b, a) : fractionalYear(year, a, b);
    }
    if (f.size() >= 2 && monthOf(f[0]) && allDigits(f[1]) && f[1].size() == 4)  // FEB 2014
        return fractionalYear(number(f[1]), monthOf(f[0]), 15);
    if (allDigits(f[0]) && f[0].size() == 8)  // 20140223
        return fractionalYear(number(f[0].substr(0, 4)), number(f[0].substr(4, 2)),
                              number(f[0].substr(6, 2)));
    if (f.size() == 1 && allDigits(f[0]) && f[0].size() == 4)  // 2014
        return fractionalYear(number(f[0]), 7, 2);
    return std::nan("");
}

AzimuthNorth readAzimuthNorth(const LasHeader* header, const std::vector<ColumnSpec>& columns,
                              const CurvePlan& plan, Diagnostics* diagnostics) {
    AzimuthNorth out;
    static const struct {
        int angle;
        const char* role;
    } kAzimuths[] = {{0, "pad-1 azimuth"}, {2, "hole azimuth"}};
    for (const auto& a : kAzimuths) {
        const int column = plan.angleColumn[a.angle];
        if (column < 0 || static_cast<std::size_t>(column) >= columns.size()) continue;
        CurveNorth curve;
        curve.mnemonic = columns[static_cast<std::size_t>(column)].mnemonic;
        curve.role = a.role;
        curve.angle = a.angle;
        const std::string description =
            shownDescription(columns[static_cast<std::size_t>(column)].description);
        curve.north = northFromText(description);
        if (curve.north != North::Unknown) {
            curve.stated = true;
            curve.evidence = "its description '" + description + "'";
        } else if (!header) {
            // Column text has no descriptions: its azimuths are from true north by the
            // format's convention (docs/formats.md, "Column text"); --azimuth-north overrides.
            curve.north = North::True;
            curve.evidence = "the column-text convention";
        }
        out.curves.push_back(std::move(curve));
    }
    if (header) {
        const LasHeader& h = *header;
        const char* section = "";
        const LasItem* reference = findItem(
            h, {"AZREF", "AZIREF", "AZMREF", "NREF", "NORTHREF", "NORTH_REF", "AZRF", "HAZIREF"},
            &section);
        if (!reference) reference = itemDescribed(h, describesNorthReference, &section);
        if (reference) {
            North n = northFromText(reference->value);
            if (n == North::Unknown)
                n = northFromText(reference->description + " " + reference->value);
            if (n != North::Unknown) {
                out.headerNorth = n;
                out.headerNorthSource = itemSource(*reference, section) + " '" +
                                        std::string(trim(reference->value)) + "'";
            }
        }
        out.declination = readAngle(h,
                                    {"MDEC", "DECL", "MAGDEC", "MAGDECL", "MDECL", "DEC", "MAGD",
                                     "MGDC", "DECLINATION", "MAG_DEC", "DECLIN"},
                                    describesDeclination, "magnetic declination", diagnostics);
        if (!out.declination.found()) out.declination = otherDeclination(h);
        out.convergence = readAngle(
            h, {"GRIDCONV", "GCONV", "GRIDC", "GRCONV", "GRID_CONV", "CONVERGENCE", "CONV"},
            describesConvergence, "grid convergence", diagnostics);
        const LasItem* date =
            findItem(h, {"DATE", "LDAT", "LOGDATE", "RUNDATE", "RDAT", "DLAB", "DATE1"}, &section);
        if (!date) date = itemDescribed(h, describesLogDate, &section);
        if (date) {
            out.logYear = parseLogYear(date->value);
            if (!std::isnan(out.logYear))
                out.dateSource = date->mnemonic + " " + std::string(trim(date->value)) + " (" +
                                 section + ", line " + std::to_string(date->line) + ")";
        }
    }
    // A curve whose description does not say takes the header's azimuth reference, else
    // the north the log's other azimuth curve states (one tool, one orientation frame).
    for (CurveNorth& curve : out.curves) {
        if (curve.north != North::Unknown) continue;
        if (out.headerNorth != North::Unknown) {
            curve.north = out.headerNorth;
            curve.evidence = "the header's " + out.headerNorthSource;
            continue;
        }
        for (const CurveNorth& other : out.curves)
            if (&other != &curve && other.stated) {
                curve.north = other.north;
                curve.evidence = "as " + other.mnemonic + ", the log's other azimuth";
            }
    }
    return out;
}

}  // namespace caliper3d::io
