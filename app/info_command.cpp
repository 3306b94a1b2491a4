#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/input_options.h"
#include "app/input_summary.h"
#include "app/verb_parser.h"
#include "io/casing_program.h"
#include "io/log_reader.h"
#include "io/median.h"
#include "io/survey_reader.h"
#include "reconstruction/analysis/borehole_classifier.h"
#include "reconstruction/load/load_well.h"
#include "reconstruction/load/wellhead_placement.h"
#include "reconstruction/path/north_reference.h"
#include "reconstruction/path/survey_interpolation.h"
#include "reconstruction/section/invalid_arm_readings.h"
#include "reconstruction/section/section_coverage.h"

namespace caliper3d::app {

namespace {

// Each row's depth and mean diameter (twice the mean of its valid radii; NaN without one).
struct RowReading {
    float md_m;
    float diameter_mm;
};

void addReadings(const io::SectionTable& rows, std::vector<RowReading>& out) {
    for (std::size_t i = 0; i < rows.rowCount(); ++i) {
        const double* r = rows.radii(i);
        double sum = 0.0;
        int valid = 0;
        for (int k = 0; k < rows.armCount; ++k)
            if (std::isfinite(r[k]) && r[k] > 0.0) {
                sum += r[k];
                ++valid;
            }
        out.push_back({static_cast<float>(rows.depth_m[i]),
                       valid > 0 ? static_cast<float>(2.0 * sum / valid) : std::nanf("")});
    }
}

// The calibration check `info` can make without the analysis: per casing string, the median
// mean diameter of the rows inside it against its nominal inner diameter, leaving out rows
// more than the arms-not-open fraction under it (docs/analysis.md, "Cased hole").
void printCasingReadings(const io::LogInfo& info, const std::vector<RowReading>& readings) {
    const double fraction = reconstruction::ClassificationRules{}.armsClosedFraction;
    for (const io::CasingString& c : info.casing) {
        std::vector<double> d;
        std::size_t closed = 0;
        for (const RowReading& r : readings) {
            if (!std::isfinite(r.diameter_mm) || io::casingAt(info.casing, r.md_m) != &c) continue;
            if (r.diameter_mm < c.innerDiameter_mm * (1.0 - fraction)) {
                ++closed;
                continue;
            }
            d.push_back(r.diameter_mm);
        }
        if (d.empty() && closed == 0) continue;  // the log does not reach into it
        std::printf("in casing: to %.2f m, ", c.bottom_m);
        if (d.empty())
            std::printf(
                "no reading (%zu rows read more than %.0f %% under its ID: arms not open)\n",
                closed, 100.0 * fraction);
        else {
            const double median = io::medianInPlace(d);
            std::printf("median mean diameter %.1f mm over %zu rows", median, d.size());
            if (std::isfinite(c.innerDiameter_mm))
                std::printf(", nominal ID %.1f mm, offset %+.1f mm", c.innerDiameter_mm,
                            median - c.innerDiameter_mm);
            if (closed > 0)
                std::printf(" (%zu rows under %.0f %% left out: arms not open)", closed,
                            100.0 * fraction);
            std::printf("\n");
        }
    }
}

// What --survey and --wellhead give a well, as every other verb uses them, and where the
// well is placed in the scene of all the files given (`origin`, sceneOrigin).
void printWellSource(const WellSource& source, const LoadOptions& options,
                     const reconstruction::Wellhead& origin) {
    if (!source.surveyPath.empty()) {
        const reconstruction::CheckedSurvey survey =
            reconstruction::readCheckedSurvey(source.surveyPath, options.read, nullptr);
        const io::SurveyTable& t = survey.table;
        std::printf(
            "survey:    %s: %zu stations, MD %.2f to %.2f m; the path is drawn from it, "
            "not from the log's inclination and azimuth\n",
            source.surveyPath.c_str(), t.stationCount(), t.md_m.front(), t.md_m.back());
        const std::string check = reconstruction::describeSurveyPositionCheck(survey.check);
        if (!check.empty()) std::printf("check:     %s\n", check.c_str());
    }
    if (source.wellhead)
        std::printf(
            "wellhead:  E %.2f m, N %.2f m, elevation %.2f m (--wellhead; places the well "
            "in the scene)\n",
            source.wellhead->easting_m, source.wellhead->northing_m, source.wellhead->elevation_m);
    const reconstruction::WellPlacement placed = reconstruction::placeWell(source, origin);
    if (!placed.wellhead) {
        std::printf("placement: at the %s: %s\n",
                    origin.frame.empty() ? "scene origin" : "first well's head (not placed)",
                    placed.description.c_str());
        return;
    }
    const reconstruction::Ned offset = reconstruction::wellheadOffset(*placed.wellhead, origin);
    std::printf("placement: %s\n", placed.description.c_str());
    if (offset.x == 0.0 && offset.y == 0.0 && offset.z == 0.0)
        std::printf("           the scene origin\n");
    else
        std::printf("           %.2f m north, %.2f m east, %.2f m down from the scene origin\n",
                    offset.x, offset.y, offset.z);
}

// Describes one file on standard output; false where no verb could use it (the reason in
// `summary`).
bool describeWell(const WellSource& source, const LoadOptions& options,
                  const reconstruction::Wellhead& origin, InputSummary& summary) {
    const std::string& file = source.path;
    bool ok = true;
    // Rows with a section shape, by the rule the other verbs draw and analyse with.
    const reconstruction::GeometryOptions geometry = reconstruction::geometryOptions(options);
    std::size_t measured = 0;
    int needed = 0, arms = 0;
    std::vector<RowReading> readings;
    reconstruction::InvalidArmReadings invalid;
    const io::ReadOptions read = reconstruction::readOptionsFor(source, options);
    io::LogInfo info = io::describeLog(
        file, read,
        [&](const io::SectionTable& rows) {
            arms = rows.armCount;
            needed = reconstruction::minValidArms(arms, geometry.minValidArmFraction);
            measured += reconstruction::countMeasuredSections(rows, geometry.minValidArmFraction,
                                                              geometry.minArmRadius_mm,
                                                              geometry.maxArmRadius_mm);
            addReadings(rows, readings);
            if (measured == 0)  // only needed while no section has a shape
                invalid.add(rows, geometry.minValidArmFraction, geometry.minArmRadius_mm,
                            geometry.maxArmRadius_mm);
        },
        !source.surveyPath.empty());
    // Which north its azimuths are from, as the other verbs settle it.
    const reconstruction::NorthCorrection north =
        reconstruction::resolveNorth(info.north, info.location, read);
    info.north.resolved = north.summary;
    for (const std::string& warning : north.warnings) info.diagnostics.warn(file, 0, warning);
    std::fputs(io::formatLogInfo(info).c_str(), stdout);
    printWellSource(source, options, origin);
    summary.rows = info.rows;
    summary.top_m = info.top_m;
    summary.bottom_m = info.bottom_m;
    summary.addWarnings(info.diagnostics);
    if (!info.survey && info.arms == 0) {
        // Described, but no verb can draw it: say why and fail.
        ok = false;
        const std::string why =
            "no caliper curve recognised: name the curves with --radii or "
            "--diameters";
        std::printf("caliper:   none recognised\n");
        std::fflush(stdout);  // the description before the error, where both go to one pipe
        std::fprintf(stderr, "caliper3d info: %s: %s\n", file.c_str(), why.c_str());
        summary.error = InputError{file, 0, why};
    } else if (!info.survey) {
        std::printf("caliper:   %zu of %zu sections measured (at least %d of %d arms valid)\n",
                    measured, info.rows, needed, arms);
        printCasingReadings(info, readings);
        if (measured == 0) {
            // Described, but every other verb refuses it: say why and where, and fail.
            ok = false;
            char why[160];
            std::snprintf(why, sizeof why,
                          "no usable caliper data: no section has at least %d of its "
                          "%d arms with a valid reading: ",
                          needed, arms);
            std::string reason =
                why + reconstruction::describeInvalidArmReadings(invalid, geometry.minArmRadius_mm,
                                                                 geometry.maxArmRadius_mm);
            if (info.firstDataLine > 0)
                reason += "; the first at line " + std::to_string(info.firstDataLine);
            std::fflush(stdout);
            std::fprintf(stderr, "caliper3d info: %s: %s\n", file.c_str(), reason.c_str());
            summary.error = InputError{file, info.firstDataLine, reason};
        }
    }
    if (info.survey) {
        // The positions a survey writes, checked against minimum curvature.
        const std::string check = reconstruction::describeSurveyPositionCheck(
            reconstruction::readCheckedSurvey(file, options.read, nullptr).check);
        if (!check.empty()) std::printf("check:     %s\n", check.c_str());
    }
    return ok;
}

}  // namespace

int runInfo(const QStringList& args) {
    return guardedVerb("info", [&]() -> int {
        VerbParser verb(
            "info", "FILE...",
            "Describe caliper logs: format, depth range, curves and their roles, nulls, warnings.");
        addInputOptions(verb.parser());
        addWellSourceOptions(verb.parser());
        addSummaryOption(verb.parser());
        if (!verb.parse(args, 1)) return kExitOk;
        rejectInapplicable(verb.parser(), "info", {OptionEffect::Geometry, OptionEffect::Picture},
                           "info describes the file as read; these shape the 3D reconstruction");
        const LoadOptions options = inputOptionsFrom(verb.parser());
        const std::vector<WellSource> sources = wellSourcesFrom(verb.parser(), verb.positional());
        int failures = 0;
        // The files given are one scene: placed as every other verb places them.
        const reconstruction::Wellhead origin = reconstruction::sceneOrigin(sources);
        SummaryFile summaries(verb.value("summary"));
        for (const WellSource& source : sources) {
            const std::string& file = source.path;
            InputSummary summary;
            summary.file = file;
            summary.verb = "info";
            const double start = steadySeconds();
            try {
                if (!describeWell(source, options, origin, summary)) ++failures;
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
