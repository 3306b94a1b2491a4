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
#include "app/verb_parser.h"
#include "io/number_parsing.h"
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
    p.addOption({"threads", "Analysis threads (default: the machine's cores).", "N"});
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

// Where the report goes: the section report (-o), and the zone table and the LAS curves where
// asked for (empty where not); each a file, or standard output for '-' (one of them at most).
struct ReportOutputs {
    std::string sections, zones, las;
    bool toStdout = false;
};

ReportOutputs reportOutputs(const VerbParser& verb) {
    ReportOutputs to;
    to.sections = verb.value("output");
    to.zones = verb.isSet("zones") ? verb.value("zones") : std::string();
    to.las = verb.isSet("las") ? verb.value("las") : std::string();
    const int dashes = (to.sections == "-") + (to.zones == "-") + (to.las == "-");
    if (dashes > 1)
        throw UsageError("caliper3d report: only one of -o, --zones and --las can be '-'");
    to.toStdout = dashes == 1;
    return to;
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

}  // namespace

int runReport(const QStringList& args) {
    return guardedVerb("report", [&]() -> int {
        VerbParser verb("report", "FILE -o OUT.csv",
                        "Analyse every section of a well: shape, class, zones, volumes.");
        QCommandLineParser& p = verb.parser();
        addReportOptions(p);
        addInputOptions(p);
        addWellSourceOptions(p);
        if (!verb.parse(args, 0)) return kExitOk;

        reconstruction::AnalysisOptions analysis;
        if (!applyRules(p, analysis.rules)) return kExitOk;
        const std::vector<std::string> files = verb.positional();
        if (files.size() != 1)
            throw UsageError("caliper3d report: give exactly one FILE (found " +
                             std::to_string(files.size()) + "); run it once per well");
        if (!verb.isSet("output")) throw UsageError("caliper3d report: -o OUT.csv is required");
        rejectInapplicable(p, "report", {"exaggerate", "segment-length", "shape-tolerance"},
                           "they shape the 3D picture, and the report measures the log");
        LoadOptions options = inputOptionsFrom(p);
        const WellSource well = wellSourcesFrom(p, files).front();

        reconstruction::ReportOptions report;
        report.step_m = nonNegative(verb, "step");
        report.wellhead = well.wellhead;
        readVolumeOptions(verb, analysis.volume);
        analysis.threads = analysisThreads(p);

        // The analysis adds the geometry's warnings from its own counts (warnAnalysis).
        options.minValidArmFraction = analysis.rules.minValidArmFraction;
        options.geometryWarnings = false;
        reconstruction::LoadedWell loaded =
            reconstruction::loadWell(well, options, reconstruction::sceneOrigin({well}));
        io::Diagnostics& diagnostics = loaded.diagnostics;
        const reconstruction::WellGeometry& geometry = *loaded.geometry;
        const reconstruction::WellAnalysis result = reconstruction::analyseWell(geometry, analysis);
        warnWhereCasingDoesNotFit(result, analysis.volume, well.path, diagnostics);

        const ReportOutputs to = reportOutputs(verb);
        writeReports(to, result, report, std::filesystem::path(well.path).stem().string());

        // With the report on standard output, everything else goes to standard error.
        FILE* info = to.toStdout ? stderr : stdout;
        reconstruction::warnAnalysis(geometry, result, diagnostics);
        std::fprintf(info,
                     "%s: %zu sections, %zu reported, %zu zones, %zu no data, %zu warnings%s\n",
                     well.path.c_str(), result.sections.size(),
                     reconstruction::reportedSections(result, report).size(), result.zones.size(),
                     result.noDataSections, diagnostics.warningCount,
                     well.surveyPath.empty() ? "" : (", path from " + well.surveyPath).c_str());
        std::fputs(reconstruction::formatAnalysisSummary(result).c_str(), info);
        printWarnings(diagnostics);
        for (const std::string& written : {to.sections, to.zones, to.las})
            if (!written.empty() && written != "-")
                std::fprintf(info, "wrote %s\n", written.c_str());
        return kExitOk;
    });
}

}  // namespace caliper3d::app
