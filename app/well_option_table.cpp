#include "app/well_option_table.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "io/casing_program.h"
#include "io/curve_roles.h"
#include "io/number_parsing.h"
#include "io/section_table.h"
#include "io/units.h"

namespace caliper3d::app {

namespace {

using Parse = void (*)(const std::string&, WellSource&, LoadOptions&);
using Format = std::optional<std::string> (*)(const WellSource&, const LoadOptions&);

const LoadOptions kDefaults;

std::string trimmed(const std::string& text) {
    const auto first = text.find_first_not_of(" \t\r\n");
    if (first == std::string::npos) return "";
    return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

// The shortest text that reads back to the same double, whatever the locale.
std::string exact(double value) {
    char buffer[32];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

std::string fixed(double value, int decimals) {
    char buffer[64];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value,
                                             std::chars_format::fixed, decimals)
                                   .ptr);
}

double number(const std::string& text, const char* option) {
    double v = 0.0;
    if (!io::parseNumber(text, v) || !std::isfinite(v))
        throw UsageError(std::string("--") + option + ": expected a number, found '" + text + "'");
    return v;
}

int wholeNumber(const std::string& text, const char* option, int lo, int hi) {
    const double v = number(text, option);
    if (v < lo || v > hi || v != std::floor(v))
        throw UsageError(std::string("--") + option + ": expected a whole number from " +
                         std::to_string(lo) + " to " + std::to_string(hi));
    return static_cast<int>(v);
}

io::LengthUnit unit(const std::string& text, const char* option) {
    auto u = io::parseLengthUnit(text);
    if (!u) throw UsageError(std::string("--") + option + ": unknown unit '" + text + "'");
    return *u;
}

std::optional<std::string> unitText(const std::optional<io::LengthUnit>& unit) {
    if (!unit) return std::nullopt;
    return std::string(io::unitName(*unit));
}

// Items between commas, each trimmed; empty ones (",,") left out.
std::vector<std::string> names(const std::string& text) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        if (comma > start) out.push_back(trimmed(text.substr(start, comma - start)));
        start = comma + 1;
    }
    return out;
}

std::optional<std::string> joined(const std::vector<std::string>& items) {
    if (items.empty()) return std::nullopt;
    std::string out;
    for (const std::string& item : items) out += (out.empty() ? "" : ",") + item;
    return out;
}

// A double option with a default: its text only where it differs.
std::optional<std::string> unlessDefault(double value, double byDefault) {
    if (value == byDefault) return std::nullopt;
    return exact(value);
}

std::string bitSizeText(double mm) {
    return fixed(mm, 1) + " mm (" + fixed(mm / 25.4, 3) + " in)";
}

// One orientation curve named by --NAME (a member of RoleOverrides): a single curve name,
// or "none" where the log has no usable such curve.
template <std::string io::RoleOverrides::*Member, const char* Name>
void parseCurveName(const std::string& text, WellSource&, LoadOptions& o) {
    const std::string name = trimmed(text);
    if (name.empty() || name.find_first_of(", \t") != std::string::npos)
        throw UsageError(std::string("--") + Name +
                         ": expected one curve name (or 'none'), found '" + text + "'");
    o.read.roles.*Member = name;
}

template <std::string io::RoleOverrides::*Member>
std::optional<std::string> formatCurveName(const WellSource&, const LoadOptions& o) {
    const std::string& name = o.read.roles.*Member;
    if (name.empty()) return std::nullopt;
    return name;
}

// The curve the reader chose for `role`, as the Open dialog's placeholder.
template <io::CurveRole Role>
std::string detectedCurve(const io::LogInfo& info) {
    for (const io::CurveInfo& c : info.curves)
        if (c.role == io::roleName(Role)) return "detected: " + c.mnemonic;
    return "none in the log";
}

constexpr char kPadAzimuth[] = "pad-azimuth";
constexpr char kRelativeBearing[] = "relative-bearing";
constexpr char kInclination[] = "inclination";
constexpr char kHoleAzimuth[] = "hole-azimuth";

// The rows under construction; a row is finished through the reference add returns.
struct Rows {
    std::vector<WellOption> list;
    WellOption& add(const char* name, const char* valueName, OptionGroup group, const char* help,
                    Parse parse, Format format) {
        WellOption& row = list.emplace_back();
        row.name = name;
        row.valueName = valueName;
        row.group = group;
        row.help = help;
        row.parse = parse;
        row.format = format;
        return row;
    }
    WellOption& back() { return list.back(); }
};
using G = OptionGroup;

