#include "app/desktop/command_arguments.h"

#include <stdexcept>

#include <QCommandLineParser>

namespace caliper3d::app {

namespace {

QStringList optionArguments(const WellOption& option, const std::string& text) {
    return {QString("--") + option.name, QString::fromStdString(text)};
}

}  // namespace

QStringList wellArguments(const std::vector<WellSource>& wells, const LoadOptions& options) {
    QStringList out;
    for (const WellOption& option : wellOptions()) {
        if (option.group != OptionGroup::PerWell) {
            if (const auto text = option.format(WellSource{}, options))
                out << optionArguments(option, *text);
            continue;
        }
        // Given once per file or not at all: a well without it cannot say so in between.
        std::size_t count = 0;
        for (const WellSource& well : wells) count += option.format(well, options) ? 1 : 0;
        if (count != 0 && count != wells.size())
            throw std::invalid_argument(std::string("only some of the wells have --") +
                                        option.name +
                                        "; the command line takes it for every well or none");
        if (count == 0) continue;
        for (const WellSource& well : wells)
            out << optionArguments(option, *option.format(well, options));
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
