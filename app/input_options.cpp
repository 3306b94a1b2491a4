#include "app/input_options.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "io/number_parsing.h"
#include "io/units.h"
#include "io/warnings_text.h"

namespace caliper3d::app {

void addInputOptions(QCommandLineParser& parser) {
    const QList<QCommandLineOption> options = {
        {"arms", "Number of caliper arms in a column-text file (default 6).", "N", "6"},
        {"depth-unit", "Depth unit: m or ft (default: the file's; m for column text).", "UNIT"},
        {"radius-unit", "Radius unit: in, mm or cm (default: the file's; in for column text).",
         "UNIT"},
        {"radii", "Curves holding the arm radii, in arm order (e.g. RAD1,RAD2,...).", "MNEM,..."},
        {"diameters",
         "Curves holding opposite-pad diameters (e.g. C1,C2; one, e.g. CALI, for a two-pad tool).",
         "MNEM,..."},
        {"row-step", "Depth step per row of a radii-only text file, metres (default 0.01).",
         "METRES", "0.01"},
        {"nulls",
         "Null values: declared (the file's NULL) or common (also -999.25, -9999, 9999, ERR, "
         "dashes; default).",
         "POLICY", "common"},
        {"bit-size", "Bit size, e.g. 8.5in or 215.9mm (a bare number is inches).", "VALUE"},
        {"points", "Points per section of the closed spline (default 48).", "M", "48"},
        {"segment-length", "Length of one level-of-detail segment in metres (default 1).", "METRES",
         "1"},
        {"shape-tolerance",
         "Level of detail: a coarse level leaves a section out only while its neighbours "
         "interpolate every arm within this many millimetres (coarser levels 4 and 16 times "
         "more; default 0.5).",
         "MM", "0.5"},
        {"exaggerate",
         "Draw radii F times larger around the true path (display only; default 1; render "
         "chooses one for its picture).",
         "F", "1"},
        {"steep-inclination",
         "Above this inclination (degrees) arm 1 is placed from RB when the log has it "
         "(default 15).",
         "DEG", "15"},
        {"tool-reach",
         "Arm readings beyond this radius (e.g. 10in, 254mm) are stuck or spurious and are "
         "interpolated from the neighbouring arms (default: no limit).",
         "LENGTH"},
    };
    parser.addOptions(options);
}

namespace {
double number(const QCommandLineParser& parser, const char* name) {
    double v = 0.0;
    const std::string text = parser.value(name).toStdString();
    if (!io::parseNumber(text, v) || !std::isfinite(v))
        throw UsageError(std::string("--") + name + ": expected a number, found '" + text + "'");
    return v;
}
io::LengthUnit unit(const QCommandLineParser& parser, const char* name) {
    const std::string text = parser.value(name).toStdString();
    auto u = io::parseLengthUnit(text);
    if (!u) throw UsageError(std::string("--") + name + ": unknown unit '" + text + "'");
    return *u;
}
}  // namespace

LoadOptions inputOptionsFrom(const QCommandLineParser& parser) {
    LoadOptions o;
    const double arms = number(parser, "arms");
    if (arms < io::kMinArms || arms > io::kMaxArms || arms != std::floor(arms))
        throw UsageError("--arms: expected a whole number from " + std::to_string(io::kMinArms) +
                         " to " + std::to_string(io::kMaxArms));
    o.read.armCount = static_cast<int>(arms);
    if (parser.isSet("depth-unit")) o.read.depthUnit = unit(parser, "depth-unit");
    if (parser.isSet("radius-unit")) o.read.radiusUnit = unit(parser, "radius-unit");
    auto list = [&](const char* name) {
        std::vector<std::string> out;
        for (const QString& s : parser.value(name).split(',', Qt::SkipEmptyParts))
            out.push_back(s.trimmed().toStdString());
        return out;
    };
    if (parser.isSet("radii")) o.read.roles.radii = list("radii");
    if (parser.isSet("diameters")) o.read.roles.diameters = list("diameters");
    const bool wholeArray =
        o.read.roles.radii.size() == 1 && o.read.roles.radii.front().size() > 2 &&
        o.read.roles.radii.front().compare(o.read.roles.radii.front().size() - 2, 2, "[]") == 0;
    if ((o.read.roles.radii.size() == 1 && !wholeArray) ||
        o.read.roles.radii.size() > static_cast<std::size_t>(io::kMaxArms))
        throw UsageError(
            "--radii: expected 2 to 256 curve names separated by commas, or one array NAME[]");
    if (o.read.roles.diameters.size() > 4)
        throw UsageError("--diameters: expected 1 to 4 curve names separated by commas");
    o.read.rowStep_m = number(parser, "row-step");
    if (!(o.read.rowStep_m > 0.0))
        throw UsageError("--row-step: expected a positive number of metres");
    const std::string nulls = parser.value("nulls").toStdString();
    if (nulls == "declared")
        o.read.nullPolicy = io::NullPolicy::Declared;
    else if (nulls == "common")
        o.read.nullPolicy = io::NullPolicy::Common;
    else
        throw UsageError("--nulls: expected 'declared' or 'common', found '" + nulls + "'");
    const double points = number(parser, "points");
    if (points < 3 || points > 1024 || points != std::floor(points))
        throw UsageError("--points: expected a whole number from 3 to 1024");
    o.splinePoints = static_cast<int>(points);
    o.segmentLength_m = number(parser, "segment-length");
    if (!(o.segmentLength_m > 0.0))
        throw UsageError("--segment-length: expected a positive number of metres");
    o.shapeTolerance_mm = number(parser, "shape-tolerance");
    if (!(o.shapeTolerance_mm > 0.0 && o.shapeTolerance_mm <= 100.0))
        throw UsageError("--shape-tolerance: expected millimetres, more than 0 and at most 100");
    o.radialExaggeration = number(parser, "exaggerate");
    if (!(o.radialExaggeration >= 1.0 && o.radialExaggeration <= 1000.0))
        throw UsageError("--exaggerate: expected a factor from 1 to 1000");
    const double steep = number(parser, "steep-inclination");
    if (!(steep >= 0.0 && steep <= 90.0))
        throw UsageError("--steep-inclination: expected an angle from 0 to 90 degrees");
    o.steepInclination_deg = steep;
    if (parser.isSet("tool-reach"))
        o.toolReach_mm = parseLength_mm(parser.value("tool-reach").toStdString(), "--tool-reach");
    if (parser.isSet("bit-size"))
        o.read.bitSize_mm = parseLength_mm(parser.value("bit-size").toStdString(), "--bit-size");
    return o;
}

void addColourOptions(QCommandLineParser& parser) {
    parser.addOption(
        {"colour-by",
         "Colour the wall by: departure (radius - bit radius, the default; diverging map, "
         "grey at bit size), diameter (equivalent), ellipticity, class (the report's classes), "
         "dls (dogleg severity), or any other curve of the log by its mnemonic (e.g. GR).",
         "NAME", "departure"});
    parser.addOption({"colour-range",
                      "The values at the colour map's ends, e.g. -10,40 (default: +-25 mm for "
                      "departure, the 2nd to 98th percentile of the well for the others).",
                      "LO,HI"});
}

reconstruction::ColourRequest colourRequestFrom(const QCommandLineParser& parser) {
    reconstruction::ColourRequest request;
    request.quantity = parser.value("colour-by").trimmed().toStdString();
    if (request.quantity.empty()) throw UsageError("--colour-by: expected a name");
    if (parser.isSet("colour-range")) {
        const QStringList parts = parser.value("colour-range").split(',');
        double lo = 0.0, hi = 0.0;
        if (parts.size() != 2 || !io::parseNumber(parts[0].trimmed().toStdString(), lo) ||
            !io::parseNumber(parts[1].trimmed().toStdString(), hi) || !std::isfinite(lo) ||
            !std::isfinite(hi) || !(lo < hi))
            throw UsageError("--colour-range: expected LO,HI with LO below HI, e.g. -10,40; got '" +
                             parser.value("colour-range").toStdString() + "'");
        request.range = std::make_pair(lo, hi);
    }
    return request;
}

void rejectInapplicable(const QCommandLineParser& parser, const std::string& verb,
                        std::initializer_list<const char*> names, const std::string& why) {
    const auto set = std::find_if(names.begin(), names.end(),
                                  [&](const char* name) { return parser.isSet(name); });
    if (set != names.end())
        throw UsageError("caliper3d " + verb + ": --" + *set + " does not apply: " + why);
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

void addWellSourceOptions(QCommandLineParser& parser) {
    parser.addOption(
        {"survey",
         "Deviation survey (MD, inclination, azimuth) for the well path instead of the "
         "log's DEVI/HAZI; once per FILE, in order.",
         "FILE"});
    parser.addOption({"wellhead",
                      "Wellhead easting, northing and elevation of the depth reference in metres "
                      "(e.g. 512300,6801200,25.5); once per FILE, in order. The first well's "
                      "wellhead is the scene origin.",
                      "E,N,ELEV"});
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

std::vector<WellSource> wellSourcesFrom(const QCommandLineParser& parser,
                                        const std::vector<std::string>& files) {
    const QStringList surveys = parser.isSet("survey") ? parser.values("survey") : QStringList();
    const QStringList heads = parser.isSet("wellhead") ? parser.values("wellhead") : QStringList();
    const auto count = static_cast<int>(files.size());
    if (!surveys.isEmpty() && surveys.size() != count)
        throw UsageError("--survey: given " + std::to_string(surveys.size()) + " times for " +
                         std::to_string(count) + " file(s); give it once per file, in order");
    if (!heads.isEmpty() && heads.size() != count)
        throw UsageError("--wellhead: given " + std::to_string(heads.size()) + " times for " +
                         std::to_string(count) + " file(s); give it once per file, in order");
    std::vector<WellSource> out;
    for (int i = 0; i < count; ++i) {
        WellSource w;
        w.path = files[static_cast<std::size_t>(i)];
        if (!surveys.isEmpty()) w.surveyPath = surveys[i].toStdString();
        if (!heads.isEmpty()) w.wellhead = parseWellhead(heads[i].toStdString());
        out.push_back(std::move(w));
    }
    return out;
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