// Which curves hold the arms, and in which units.
void curveRows(Rows& rows) {
    WellOption& arms = rows.add(
        "arms", "N", G::Reading, "Number of caliper arms in a column-text file (default 6).",
        [](const std::string& t, WellSource&, LoadOptions& o) {
            o.read.armCount = wholeNumber(t, "arms", io::kMinArms, io::kMaxArms);
        },
        [](const WellSource&, const LoadOptions& o) -> std::optional<std::string> {
            if (o.read.armCount == kDefaults.read.armCount) return std::nullopt;
            return std::to_string(o.read.armCount);
        });
    arms.value = OptionValue::Count;
    arms.minCount = io::kMinArms;
    arms.maxCount = io::kMaxArms;
    arms.column = "arms";
    arms.field = "Arms (column text)";
    arms.blank = "6";
    arms.columnTextOnly = true;

    WellOption& depthUnit = rows.add(
        "depth-unit", "m|ft", G::Reading,
        "Depth unit: m or ft (default: the file's; m for column text).",
        [](const std::string& t, WellSource&, LoadOptions& o) {
            o.read.depthUnit = unit(t, "depth-unit");
        },
        [](const WellSource&, const LoadOptions& o) { return unitText(o.read.depthUnit); });
    depthUnit.value = OptionValue::Choice;
    depthUnit.choices = {"m", "ft"};
    depthUnit.column = "depth_unit";
    depthUnit.field = "Depth unit";
    depthUnit.blank = "the file's";

    WellOption& radiusUnit = rows.add(
        "radius-unit", "in|mm|cm", G::Reading,
        "Radius unit: in, mm or cm (default: the file's; in for column text).",
        [](const std::string& t, WellSource&, LoadOptions& o) {
            o.read.radiusUnit = unit(t, "radius-unit");
        },
        [](const WellSource&, const LoadOptions& o) { return unitText(o.read.radiusUnit); });
    radiusUnit.value = OptionValue::Choice;
    radiusUnit.choices = {"in", "mm", "cm"};
    radiusUnit.column = "radius_unit";
    radiusUnit.field = "Radius unit";
    radiusUnit.blank = "the file's";

    WellOption& radii = rows.add(
        "radii", "MNEM,...", G::Reading,
        "Curves holding the arm radii, in arm order (e.g. RAD1,RAD2,...).",
        [](const std::string& t, WellSource&, LoadOptions& o) {
            std::vector<std::string> list = names(t);
            const std::string& first = list.empty() ? std::string() : list.front();
            const bool wholeArray = list.size() == 1 && first.size() > 2 &&
                                    first.compare(first.size() - 2, 2, "[]") == 0;
            if ((list.size() == 1 && !wholeArray) ||
                list.size() > static_cast<std::size_t>(io::kMaxArms))
                throw UsageError(
                    "--radii: expected 2 to 256 curve names separated by commas, or one array "
                    "NAME[]");
            o.read.roles.radii = std::move(list);
        },
        [](const WellSource&, const LoadOptions& o) { return joined(o.read.roles.radii); });
    radii.value = OptionValue::CommaList;
    radii.column = "radii";
    radii.field = "Radius curves";
    radii.blank = "detected";
    radii.blankFor = [](const io::LogInfo& info) { return "detected: " + info.armSource; };

    WellOption& diameters = rows.add(
        "diameters", "MNEM,...", G::Reading,
        "Curves holding opposite-pad diameters (e.g. C1,C2; one, e.g. CALI, for a two-pad tool).",
        [](const std::string& t, WellSource&, LoadOptions& o) {
            std::vector<std::string> list = names(t);
            if (list.size() > 4)
                throw UsageError("--diameters: expected 1 to 4 curve names separated by commas");
            o.read.roles.diameters = std::move(list);
        },
        [](const WellSource&, const LoadOptions& o) { return joined(o.read.roles.diameters); });
    diameters.value = OptionValue::CommaList;
    diameters.column = "diameters";
    diameters.field = "Diameter curves";
    diameters.blank = "detected";
}

