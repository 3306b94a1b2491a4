#include "app/input_options.h"

#include <cmath>

#include "io/number_parsing.h"
#include "io/units.h"

namespace caliper3d::app {

void addInputOptions(QCommandLineParser& parser) {
    parser.addOption(
        {"arms", "Number of caliper arms in a column-text file (default 6).", "N", "6"});
    parser.addOption(
        {"depth-unit", "Depth unit of a column-text file: m or ft (default m).", "UNIT", "m"});
    parser.addOption({"radius-unit",
                      "Radius unit of a column-text file: in, mm or cm (default in).", "UNIT",
                      "in"});
    parser.addOption(
        {"bit-size", "Bit size, e.g. 8.5in or 215.9mm (a bare number is inches).", "VALUE"});
    parser.addOption(
        {"points", "Points per section of the closed spline (default 48).", "M", "48"});
    parser.addOption({"segment-length",
                      "Length of one level-of-detail segment in metres (default 10).", "METRES",
                      "10"});
    parser.addOption({"exaggerate",
                      "Draw radii F times larger around the true path (display only; default 1).",
                      "F", "1"});
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
    o.columnText.armCount = static_cast<int>(arms);
    o.columnText.depthUnit = unit(parser, "depth-unit");
    o.columnText.radiusUnit = unit(parser, "radius-unit");
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
        o.bitSize_mm = v * scale;
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
    io::SectionTable table = io::readColumnText(path, options.columnText, diagnostics);
    if (options.bitSize_mm) table.bitSize_mm.assign(table.rowCount(), *options.bitSize_mm);
    return table;
}

}  // namespace caliper3d::app
