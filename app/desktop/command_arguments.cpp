#include "app/desktop/command_arguments.h"

#include <stdexcept>

#include <QCommandLineParser>

namespace caliper3d::app {

namespace {

QString exact(double value) {
    return QString::number(value, 'g', 17);
}

QString joined(const std::vector<std::string>& names) {
    QStringList out;
    for (const std::string& name : names) out << QString::fromStdString(name);
    return out.join(',');
}

QString unitText(io::LengthUnit unit) {
    const std::string_view name = io::unitName(unit);
    return QString::fromUtf8(name.data(), static_cast<int>(name.size()));
}

// "all" when every well has it, "none" when none has, else throws.
bool everyOrNone(const std::vector<WellSource>& wells, bool (*has)(const WellSource&),
                 const char* what) {
    std::size_t count = 0;
    for (const WellSource& well : wells) count += has(well) ? 1 : 0;
    if (count != 0 && count != wells.size())
        throw std::invalid_argument(std::string("only some of the wells have ") + what +
                                    "; the command line takes one for every well or none");
    return count != 0;
}

}  // namespace

QStringList loadOptionArguments(const LoadOptions& options) {
    const io::ReadOptions& read = options.read;
    QStringList out;
    out << "--arms" << QString::number(read.armCount);
    if (read.depthUnit) out << "--depth-unit" << unitText(*read.depthUnit);
    if (read.radiusUnit) out << "--radius-unit" << unitText(*read.radiusUnit);
    if (!read.roles.radii.empty()) out << "--radii" << joined(read.roles.radii);
    if (!read.roles.diameters.empty()) out << "--diameters" << joined(read.roles.diameters);
    out << "--row-step" << exact(read.rowStep_m);
    out << "--nulls" << (read.nullPolicy == io::NullPolicy::Declared ? "declared" : "common");
    if (read.bitSize_mm) out << "--bit-size" << exact(*read.bitSize_mm) + "mm";
    out << "--points" << QString::number(options.splinePoints);
    out << "--segment-length" << exact(options.segmentLength_m);
    out << "--shape-tolerance" << exact(options.shapeTolerance_mm);
    out << "--exaggerate" << exact(options.radialExaggeration);
    out << "--steep-inclination" << exact(options.steepInclination_deg);
    if (options.toolReach_mm < LoadOptions().toolReach_mm)
        out << "--tool-reach" << exact(options.toolReach_mm) + "mm";
    out << "--colour-by" << QString::fromStdString(options.colour.quantity);
    if (options.colour.range)
        out << "--colour-range"
            << exact(options.colour.range->first) + "," + exact(options.colour.range->second);
    return out;
}

QStringList wellArguments(const std::vector<WellSource>& wells, const LoadOptions& options) {
    const bool surveys = everyOrNone(
        wells, [](const WellSource& w) { return !w.surveyPath.empty(); }, "a survey");
    const bool heads = everyOrNone(
        wells, [](const WellSource& w) { return w.wellhead.has_value(); }, "a wellhead");
    QStringList out = loadOptionArguments(options);
    for (const WellSource& well : wells) {
        if (surveys) out << "--survey" << QString::fromStdString(well.surveyPath);
        if (heads)
            out << "--wellhead"
                << exact(well.wellhead->easting_m) + "," + exact(well.wellhead->northing_m) + "," +
                       exact(well.wellhead->elevation_m);
    }
    out << "--";  // the files last: a file named "-x" is a file
    for (const WellSource& well : wells) out << QString::fromStdString(well.path);
    return out;
}

QStringList exportArguments(const std::vector<WellSource>& wells, const LoadOptions& options,
                            const QString& out) {
    return QStringList{"export", "-o", out, "--progress"} << wellArguments(wells, options);
}

ParsedWells parseWellArguments(const QStringList& arguments) {
    QCommandLineParser parser;
    addInputOptions(parser);
    addColourOptions(parser);
    addWellSourceOptions(parser);
    if (!parser.parse(QStringList{"caliper3d"} << arguments))
        throw UsageError(parser.errorText().toStdString());
    std::vector<std::string> files;
    for (const QString& file : parser.positionalArguments()) files.push_back(file.toStdString());
    ParsedWells out;
    out.options = inputOptionsFrom(parser);
    out.options.colour = colourRequestFrom(parser);
    out.wells = wellSourcesFrom(parser, files);
    return out;
}

}  // namespace caliper3d::app