// Which curves give the tool's orientation and the hole's direction.
void orientationRows(Rows& rows) {
    using io::RoleOverrides;
    WellOption& padAzimuth =
        rows.add(kPadAzimuth, "MNEM|none", G::Reading,
                 "Curve holding the pad-1 azimuth (e.g. P1AZ, IAP1); none: leave it out.",
                 parseCurveName<&RoleOverrides::padAzimuth, kPadAzimuth>,
                 formatCurveName<&RoleOverrides::padAzimuth>);
    padAzimuth.column = "pad_azimuth";
    padAzimuth.field = "Pad-1 azimuth curve";
    padAzimuth.blank = "detected";
    padAzimuth.blankFor = detectedCurve<io::CurveRole::PadAzimuth>;

    WellOption& bearing =
        rows.add(kRelativeBearing, "MNEM|none", G::Reading,
                 "Curve holding pad 1's relative bearing (e.g. RB, IRBR); none: leave it out.",
                 parseCurveName<&RoleOverrides::relativeBearing, kRelativeBearing>,
                 formatCurveName<&RoleOverrides::relativeBearing>);
    bearing.column = "relative_bearing";
    bearing.field = "Relative bearing curve";
    bearing.blank = "detected";
    bearing.blankFor = detectedCurve<io::CurveRole::RelativeBearing>;

    WellOption& inclination =
        rows.add(kInclination, "MNEM|none", G::Reading,
                 "Curve holding the hole's inclination (e.g. DEVI, ITLT); none: leave it out.",
                 parseCurveName<&RoleOverrides::deviation, kInclination>,
                 formatCurveName<&RoleOverrides::deviation>);
    inclination.column = "inclination";
    inclination.field = "Inclination curve";
    inclination.blank = "detected";
    inclination.blankFor = detectedCurve<io::CurveRole::Deviation>;

    WellOption& holeAzimuth =
        rows.add(kHoleAzimuth, "MNEM|none", G::Reading,
                 "Curve holding the hole's azimuth (e.g. HAZI, IAZT); none: leave it out.",
                 parseCurveName<&RoleOverrides::holeAzimuth, kHoleAzimuth>,
                 formatCurveName<&RoleOverrides::holeAzimuth>);
    holeAzimuth.column = "hole_azimuth";
    holeAzimuth.field = "Hole azimuth curve";
    holeAzimuth.blank = "detected";
    holeAzimuth.blankFor = detectedCurve<io::CurveRole::HoleAzimuth>;
}

// How a file is read: its rows, nulls and bit size.
// Which rows and which run of the file are read.
void layoutRows(Rows& rows) {
    WellOption& rowStep = rows.add(
        "row-step", "METRES", G::Reading,
        "Depth step per row of a radii-only text file, metres (default 0.01).",
        [](const std::string& t, WellSource&, LoadOptions& o) {
            const double step = number(t, "row-step");
            if (!(step > 0.0)) throw UsageError("--row-step: expected a positive number of metres");
            o.read.rowStep_m = step;
        },
        [](const WellSource&, const LoadOptions& o) {
            return unlessDefault(o.read.rowStep_m, kDefaults.read.rowStep_m);
        });
    rowStep.columnTextOnly = true;

    WellOption& logicalFile = rows.add(
        "file", "N", G::Reading,
        "DLIS: the logical file (run) to read, 1 for the first; default the first that holds "
        "caliper curves (`info` lists them).",
        [](const std::string& t, WellSource&, LoadOptions& o) {
            o.read.logicalFile = wholeNumber(t, "file", 1, 100000);
        },
        [](const WellSource&, const LoadOptions& o) -> std::optional<std::string> {
            if (o.read.logicalFile == 0) return std::nullopt;
            return std::to_string(o.read.logicalFile);
        });
    logicalFile.column = "logical_file";
    logicalFile.field = "DLIS logical file";
    logicalFile.blank = "the first with caliper curves";
}

// A casing program as --casing and --casing-each take it: strings "BOTTOM,SIZE[,WEIGHT|ID]"
// separated by ';', sorted by shoe depth.
std::vector<io::CasingString> casingProgram(const std::string& t, const char* option) {
    std::vector<io::CasingString> program;
    std::size_t start = 0;
    while (start <= t.size()) {
        const std::size_t end = std::min(t.find(';', start), t.size());
        const std::string one = trimmed(t.substr(start, end - start));
        start = end + 1;
        if (one.empty()) continue;
        std::string error;
        const std::optional<io::CasingString> c = io::parseCasingSpec(one, error);
        if (!c) throw UsageError(std::string("--") + option + ": " + error);
        program.push_back(*c);
    }
    std::sort(program.begin(), program.end(),
              [](const io::CasingString& a, const io::CasingString& b) {
                  return a.bottom_m < b.bottom_m;
              });
    return program;
}

