#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <thread>
#include <tuple>

#include "app/commands.h"
#include "app/input_options.h"
#include "app/input_summary.h"
#include "app/output_names.h"
#include "app/progress_display.h"
#include "app/verb_parser.h"
#include "io/number_parsing.h"
#include "io/picks_reader.h"
#include "reconstruction/analysis/pick_comparison.h"
#include "reconstruction/analysis/report_writer.h"
#include "reconstruction/analysis/rule_settings.h"
#include "reconstruction/analysis/well_analysis.h"
#include "reconstruction/load/load_well.h"
#include "reconstruction/load/well_warnings.h"

namespace caliper3d::app {

namespace {

double nonNegative(const VerbParser& verb, const char* name) {
    double v = 0.0;
    const std::string text = verb.value(name);
    if (!io::parseNumber(text, v) || !std::isfinite(v) || v < 0.0)
        throw UsageError(std::string("caliper3d report: --") + name +
                         " takes a number >= 0, found '" + text + "'");
    return v;
}

// "TOP,BOTTOM" in metres of measured depth.
std::pair<double, double> interval(const std::string& text) {
    const std::size_t comma = text.find(',');
    double top = 0.0, bottom = 0.0;
    if (comma == std::string::npos || !io::parseNumber(text.substr(0, comma), top) ||
        !io::parseNumber(text.substr(comma + 1), bottom) || !(bottom > top))
        throw UsageError(
            "caliper3d report: --interval takes TOP,BOTTOM in metres with TOP < "
            "BOTTOM, found '" +
            text + "'");
    return {top, bottom};
}

// A casing at least as wide as the hole leaves no annulus: the volumes count
// zero there, which is worth a warning rather than a quiet figure.
void warnWhereCasingDoesNotFit(const reconstruction::WellAnalysis& result,
                               const reconstruction::VolumeOptions& volume, const std::string& file,
                               io::Diagnostics& diagnostics) {
    if (!(volume.casingOd_mm > 0.0)) return;
    std::size_t narrower = 0, inInterval = 0, bitNarrower = 0;
    for (const reconstruction::SectionResult& s : result.sections) {
        if (s.md_m < volume.top_m || s.md_m > volume.bottom_m) continue;
        if (s.cls == reconstruction::BoreholeClass::Cased) continue;  // no volume there
        ++inInterval;
        narrower += s.equivalentDiameter_mm <= volume.casingOd_mm;
        bitNarrower += s.bit_mm <= volume.casingOd_mm;
    }
    char text[256];
    if (bitNarrower > 0) {
        std::snprintf(text, sizeof text,
                      "--casing-od %.1f mm is not smaller than the bit size on %zu of %zu "
                      "sections: the gauge annulus there is counted as zero",
                      volume.casingOd_mm, bitNarrower, inInterval);
        diagnostics.warn(file, 0, text);
    }
    if (narrower > 0) {
        std::snprintf(text, sizeof text,
                      "--casing-od %.1f mm is not smaller than the measured hole on %zu of %zu "
                      "sections: the annulus there is counted as zero",
                      volume.casingOd_mm, narrower, inInterval);
        diagnostics.warn(file, 0, text);
    }
}

// The report verb's own options (the input and well-source ones follow them).
void addReportOptions(QCommandLineParser& p) {
    p.addOption({{"o", "output"}, "Per-section report (CSV; '-' for standard output).", "OUT"});
    p.addOption({"step",
                 "One row every this many metres (the nearest section; default: every section).",
                 "METRES", "0"});
    p.addOption({"zones", "Also write the zone table (CSV; '-' for standard output).", "ZONES"});
    p.addOption(
        {"las", "Also write the computed curves as LAS 2.0 ('-' for standard output).", "OUT.las"});
    p.addOption(
        {"casing-od", "Casing outer diameter for the annular volumes (e.g. 7in).", "LENGTH"});
    p.addOption({"excess", "Cement excess as a fraction (0.3 = 30 %; default 0).", "F", "0"});
    p.addOption({"interval",
                 "Depth interval of the volumes, TOP,BOTTOM in metres (default: the log).",
                 "TOP,BOTTOM"});
    p.addOption({"rule",
                 "Set a classification threshold, NAME=VALUE (repeatable); 'list' prints them "
                 "with their defaults.",
                 "NAME=VALUE"});
    p.addOption({"threads",
                 "Analysis threads (default: the machine's cores); with 1 the log is also read "
                 "on one thread.",
                 "N"});
}

// Applies each --rule in turn; false where one is 'list', which prints the rules (with those
// before it applied) instead.
bool applyRules(const QCommandLineParser& p, reconstruction::ClassificationRules& rules) {
    for (const QString& rule : p.values("rule")) {
        if (rule == "list") {
            std::fputs(reconstruction::describeRules(rules).c_str(), stdout);
            return false;
        }
        try {
            reconstruction::applyRuleSetting(rules, rule.toStdString());
        } catch (const std::invalid_argument& e) {
            throw UsageError(std::string("caliper3d report: --rule: ") + e.what());
        }
    }
    return true;
}

// --casing-od, --excess and --interval.
void readVolumeOptions(const VerbParser& verb, reconstruction::VolumeOptions& volume) {
    if (verb.isSet("casing-od"))
        volume.casingOd_mm = parseLength_mm(verb.value("casing-od"), "--casing-od");
    volume.excess = nonNegative(verb, "excess");
    if (verb.isSet("interval"))
        std::tie(volume.top_m, volume.bottom_m) = interval(verb.value("interval"));
}

// --threads, or the machine's cores.
int analysisThreads(const QCommandLineParser& p) {
    if (!p.isSet("threads"))
        return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    bool ok = false;
    const int threads = p.value("threads").toInt(&ok);
    if (!ok || threads < 1 || threads > 256)
        throw UsageError("caliper3d report: --threads takes a whole number from 1 to 256");
    return threads;
}

// Where one well's report goes: the section report (-o), and the zone table and the LAS
// curves where asked for (empty where not); each a file, or standard output for '-' (one of
// them at most).
struct ReportOutputs {
    std::string sections, zones, las;
    bool toStdout = false;
};

// -o, --zones and --las for each of `files`: one of each per file (a folder or a pattern
// with {stem}) when there are several.
std::vector<ReportOutputs> reportOutputs(const VerbParser& verb,
                                         const std::vector<std::string>& files) {
    const OutputNames sections(verb.value("output"), ".csv");
    const OutputNames zones(verb.isSet("zones") ? verb.value("zones") : "", "-zones.csv");
    const OutputNames las(verb.isSet("las") ? verb.value("las") : "", ".las");
    const int dashes = (sections.spec() == "-") + (zones.spec() == "-") + (las.spec() == "-");
    if (dashes > 1)
        throw UsageError("caliper3d report: only one of -o, --zones and --las can be '-'");
    if (files.size() > 1)
        for (const OutputNames* names : {&sections, &zones, &las})
            if (!names->spec().empty() && !names->perInput())
                throw UsageError("caliper3d report: " + std::to_string(files.size()) +
                                 " files write one report each: give -o (and --zones, --las) a "
                                 "folder (out/) or a pattern with {stem} (out/{stem}.csv), not '" +
                                 names->spec() + "'");
    const std::vector<std::string> sectionFiles = sections.forInputs(files, "-o");
    std::vector<std::string> zoneFiles(files.size()), lasFiles(files.size());
    if (!zones.spec().empty()) zoneFiles = zones.forInputs(files, "--zones");
    if (!las.spec().empty()) lasFiles = las.forInputs(files, "--las");
    std::vector<ReportOutputs> out;
    for (std::size_t i = 0; i < files.size(); ++i)
        out.push_back({sectionFiles[i], zoneFiles[i], lasFiles[i], dashes == 1});
    return out;
}

// Writes each output asked for, standard output flushed.
void writeReports(const ReportOutputs& to, const reconstruction::WellAnalysis& result,
                  const reconstruction::ReportOptions& report, const std::string& wellName) {
    if (to.sections == "-")
        reconstruction::writeSectionReport(std::cout, result, report);
    else
        reconstruction::writeSectionReport(to.sections, result, report);
    if (to.zones == "-")
        reconstruction::writeZoneReport(std::cout, result);
    else if (!to.zones.empty())
        reconstruction::writeZoneReport(to.zones, result);
    if (to.las == "-")
        reconstruction::writeAnalysisLas(std::cout, result, report, wellName);
    else if (!to.las.empty())
        reconstruction::writeAnalysisLas(to.las, result, report, wellName);
    std::cout.flush();
}

// What every well of one run is read and analysed with.
struct ReportSettings {
    LoadOptions load;
    reconstruction::AnalysisOptions analysis;
    reconstruction::ReportOptions report;
};

// Reads, analyses and reports one well; its summary line (the caller stamps the cost).
InputSummary reportWell(const WellSource& well, const ReportSettings& settings,
                        const ReportOutputs& to, ProgressDisplay& progress) {
    InputSummary summary;
    reconstruction::ReportOptions report = settings.report;
    report.wellhead = well.wellhead;
    reconstruction::LoadedWell loaded =
        reconstruction::loadWell(well, settings.load, reconstruction::sceneOrigin({well}));
    io::Diagnostics& diagnostics = loaded.diagnostics;
    const reconstruction::WellGeometry& geometry = *loaded.geometry;
    const reconstruction::WellAnalysis result =
        reconstruction::analyseWell(geometry, settings.analysis);
    warnWhereCasingDoesNotFit(result, settings.analysis.volume, well.path, diagnostics);
    progress.clear();
    writeReports(to, result, report, std::filesystem::path(well.path).stem().string());

    // With the report on standard output, everything else goes to standard error.
    FILE* info = to.toStdout ? stderr : stdout;
    reconstruction::warnAnalysis(geometry, result, diagnostics);
    std::fprintf(info, "%s: %zu sections, %zu reported, %zu zones, %zu no data, %zu warnings%s\n",
                 well.path.c_str(), result.sections.size(),
                 reconstruction::reportedSections(result, report).size(), result.zones.size(),
                 result.noDataSections + result.armsNotOpenSections, diagnostics.warningCount,
                 well.surveyPath.empty() ? "" : (", path from " + well.surveyPath).c_str());
    std::fputs(reconstruction::formatAnalysisSummary(result).c_str(), info);
    if (!well.picksPath.empty()) {
        // Image-log picks beside the caliper's zones (docs/analysis.md, "Picks").
        io::PickFile picks = io::readPicks(well.picksPath);
        diagnostics.merge(picks.diagnostics);
        std::fputs(
            reconstruction::formatPicksComparison(reconstruction::comparePicks(picks.picks, result))
                .c_str(),
            info);
    }
    printWarnings(diagnostics);
    for (const std::string& written : {to.sections, to.zones, to.las})
        if (!written.empty() && written != "-") {
            std::fprintf(info, "wrote %s\n", written.c_str());
            summary.outputs.push_back(written);
        }
    summary.addAnalysis(result);
    summary.addWarnings(diagnostics);
    return summary;
}

// The settings of every well from the options; false where --rule list printed the rules.
bool reportSettings(VerbParser& verb, ReportSettings& settings) {
    const QCommandLineParser& p = verb.parser();
    if (!applyRules(p, settings.analysis.rules)) return false;
    rejectInapplicable(p, "report", {OptionEffect::Picture},
                       "they shape the 3D picture, and the report measures the log");
    settings.load = inputOptionsFrom(p);
    settings.report.step_m = nonNegative(verb, "step");
    readVolumeOptions(verb, settings.analysis.volume);
    settings.analysis.threads = analysisThreads(p);
    settings.load.readThreads = std::min(2, settings.analysis.threads);
    // The analysis adds the geometry's warnings from its own counts (warnAnalysis).
    settings.load.minValidArmFraction = settings.analysis.rules.minValidArmFraction;
    settings.load.geometryWarnings = false;
    return true;
}

}  // namespace

int runReport(const QStringList& args) {
    return guardedVerb("report", [&]() -> int {
        VerbParser verb("report", "FILE... -o OUT.csv|DIR/|PATTERN",
                        "Analyse every section of a well: shape, class, zones, volumes.\n"
                        "With several files, -o (and --zones, --las) take a folder (out/: "
                        "out/STEM.csv, out/STEM-zones.csv, out/STEM.las) or a pattern with "
                        "{stem}, {name} or {index} (out/{stem}.csv); each file is reported on "
                        "its own, and a bad one does not stop the others (exit status 1).");
        QCommandLineParser& p = verb.parser();
        addReportOptions(p);
        addInputOptions(p);
        addWellSourceOptions(p);
        addSummaryOption(p);
        if (!verb.parse(args, 0)) return kExitOk;

        ReportSettings settings;
        if (!reportSettings(verb, settings)) return kExitOk;
        const std::vector<std::string> files = verb.positional();
        if (files.empty()) throw UsageError("caliper3d report: give at least one FILE");
        if (!verb.isSet("output")) throw UsageError("caliper3d report: -o OUT.csv is required");
        const std::vector<WellSource> wells = wellSourcesFrom(p, files);
        const std::vector<ReportOutputs> outputs = reportOutputs(verb, files);
        SummaryFile summaries(verb.value("summary"));
        ProgressDisplay progress(files.size());
        int failures = 0;
        for (std::size_t i = 0; i < wells.size(); ++i) {
            const double start = steadySeconds();
            progress.started(wells[i].path, wells[i].path);
            InputSummary summary;
            try {
                summary = reportWell(wells[i], settings, outputs[i], progress);
            } catch (const std::exception& e) {
                ++failures;
                progress.clear();
                std::fprintf(stderr, "caliper3d report: %s\n", e.what());
                summary.error = inputErrorFrom(e, wells[i].path);
            }
            summary.file = wells[i].path;
            summary.verb = "report";
            stampCost(summary, start);
            summaries.write(summary);
            progress.finished(wells[i].path, !summary.error);
        }
        return failures > 0 ? kExitBadInput : kExitOk;
    });
}

}  // namespace caliper3d::app
