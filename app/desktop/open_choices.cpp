#include "app/desktop/open_choices.h"

namespace caliper3d::app {

QStringList openArguments(const OpenChoices& choices) {
    QStringList out{"--arms", QString::number(choices.arms)};
    auto add = [&out](const char* option, const QString& value) {
        if (!value.trimmed().isEmpty()) out << option << value.trimmed();
    };
    add("--radii", choices.radii);
    add("--diameters", choices.diameters);
    add("--depth-unit", choices.depthUnit);
    add("--radius-unit", choices.radiusUnit);
    add("--bit-size", choices.bitSize);
    add("--survey", choices.survey);
    add("--wellhead", choices.wellhead);
    return out << "--" << choices.path;  // "--": a file named "-x" is a file
}

ParsedWells openRequestFrom(const OpenChoices& choices, const LoadOptions& look) {
    ParsedWells out = parseWellArguments(openArguments(choices));
    out.options.radialExaggeration = look.radialExaggeration;
    out.options.colour = look.colour;
    return out;
}

}  // namespace caliper3d::app