// The text casingProgram reads back to `program`; nullopt for none.
std::optional<std::string> casingProgramText(const std::vector<io::CasingString>& program) {
    if (program.empty()) return std::nullopt;
    std::string text;
    for (const io::CasingString& c : program)
        text += (text.empty() ? "" : ";") + io::casingSpecText(c);
    return text;
}

// How the file's data are read: nulls, bit size, casing.
void fileRows(Rows& rows) {
    rows.add(
            "nulls", "declared|common", G::Reading,
            "Null values: declared (the file's NULL) or common (also -999.25, -9999, 9999, ERR, "
            "dashes; default).",
            [](const std::string& t, WellSource&, LoadOptions& o) {
                if (t == "declared")
                    o.read.nullPolicy = io::NullPolicy::Declared;
                else if (t == "common")
                    o.read.nullPolicy = io::NullPolicy::Common;
                else
                    throw UsageError("--nulls: expected 'declared' or 'common', found '" + t + "'");
            },
            [](const WellSource&, const LoadOptions& o) -> std::optional<std::string> {
                if (o.read.nullPolicy == kDefaults.read.nullPolicy) return std::nullopt;
                return o.read.nullPolicy == io::NullPolicy::Declared ? "declared" : "common";
            })
        .choices = {"declared", "common"};
    rows.back().value = OptionValue::Choice;

    WellOption& bitSize = rows.add(
        "bit-size", "VALUE[in|mm]", G::Reading,
        "Bit size, e.g. 8.5in or 215.9mm (a bare number is inches).",
        [](const std::string& t, WellSource&, LoadOptions& o) {
            o.read.bitSize_mm = parseLength_mm(t, "--bit-size");
        },
        [](const WellSource&, const LoadOptions& o) -> std::optional<std::string> {
            if (!o.read.bitSize_mm) return std::nullopt;
            return exact(*o.read.bitSize_mm) + "mm";
        });
    bitSize.column = "bit_size";
    bitSize.field = "Bit size";
    bitSize.blank = "the log's own: 8.5in, 215.9mm (a bare number is inches)";
    bitSize.blankFor = [](const io::LogInfo& info) -> std::string {
        if (!std::isfinite(info.bitSize_mm)) return "none in the log: e.g. 8.5in or 215.9mm";
        std::string text = "the log's: " + bitSizeText(info.bitSize_mm);
        if (std::isfinite(info.bitSizeMax_mm) && info.bitSizeMax_mm > info.bitSize_mm)
            text += " to " + bitSizeText(info.bitSizeMax_mm);
        return text;
    };

    WellOption& casing = rows.add(
        "casing", "BOTTOM,SIZE[,WEIGHT|ID]", G::Reading,
        "Casing set in the hole, replacing the log's casing program: shoe depth in metres, outer "
        "diameter (7in, 177.8mm), then weight (17lb/ft, 25.3kg/m) or inner diameter (6.538in); "
        "repeat it for each string.",
        [](const std::string& t, WellSource&, LoadOptions& o) {
            o.read.casing = casingProgram(t, "casing");
        },
        [](const WellSource&, const LoadOptions& o) -> std::optional<std::string> {
            return casingProgramText(o.read.casing);
        });
    casing.repeatable = true;
    casing.effect = OptionEffect::Log;
    casing.column = "casing";
    casing.field = "Casing";
    casing.blank = "the log's casing program: e.g. 88.3,7in,17lb/ft (several: ';' between)";
    casing.blankFor = [](const io::LogInfo& info) -> std::string {
        if (info.casing.empty()) return "none in the log: e.g. 88.3,7in,17lb/ft";
        std::string text = "the log's: ";
        for (const io::CasingString& c : info.casing)
            text += (&c == &info.casing.front() ? "" : "; ") + io::casingSpecText(c);
        return text;
    };
}

