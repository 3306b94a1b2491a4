#include <cstdio>

#include "app/commands.h"
#include "app/input_options.h"
#include "app/input_summary.h"
#include "app/verb_parser.h"
#include "io/log_reader.h"
#include "io/survey_reader.h"
#include "reconstruction/load/load_well.h"
#include "reconstruction/path/north_reference.h"
#include "reconstruction/path/survey_interpolation.h"
#include "reconstruction/section/section_coverage.h"

namespace caliper3d::app {

int runInfo(const QStringList& args) {
    return guardedVerb("info", [&]() -> int {
        VerbParser verb(
            "info", "FILE...",
            "Describe caliper logs: format, depth range, curves and their roles, nulls, warnings.");
        addInputOptions(verb.parser());
        addSummaryOption(verb.parser());
        if (!verb.parse(args, 1)) return kExitOk;
        rejectInapplicable(verb.parser(), "info", {OptionEffect::Geometry, OptionEffect::Picture},
                           "info describes the file as read; these shape the 3D reconstruction");
        const LoadOptions options = inputOptionsFrom(verb.parser());
        int failures = 0;
        SummaryFile summaries(verb.value("summary"));
        for (const std::string& file : verb.positional()) {
            InputSummary summary;
            summary.file = file;
            summary.verb = "info";
            const double start = steadySeconds();
            try {
                // Rows with a section shape, by the rule the other verbs draw and analyse with.
                const reconstruction::GeometryOptions geometry =
                    reconstruction::geometryOptions(options);
                std::size_t measured = 0;
                int needed = 0, arms = 0;
                io::LogInfo info =
                    io::describeLog(file, options.read, [&](const io::SectionTable& rows) {
                        arms = rows.armCount;
                        needed = reconstruction::minValidArms(arms, geometry.minValidArmFraction);
                        measured += reconstruction::countMeasuredSections(
                            rows, geometry.minValidArmFraction, geometry.minArmRadius_mm,
                            geometry.maxArmRadius_mm);
                    });
                // Which north its azimuths are from, as the other verbs settle it.
                const reconstruction::NorthCorrection north =
                    reconstruction::resolveNorth(info.north, info.location, options.read);
                info.north.resolved = north.summary;
                for (const std::string& warning : north.warnings)
                    info.diagnostics.warn(file, 0, warning);
                std::fputs(io::formatLogInfo(info).c_str(), stdout);
                summary.rows = info.rows;
                summary.top_m = info.top_m;
                summary.bottom_m = info.bottom_m;
                summary.addWarnings(info.diagnostics);
                if (!info.survey) {
                    std::printf(
                        "caliper:   %zu of %zu sections measured (at least %d of %d arms valid)\n",
                        measured, info.rows, needed, arms);
                    if (measured == 0) {
                        // Described, but every other verb refuses it: say so and fail.
                        ++failures;
                        char why[160];
                        std::snprintf(why, sizeof why,
                                      "no usable caliper data: no section has at least %d of its "
                                      "%d arms with a valid reading",
                                      needed, arms);
                        std::fprintf(stderr, "caliper3d info: %s: %s\n", file.c_str(), why);
                        summary.error = InputError{file, 0, why};
                    }
                }
                if (info.survey) {
                    // The positions a survey writes, checked against minimum curvature.
                    const std::string check = reconstruction::describeSurveyPositionCheck(
                        reconstruction::readCheckedSurvey(file, options.read, nullptr).check);
                    if (!check.empty()) std::printf("check:     %s\n", check.c_str());
                }
            } catch (const std::exception& e) {
                ++failures;
                std::fprintf(stderr, "caliper3d info: %s\n", e.what());
                summary.error = inputErrorFrom(e, file);
            }
            stampCost(summary, start);
            summaries.write(summary);
            std::fputs("\n", stdout);
        }
        return failures > 0 ? kExitBadInput : kExitOk;
    });
}

}  // namespace caliper3d::app
