// caliper3d compare RUN1 RUN2: two runs of one well, depth-matched and compared in the earth
// frame (docs/analysis.md, "Two runs of one well").
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <future>
#include <iostream>
#include <thread>

#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/input_options.h"
#include "app/input_summary.h"
#include "app/verb_parser.h"
#include "io/number_parsing.h"
#include "reconstruction/analysis/comparison_writer.h"
#include "reconstruction/analysis/run_change.h"
#include "reconstruction/analysis/run_comparison.h"
#include "reconstruction/load/load_well.h"
#include "reconstruction/load/well_warnings.h"

namespace caliper3d::app {

namespace {

void addCompareOptions(QCommandLineParser& p) {
    p.addOption(
        {{"o", "output"}, "Per-depth comparison (CSV; '-' for standard output).", "OUT.csv"});
    p.addOption({"zones",
                 "Also write the zones that appeared, grew, shrank or closed and the intervals "
                 "that changed (CSV; '-' for standard output).",
                 "ZONES.csv"});
    p.addOption({"match-curve",
                 "Curve both runs are depth-matched on: a mnemonic both logs carry, or deq (the "
                 "equivalent diameter); default GR when both have a gamma ray, else deq.",
                 "NAME"});
    p.addOption({"max-shift", "Search the depth shift of RUN2 within this many metres (default 2).",
                 "M", "2"});
    p.addOption(
        {"shift", "Take RUN2's depth as RUN1's plus this many metres instead of matching.", "S"});
    p.addOption({"no-stretch",
                 "Never fit a linear stretch between two tie points (a long overlap's counters "
                 "are otherwise checked for one)."});
    p.addOption({"repeatability",
                 "A diameter change beyond this many millimetres is significant (default: 3 "
                 "for tools of six or more arms or pads, 5 for pad pairs; the larger of the "
                 "two runs').",
                 "MM"});
    p.addOption({"keep-bias",
                 "Do not remove each run's reading offset in casing of known inner diameter."});
    p.addOption({"all-outlines",
                 "Compare the wall at every azimuth on every oriented section (default: only "
                 "where a diameter changed by more than half the repeatability or the major "
                 "axis turned by more than 10 degrees; elsewhere the note says so)."});
    p.addOption({"threads", "Analysis threads (default: the machine's cores).", "N"});
}

double number(VerbParser& verb, const char* name, bool positive) {
    double v = 0.0;
    const std::string text = verb.value(name);
    if (!io::parseNumber(text, v) || !std::isfinite(v) || (positive && !(v > 0.0)))
        throw UsageError(std::string("caliper3d compare: --") + name + " takes a " +
                         (positive ? "number > 0" : "number") + ", found '" + text + "'");
    return v;
}

int threadsFrom(const QCommandLineParser& p) {
    if (!p.isSet("threads"))
        return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    bool ok = false;
    const int threads = p.value("threads").toInt(&ok);
    if (!ok || threads < 1 || threads > 256)
        throw UsageError("caliper3d compare: --threads takes a whole number from 1 to 256");
    return threads;
}

// One run read and analysed.
struct AnalysedRun {
    reconstruction::LoadedWell loaded;
    reconstruction::WellAnalysis analysis;
};

AnalysedRun analyseRun(const WellSource& well, const LoadOptions& load,
                       const reconstruction::AnalysisOptions& options) {
    AnalysedRun run;
    run.loaded = reconstruction::loadWell(well, load, reconstruction::sceneOrigin({well}));
    run.analysis = reconstruction::analyseWell(*run.loaded.geometry, options);
    reconstruction::warnAnalysis(*run.loaded.geometry, run.analysis, run.loaded.diagnostics);
    return run;
}

reconstruction::DepthMapping depthMapping(VerbParser& verb, const AnalysedRun& a,
                                          const AnalysedRun& b, int threads) {
    reconstruction::RunMatchRequest request;
    request.threads = threads;
    if (verb.isSet("shift")) request.shift_m = number(verb, "shift", false);
    request.curve = verb.value("match-curve");
    request.maxShift_m = number(verb, "max-shift", true);
    request.allowStretch = !verb.isSet("no-stretch");
    return reconstruction::matchRuns({a.loaded.geometry.get(), &a.analysis},
                                     {b.loaded.geometry.get(), &b.analysis}, request);
}

// Reads, analyses, matches and compares the two runs; writes the outputs and the summary.
void compareWells(VerbParser& verb, const std::vector<WellSource>& wells, InputSummary& summary) {
    const QCommandLineParser& p = verb.parser();
    LoadOptions load = inputOptionsFrom(p);
    reconstruction::AnalysisOptions analysis;
    analysis.threads = threadsFrom(p);
    load.geometryWarnings = false;
    // The two runs are read and analysed side by side, each on half the threads: a run's path
    // is built on one thread, which the other run's read can use meanwhile.
    const int half = std::max(1, analysis.threads / 2);
    load.readThreads = std::min(2, half);
    reconstruction::AnalysisOptions each = analysis;
    each.threads = half;
    std::future<AnalysedRun> second =
        std::async(analysis.threads > 1 ? std::launch::async : std::launch::deferred,
                   [&] { return analyseRun(wells[1], load, each); });
    const AnalysedRun run1 = analyseRun(wells[0], load, each);
    const AnalysedRun run2 = second.get();

    reconstruction::RunComparisonOptions options;
    options.mapping = depthMapping(verb, run1, run2, analysis.threads);
    options.removeBias = !verb.isSet("keep-bias");
    options.threads = analysis.threads;
    options.outlineGate = verb.isSet("all-outlines") ? 0.0 : reconstruction::kCompareOutlineGate;
    options.repeatability95_mm =
        verb.isSet("repeatability")
            ? number(verb, "repeatability", true)
            : reconstruction::repeatabilityLimit_mm({run1.loaded.geometry.get(), &run1.analysis},
                                                    {run2.loaded.geometry.get(), &run2.analysis});
    auto comparison = std::make_shared<reconstruction::RunComparison>(
        reconstruction::compareRuns({run1.loaded.geometry.get(), &run1.analysis},
                                    {run2.loaded.geometry.get(), &run2.analysis}, options));
    const reconstruction::RunComparison& r = *comparison;

    const std::string out = verb.value("output"), zones = verb.value("zones");
    if (out == "-")
        reconstruction::writeComparisonCsv(std::cout, r, analysis.threads);
    else
        reconstruction::writeComparisonCsv(out, r, analysis.threads);
    if (zones == "-")
        reconstruction::writeZoneChanges(std::cout, r);
    else if (!zones.empty())
        reconstruction::writeZoneChanges(zones, r);
    std::cout.flush();
    FILE* info = out == "-" || zones == "-" ? stderr : stdout;
    std::fprintf(info, "%s (run 1) against %s (run 2): %zu depths of the overlap\n",
                 wells[0].path.c_str(), wells[1].path.c_str(), r.sections.size());
    std::fputs(reconstruction::formatComparisonSummary(r).c_str(), info);
    printWarnings(run1.loaded.diagnostics);
    printWarnings(run2.loaded.diagnostics);
    for (const std::string& written : {out, zones})
        if (!written.empty() && written != "-") {
            std::fprintf(info, "wrote %s\n", written.c_str());
            summary.outputs.push_back(written);
        }
    summary.addWarnings(run1.loaded.diagnostics);
    summary.addWarnings(run2.loaded.diagnostics);
    summary.compared = ComparedRuns{wells[1].path, comparison, r.sections.size(), ""};
}

}  // namespace

int runCompare(const QStringList& args) {
    return guardedVerb("compare", [&]() -> int {
        VerbParser verb("compare", "RUN1 RUN2 -o OUT.csv|-",
                        "Compare two runs of one well: match RUN2's depths to RUN1's, then "
                        "compare their sections at the same depth in the earth frame (diameters, "
                        "areas, the wall at each azimuth), the zones that appeared, grew or "
                        "closed, and the hole volume; changes are RUN2 minus RUN1. --survey "
                        "and --wellhead are given once per run, in order.");
        QCommandLineParser& p = verb.parser();
        addCompareOptions(p);
        addInputOptions(p);
        addWellSourceOptions(p);
        addSummaryOption(p);
        if (!verb.parse(args, 0)) return kExitOk;
        rejectInapplicable(p, "compare", {OptionEffect::Picture},
                           "they shape the 3D picture, and compare measures the logs");
        const std::vector<std::string> files = verb.positional();
        if (files.size() != 2)
            throw UsageError("caliper3d compare: give two runs, RUN1 RUN2 (found " +
                             std::to_string(files.size()) + ")");
        if (!verb.isSet("output")) throw UsageError("caliper3d compare: -o OUT.csv is required");
        if (verb.value("output") == "-" && verb.value("zones") == "-")
            throw UsageError("caliper3d compare: only one of -o and --zones can be '-'");
        if (verb.isSet("shift") && verb.isSet("match-curve"))
            throw UsageError("caliper3d compare: --shift and --match-curve exclude each other");
        const std::vector<WellSource> wells = wellSourcesFrom(p, files);
        SummaryFile summaries(verb.value("summary"));
        const double start = steadySeconds();
        InputSummary summary;
        summary.file = files[0];
        summary.verb = "compare";
        int status = kExitOk;
        try {
            compareWells(verb, wells, summary);
        } catch (const UsageError&) {
            throw;
        } catch (const std::exception& e) {
            std::fprintf(stderr, "caliper3d compare: %s\n", e.what());
            summary.error = inputErrorFrom(e, files[0]);
            status = kExitBadInput;
        }
        stampCost(summary, start);
        nlohmann::ordered_json line = toJson(summary);
        line["file2"] = files[1];  // also where the runs could not be compared
        summaries.write(line);
        return status;
    });
}

}  // namespace caliper3d::app