// Which north the azimuths are from (docs/conventions.md, "North").
void northRows(Rows& rows) {
    WellOption& declination = rows.add(
        "declination", "DEG", G::Reading,
        "Magnetic declination, degrees east positive, applied to azimuths from magnetic north "
        "(default: the header's MDEC, DECL, ..., else the World Magnetic Model's).",
        [](const std::string& t, WellSource&, LoadOptions& o) {
            const double deg = number(t, "declination");
            if (!(std::fabs(deg) <= 180.0))
                throw UsageError(
                    "--declination: expected degrees from -180 to 180 (east positive)");
            o.read.declination_deg = deg;
        },
        [](const WellSource&, const LoadOptions& o) -> std::optional<std::string> {
            if (!o.read.declination_deg) return std::nullopt;
            return exact(*o.read.declination_deg);
        });
    declination.column = "declination";
    declination.field = "Declination (deg E)";
    declination.blank = "the header's, else the magnetic model's";
    declination.blankFor = [](const io::LogInfo& info) -> std::string {
        if (info.north.declination.found())
            return "the header's: " + exact(info.north.declination.deg) + " (" +
                   info.north.declination.source + ")";
        return "none in the header: the magnetic model's";
    };

    WellOption& convergence = rows.add(
        "grid-convergence", "DEG", G::Reading,
        "Grid convergence (grid north clockwise from true north), degrees, applied to azimuths "
        "from grid north (default: the header's GRIDCONV, GCONV, ...).",
        [](const std::string& t, WellSource&, LoadOptions& o) {
            const double deg = number(t, "grid-convergence");
            if (!(std::fabs(deg) <= 90.0))
                throw UsageError("--grid-convergence: expected degrees from -90 to 90");
            o.read.gridConvergence_deg = deg;
        },
        [](const WellSource&, const LoadOptions& o) -> std::optional<std::string> {
            if (!o.read.gridConvergence_deg) return std::nullopt;
            return exact(*o.read.gridConvergence_deg);
        });
    convergence.column = "grid_convergence";
    convergence.field = "Grid convergence (deg)";
    convergence.blank = "the header's";

    WellOption& north = rows.add(
        "azimuth-north", "true|magnetic|grid", G::Reading,
        "The north of azimuth curves whose description does not say (default: taken as true "
        "north, with a warning).",
        [](const std::string& t, WellSource&, LoadOptions& o) {
            const io::North n = io::parseNorthWord(t);
            if (n == io::North::Unknown)
                throw UsageError("--azimuth-north: expected 'true', 'magnetic' or 'grid', found '" +
                                 t + "'");
            o.read.azimuthNorth = n;
        },
        [](const WellSource&, const LoadOptions& o) -> std::optional<std::string> {
            switch (o.read.azimuthNorth) {
                case io::North::True:
                    return std::string("true");
                case io::North::Magnetic:
                    return std::string("magnetic");
                case io::North::Grid:
                    return std::string("grid");
                case io::North::Unknown:
                    break;
            }
            return std::nullopt;
        });
    north.value = OptionValue::Choice;
    north.choices = {"true", "magnetic", "grid"};
    north.column = "azimuth_north";
    north.field = "Azimuth north";
    north.blank = "the curves' descriptions";
}

// How the well is reconstructed and drawn.
void geometryRows(Rows& rows) {
    rows.add(
            "points", "M", G::Reading, "Points per section of the closed spline (default 48).",
            [](const std::string& t, WellSource&, LoadOptions& o) {
                o.splinePoints = wholeNumber(t, "points", 3, 1024);
            },
            [](const WellSource&, const LoadOptions& o) -> std::optional<std::string> {
                if (o.splinePoints == kDefaults.splinePoints) return std::nullopt;
                return std::to_string(o.splinePoints);
            })
        .value = OptionValue::Count;
    rows.back().minCount = 3;
    rows.back().maxCount = 1024;
    rows.back().effect = OptionEffect::Geometry;

    rows.add(
        "segment-length", "METRES", G::Reading,
        "Length of one level-of-detail segment in metres (default: 1, or 100 rows "
        "rounded up to whole metres on a log sampled more sparsely than 1 cm).",
        [](const std::string& t, WellSource&, LoadOptions& o) {
            const double length = number(t, "segment-length");
            if (!(length > 0.0))
                throw UsageError("--segment-length: expected a positive number of metres");
            o.segmentLength_m = length;
        },
        [](const WellSource&, const LoadOptions& o) {
            return unlessDefault(o.segmentLength_m, kDefaults.segmentLength_m);
        });
    rows.back().effect = OptionEffect::Picture;

    rows.add(
        "shape-tolerance", "MM", G::Reading,
        "Level of detail: a coarse level leaves a section out only while its neighbours "
        "interpolate every arm within this many millimetres (coarser levels 4 and 16 times "
        "more; default 0.5).",
        [](const std::string& t, WellSource&, LoadOptions& o) {
            const double tolerance = number(t, "shape-tolerance");
            if (!(tolerance > 0.0 && tolerance <= 100.0))
                throw UsageError(
                    "--shape-tolerance: expected millimetres, more than 0 and at most 100");
            o.shapeTolerance_mm = tolerance;
        },
        [](const WellSource&, const LoadOptions& o) {
            return unlessDefault(o.shapeTolerance_mm, kDefaults.shapeTolerance_mm);
        });
    rows.back().effect = OptionEffect::Picture;

    rows.add(
        "exaggerate", "F", G::Reading,
        "Draw radii F times larger around the true path (display only; default 1; render "
        "chooses one for its picture).",
        [](const std::string& t, WellSource&, LoadOptions& o) {
            const double factor = number(t, "exaggerate");
            if (!(factor >= 1.0 && factor <= 1000.0))
                throw UsageError("--exaggerate: expected a factor from 1 to 1000");
            o.radialExaggeration = factor;
        },
        [](const WellSource&, const LoadOptions& o) {
            return unlessDefault(o.radialExaggeration, kDefaults.radialExaggeration);
        });
    rows.back().effect = OptionEffect::Picture;

    rows.add(
        "steep-inclination", "DEG", G::Reading,
        "Above this inclination (degrees) arm 1 is placed from RB when the log has it "
        "(default 15).",
        [](const std::string& t, WellSource&, LoadOptions& o) {
            const double steep = number(t, "steep-inclination");
            if (!(steep >= 0.0 && steep <= 90.0))
                throw UsageError("--steep-inclination: expected an angle from 0 to 90 degrees");
            o.steepInclination_deg = steep;
        },
        [](const WellSource&, const LoadOptions& o) {
            return unlessDefault(o.steepInclination_deg, kDefaults.steepInclination_deg);
        });
    rows.back().effect = OptionEffect::Geometry;

    rows.add(
        "tool-reach", "LENGTH", G::Reading,
        "Arm readings beyond this radius (e.g. 10in, 254mm) are stuck or spurious and are "
        "interpolated from the neighbouring arms (default: no limit).",
        [](const std::string& t, WellSource&, LoadOptions& o) {
            o.toolReach_mm = parseLength_mm(t, "--tool-reach");
        },
        [](const WellSource&, const LoadOptions& o) -> std::optional<std::string> {
            if (o.toolReach_mm == kDefaults.toolReach_mm) return std::nullopt;
            return exact(o.toolReach_mm) + "mm";
        });
    rows.back().effect = OptionEffect::Geometry;
}

