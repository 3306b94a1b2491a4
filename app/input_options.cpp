#include "app/input_options.h"

#include <cmath>

#include "io/number_parsing.h"
#include "io/units.h"

namespace caliper3d::app {

void addInputOptions(QCommandLineParser& parser) {
    const QList<QCommandLineOption> options = {
        {"arms", "Number of caliper arms in a column-text file (default 6).", "N", "6"},
        {"depth-unit", "Depth unit: m or ft (default: the file's; m for column text).", "UNIT"},
        {"radius-unit", "Radius unit: in, mm or cm (default: the file's; in for column text).",
         "UNIT"},
        {"radii", "Curves holding the arm radii, in arm order (e.g. RAD1,RAD2,...).", "MNEM,..."},
        {"diameters", "Curves holding opposite-pad diameters (e.g. C1,C2).", "MNEM,..."},
        {"row-step", "Depth step per row of a radii-only text file, metres (default 0.01).",
         "METRES", "0.01"},
        {"nulls",
         "Null values: declared (the file's NULL) or common (also -999.25, -9999, 9999, ERR, "
         "dashes; default).",
         "POLICY", "common"},
        {"bit-size", "Bit size, e.g. 8.5in or 215.9mm (a bare number is inches).", "VALUE"},
        {"points", "Points per section of the closed spline (default 48).", "M", "48"},
        {"segment-length", "Length of one level-of-detail segment in metres (default 10).",
         "METRES", "10"},
        {"exaggerate", "Draw radii F times larger around the true path (display only; default 1).",
         "F", "1"},
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

InputOptions inputOptionsFrom(const QCommandLineParser& parser) {
    InputOptions o;
    const double arms = number(parser, "arms");
    if (arms < 3 || arms > 256 || arms != std::floor(arms))
        throw UsageError("--arms: expected a whole number from 3 to 256");
    o.read.armCount = static_cast<int>(arms);
    if (parser.isSet("depth-unit")) o.read.depthUnit = unit(parser, "depth-unit");
    if (parser.isSet("radius-unit")) o.read.radiusUnit = unit(parser, "radius-unit");
    auto list = [&](const char* name) {
        std::vector<std::string> out;
        for (const QString& s : parser.value(name).split(',', Qt::SkipEmptyParts)) out.push_back(s.trimmed().toStdString());
        return out;
    };
    if (parser.isSet("radii")) o.read.roles.radii = list("radii");
    if (parser.isSet("diameters")) o.read.roles.diameters = list("diameters");
    if (o.read.roles.radii.size() == 1 || o.read.roles.radii.size() > 256)
        throw UsageError("--radii: expected 3 to 256 curve names separated by commas");
    if (!o.read.roles.diameters.empty() && (o.read.roles.diameters.size() < 2 || o.read.roles.diameters.size() > 4))
        throw UsageError("--diameters: expected 2 to 4 curve names separated by commas");
    o.read.rowStep_m = number(parser, "row-step");
    if (!(o.read.rowStep_m > 0.0)) throw UsageError("--row-step: expected a positive number of metres");
    const std::string nulls = parser.value("nulls").toStdString();
    if (nulls == "declared") o.read.nullPolicy = io::NullPolicy::Declared;
    else if (nulls == "common") o.read.nullPolicy = io::NullPolicy::Common;
    else throw UsageError("--nulls: expected 'declared' or 'common', found '" + nulls + "'");
    const double points = number(parser, "points");
    if (points < 3 || points > 1024 || points != std::floor(points))
        throw UsageError("--points: expected a whole number from 3 to 1024");
    o.splinePoints = static_cast<int>(points);
    o.segmentLength_m = number(parser, "segment-length");
    if (!(o.segmentLength_m > 0.0))
        throw UsageError("--segment-length: expected a positive number of metres");
    o.radialExaggeration = number(parser, "exaggerate");
    if (!(o.radialExaggeration >= 1.0 && o.radialExaggeration <= 1000.0))
        throw UsageError("--exaggerate: expected a factor from 1 to 1000");
    if (parser.isSet("bit-size")) {
        std::string text = parser.value("bit-size").toStdString();
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
        if (!io::parseNumber(text, v) || !(v > 0.0))
            throw UsageError("--bit-size: expected a positive size such as 8.5in or 215.9mm");
        o.read.bitSize_mm = v * scale;
    }
    return o;
}

reconstruction::GeometryOptions geometryOptions(const InputOptions& options) {
    reconstruction::GeometryOptions g;
    g.splinePoints = options.splinePoints;
    g.segmentLength_m = options.segmentLength_m;
    g.radialExaggeration = options.radialExaggeration;
    return g;
}

io::SectionTable readWellFile(const std::string& path, const InputOptions& options,
                              io::Diagnostics* diagnostics) {
    return io::readCaliperLog(path, options.read, diagnostics);
}

}  // namespace caliper3d::app
