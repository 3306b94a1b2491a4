#include "app/desktop/open_choices.h"

namespace caliper3d::app {

ParsedWells openRequestFrom(const OpenChoices& choices, const LoadOptions& look) {
    ParsedWells out;
    WellSource well;
    well.path = choices.path.toStdString();
    applyOptionTexts(choices.options, well, out.options);
    out.wells = {well};
    out.options.radialExaggeration = look.radialExaggeration;
    out.options.colour = look.colour;
    return out;
}

}  // namespace caliper3d::app