// What the wall is coloured by.
void colourRows(Rows& rows) {
    rows.add(
        "colour-by", "NAME", G::Colour,
        "Colour the wall by: departure (radius - bit radius, the default; diverging map, "
        "grey at bit size), diameter (equivalent), ellipticity, class (the report's classes), "
        "dls (dogleg severity), change (how far the wall moved against the run "
        "--compare-with names, at each azimuth where both runs are oriented, depth-matched as "
        "compare does; diverging map, grey where they agree), or any other curve of the log "
        "by its mnemonic (e.g. GR).",
        [](const std::string& t, WellSource&, LoadOptions& o) {
            o.colour.quantity = trimmed(t);
            if (o.colour.quantity.empty()) throw UsageError("--colour-by: expected a name");
        },
        [](const WellSource&, const LoadOptions& o) -> std::optional<std::string> {
            if (o.colour.quantity == kDefaults.colour.quantity) return std::nullopt;
            return o.colour.quantity;
        });
    rows.back().effect = OptionEffect::Picture;

    rows.add(
            "colour-range", "LO,HI", G::Colour,
            "The values at the colour map's ends, e.g. -10,40 (default: +-25 mm for departure, the "
            "2nd to 98th percentile of the well for the others).",
            [](const std::string& t, WellSource&, LoadOptions& o) {
                const std::size_t comma = t.find(',');
                double lo = 0.0, hi = 0.0;
                if (comma == std::string::npos || t.find(',', comma + 1) != std::string::npos ||
                    !io::parseNumber(trimmed(t.substr(0, comma)), lo) ||
                    !io::parseNumber(trimmed(t.substr(comma + 1)), hi) || !std::isfinite(lo) ||
                    !std::isfinite(hi) || !(lo < hi))
                    throw UsageError(
                        "--colour-range: expected LO,HI with LO below HI, e.g. -10,40; got '" + t +
                        "'");
                o.colour.range = std::make_pair(lo, hi);
            },
            [](const WellSource&, const LoadOptions& o) -> std::optional<std::string> {
                if (!o.colour.range) return std::nullopt;
                return exact(o.colour.range->first) + "," + exact(o.colour.range->second);
            })
        .value = OptionValue::CommaList;
    rows.back().effect = OptionEffect::Picture;

    WellOption& compareWith = rows.add(
        "compare-with", "RUN", G::Colour,
        "With --colour-by change: the other run of the same well (a log file, read with the "
        "same options) that each FILE is compared with; the wall shows FILE minus RUN.",
        [](const std::string& t, WellSource&, LoadOptions& o) {
            o.colour.compareWith = trimmed(t);
            if (o.colour.compareWith.empty())
                throw UsageError("--compare-with: expected a log file");
        },
        [](const WellSource&, const LoadOptions& o) -> std::optional<std::string> {
            if (o.colour.compareWith.empty()) return std::nullopt;
            return o.colour.compareWith;
        });
    compareWith.value = OptionValue::Path;
    compareWith.effect = OptionEffect::Picture;
}

// Where each well is: its survey and wellhead.
void perWellRows(Rows& rows) {
    WellOption& survey = rows.add(
        "survey", "FILE", G::PerWell,
        "Deviation survey (MD, inclination, azimuth) for the well path instead of the log's "
        "DEVI/HAZI; once per FILE, in order.",
        [](const std::string& t, WellSource& w, LoadOptions&) { w.surveyPath = t; },
        [](const WellSource& w, const LoadOptions&) -> std::optional<std::string> {
            if (w.surveyPath.empty()) return std::nullopt;
            return w.surveyPath;
        });
    survey.value = OptionValue::Path;
    survey.effect = OptionEffect::Geometry;
    survey.column = "survey";
    survey.field = "Survey";
    survey.blank = "none: the path from the log's DEVI/HAZI";

    WellOption& picks = rows.add(
        "picks", "FILE", G::PerWell,
        "Breakouts picked on an image log (depth, azimuth, type: LAS or delimited text), shown "
        "beside the caliper's zones; once per FILE, in order.",
        [](const std::string& t, WellSource& w, LoadOptions&) { w.picksPath = t; },
        [](const WellSource& w, const LoadOptions&) -> std::optional<std::string> {
            if (w.picksPath.empty()) return std::nullopt;
            return w.picksPath;
        });
    picks.value = OptionValue::Path;
    picks.effect = OptionEffect::Geometry;
    picks.column = "picks";
    picks.field = "Image-log picks";
    picks.blank = "none";

    WellOption& wellhead = rows.add(
        "wellhead", "E,N,ELEV", G::PerWell,
        "Wellhead easting, northing and elevation of the depth reference in metres (e.g. "
        "512300,6801200,25.5); once per FILE, in order. Overrides the header's location (without "
        "it, a well is placed from its header's latitude/longitude or map coordinates). The "
        "first well's wellhead is the scene origin.",
        [](const std::string& t, WellSource& w, LoadOptions&) { w.wellhead = parseWellhead(t); },
        [](const WellSource& w, const LoadOptions&) -> std::optional<std::string> {
            if (!w.wellhead) return std::nullopt;
            return exact(w.wellhead->easting_m) + "," + exact(w.wellhead->northing_m) + "," +
                   exact(w.wellhead->elevation_m);
        });
    wellhead.value = OptionValue::CommaList;
    wellhead.effect = OptionEffect::Geometry;
    wellhead.column = "wellhead";
    wellhead.field = "Wellhead";
    wellhead.blank = "E,N,ELEV in metres, e.g. 512300,6801200,25.5 (none: from the header)";

    WellOption& casingEach = rows.add(
        "casing-each", "PROGRAM", G::PerWell,
        "Each FILE's own casing program, once per FILE, in order: strings as --casing takes "
        "them, ';' between, or '-' for the file's own header. Runs of one well logged weeks "
        "apart each see only the casing set before them.",
        [](const std::string& t, WellSource& w, LoadOptions&) {
            if (trimmed(t) == "-") {
                w.casing.reset();
                return;
            }
            std::vector<io::CasingString> program = casingProgram(t, "casing-each");
            for (io::CasingString& c : program) c.source = "--casing-each";
            if (program.empty())
                throw UsageError("--casing-each: give BOTTOM,SIZE[,WEIGHT|ID] strings, or '-'");
            w.casing = std::move(program);
        },
        [](const WellSource& w, const LoadOptions&) -> std::optional<std::string> {
            if (!w.casing) return std::nullopt;
            return casingProgramText(*w.casing);
        });
    casingEach.effect = OptionEffect::Log;
}

// Each row in the order `caliper3d VERB --help` lists them; the messages are the command
// line's (tests check them).
std::vector<WellOption> makeTable() {
    Rows rows;
    rows.list.reserve(40);  // a row is finished through a reference before the next is added
    curveRows(rows);
    orientationRows(rows);
    layoutRows(rows);
    fileRows(rows);
    northRows(rows);
    geometryRows(rows);
    colourRows(rows);
    perWellRows(rows);
    return rows.list;
}

}  // namespace

const std::vector<WellOption>& wellOptions() {
    static const std::vector<WellOption> kTable = makeTable();
    return kTable;
}

const WellOption* findWellOption(const std::string& name) {
    for (const WellOption& option : wellOptions())
        if (name == option.name) return &option;
    return nullptr;
}

const std::vector<std::string>& verbsTaking(OptionGroup group) {
    static const std::vector<std::string> kReading = {"view", "info", "export", "render", "report"};
    static const std::vector<std::string> kColour = {"view", "export", "render"};
    static const std::vector<std::string> kPerWell = {"view", "info", "export", "render", "report"};
    switch (group) {
        case OptionGroup::Reading:
            return kReading;
        case OptionGroup::Colour:
            return kColour;
        case OptionGroup::PerWell:
            break;
    }
    return kPerWell;
}

bool takes(const std::string& verb, OptionGroup group) {
    const std::vector<std::string>& verbs = verbsTaking(group);
    return std::find(verbs.begin(), verbs.end(), verb) != verbs.end();
}

void applyOptionTexts(const OptionTexts& texts, WellSource& well, LoadOptions& options) {
    for (const auto& [name, text] : texts)
        if (!findWellOption(name)) throw UsageError("unknown option '--" + name + "'");
    for (const WellOption& option : wellOptions()) {
        const auto it = texts.find(option.name);
        if (it == texts.end()) continue;
        const std::string text = trimmed(it->second);
        if (!text.empty()) option.parse(text, well, options);
    }
}

OptionTexts optionTexts(const WellSource& well, const LoadOptions& options) {
    OptionTexts out;
    for (const WellOption& option : wellOptions())
        if (std::optional<std::string> text = option.format(well, options))
            out[option.name] = *text;
    return out;
}

std::string optionsUsage() {
    constexpr std::size_t kWidth = 96;
    std::string out;
    auto lines = [&out](const std::string& head, bool (*wanted)(const WellOption&)) {
        std::string line = head;
        for (const WellOption& option : wellOptions()) {
            if (!wanted(option)) continue;
            std::string item = std::string("--") + option.name + " " + option.valueName;
            if (option.group == OptionGroup::PerWell) item += " (once per FILE)";
            if (line.size() + 1 + item.size() > kWidth && line.size() > 8) {
                out += line + "\n";
                line = std::string(8, ' ');
            }
            line += (line.back() == ' ' ? "" : " ") + item;
        }
        out += line + "\n";
    };
    lines("common:", [](const WellOption& o) { return o.group != OptionGroup::Colour; });
    std::string drawing;
    for (const std::string& verb : verbsTaking(OptionGroup::Colour))
        drawing += (drawing.empty() ? "" : ", ") + verb;
    lines(drawing + ":", [](const WellOption& o) { return o.group == OptionGroup::Colour; });
    return out;
}

double parseLength_mm(const std::string& value, const std::string& option) {
    std::string text = value;
    double scale = 25.4;
    for (const char* suffix : {"mm", "in", "cm"}) {
        const std::string s(suffix);
        if (text.size() > s.size() && text.compare(text.size() - s.size(), s.size(), s) == 0) {
            scale = io::toMillimetres(*io::parseLengthUnit(s));
            text.resize(text.size() - s.size());
            break;
        }
    }
    double v = 0.0;
    if (!io::parseNumber(text, v) || !(v > 0.0) || !std::isfinite(v))
        throw UsageError(option + ": expected a positive length such as 8.5in or 215.9mm, found '" +
                         value + "'");
    return v * scale;
}

reconstruction::Wellhead parseWellhead(const std::string& text) {
    // Commas separate the three numbers, so a decimal comma cannot be used here.
    double v[3] = {0.0, 0.0, 0.0};
    std::size_t start = 0;
    for (int k = 0; k < 3; ++k) {
        const std::size_t comma = text.find(',', start);
        const bool last = k == 2;
        if (last != (comma == std::string::npos) ||
            !io::parseNumber(
                text.substr(start, comma == std::string::npos ? std::string::npos : comma - start),
                v[k]) ||
            !std::isfinite(v[k]))
            throw UsageError(
                "--wellhead: expected easting,northing,elevation in metres (three "
                "numbers with a decimal point), found '" +
                text + "'");
        start = comma + 1;
    }
    return {v[0], v[1], v[2]};
}

}  // namespace caliper3d::app
