// caliper3d splice RUN1 RUN2 ... -o OUT.las: runs of one well joined into one log
// (docs/analysis.md, "Splicing runs").
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/input_options.h"
#include "app/input_summary.h"
#include "app/verb_parser.h"
#include "io/casing_program.h"
#include "io/las_writer.h"
#include "io/number_parsing.h"
#include "reconstruction/analysis/match_curve.h"
#include "reconstruction/analysis/run_splice.h"
#include "reconstruction/analysis/well_analysis.h"
#include "reconstruction/load/load_well.h"

namespace caliper3d::app {

namespace {

void addSpliceOptions(QCommandLineParser& p) {
    p.addOption(
        {{"o", "output"}, "The spliced log (LAS 2.0; '-' for standard output).", "OUT.las"});
    p.addOption({"at",
                 "Join the next run at this depth of the log (metres; once per joined run, in "
                 "order; default: the overlap's middle).",
                 "MD"});
    p.addOption({"shift",
                 "Take the next run's depth as the one before's plus this many metres instead "
                 "of matching (once per joined run, or once for all).",
                 "S"});
    p.addOption({"match-curve",
                 "Curve the runs are depth-matched on: a mnemonic both logs carry, or deq; "
                 "default GR when both have a gamma ray, else deq.",
                 "NAME"});
    p.addOption(
        {"max-shift", "Search each depth shift within this many metres (default 2).", "M", "2"});
    p.addOption({"exact-shift",
                 "Apply each matched shift as measured (by default it is rounded to whole "
                 "sampling steps where the runs share one, so the log keeps one step)."});
}

std::vector<double> numbers(VerbParser& verb, const char* name) {
    std::vector<double> out;
    for (const QString& text : verb.parser().values(name)) {
        double v = 0.0;
        if (!io::parseNumber(text.toStdString(), v) || !std::isfinite(v))
            throw UsageError(std::string("caliper3d splice: --") + name +
                             " takes a number of metres, found '" + text.toStdString() + "'");
        out.push_back(v);
    }
    return out;
}

double positive(VerbParser& verb, const char* name) {
    const std::vector<double> v = numbers(verb, name);
    if (v.size() != 1 || !(v.front() > 0.0))
        throw UsageError(std::string("caliper3d splice: --") + name + " takes one number > 0");
    return v.front();
}

struct SpliceRun {
    reconstruction::LoadedWell loaded;
    std::unique_ptr<reconstruction::WellAnalysis> analysis;  // only to match on deq
};

// The depth mapping of each run against the one before.
std::vector<reconstruction::DepthMapping> mappings(VerbParser& verb, std::vector<SpliceRun>& runs) {
    const std::vector<double> shifts = numbers(verb, "shift");
    const std::size_t joins = runs.size() - 1;
    if (!shifts.empty() && shifts.size() != 1 && shifts.size() != joins)
        throw UsageError("caliper3d splice: give --shift once, or once per joined run (" +
                         std::to_string(joins) + ")");
    std::vector<reconstruction::DepthMapping> out;
    reconstruction::DepthMappingOptions options;
    options.match.maxShift_m = positive(verb, "max-shift");
    for (std::size_t k = 1; k < runs.size(); ++k) {
        reconstruction::DepthMapping m;
        if (!shifts.empty()) {
            m.shift_m = shifts.size() == 1 ? shifts.front() : shifts[k - 1];
            m.given = true;
            out.push_back(m);
            continue;
        }
        const io::SectionTable& a = *runs[k - 1].loaded.table;
        const io::SectionTable& b = *runs[k].loaded.table;
        const std::string curve = reconstruction::chooseMatchCurve(a, b, verb.value("match-curve"));
        for (std::size_t i : {k - 1, k})
            if (curve == reconstruction::kEquivalentDiameterCurve && !runs[i].analysis)
                runs[i].analysis = std::make_unique<reconstruction::WellAnalysis>(
                    reconstruction::analyseWell(*runs[i].loaded.geometry, {}));
        const reconstruction::WellAnalysis none;
        const auto analysisOf = [&](std::size_t i) -> const reconstruction::WellAnalysis& {
            return runs[i].analysis ? *runs[i].analysis : none;
        };
        m = reconstruction::fitDepthMapping(
            reconstruction::matchCurveOf(a, analysisOf(k - 1), curve),
            reconstruction::matchCurveOf(b, analysisOf(k), curve), options);
        m.curve = curve == reconstruction::kEquivalentDiameterCurve ? "equivalent diameter" : curve;
        out.push_back(m);
    }
    return out;
}

// printf's "%+.*f" (signed) and "%.*f".
std::string fixed(double v, int decimals, bool sign = true) {
    char text[64];
    std::snprintf(text, sizeof text, sign ? "%+.*f" : "%.*f", decimals, v);
    return text;
}

// What each join did, as printed and kept in the log's ~Other section.
std::string describeJoins(const reconstruction::SplicedLog& log,
                          const std::vector<std::string>& files) {
    std::string s;
    for (const reconstruction::SpliceJoin& j : log.joins) {
        const reconstruction::DepthMapping& m = j.mapping;
        s += "run " + std::to_string(j.run + 1) + " (" + files[j.run] + "): depth " +
             (m.given ? "shift given " + fixed(m.shift_m, 3) + " m"
                      : "matched on " + m.curve + ", " + fixed(m.shift_m, 3) + " m against run " +
                            std::to_string(j.run) + " (correlation " +
                            fixed(m.match.correlation, 3, false) + ")");
        if (m.stretch != 0.0) s += ", stretch " + fixed(m.stretch * 1000.0, 3) + " mm per m";
        s += "; applied " + fixed(j.appliedShift_m, 3) + " m; overlap " +
             fixed(j.overlapTop_m, 2, false) + "-" + fixed(j.overlapBottom_m, 2, false) +
             " m; joined at " + fixed(j.at_m, 3, false) + " m";
        if (std::isfinite(j.until_m)) s += " to " + fixed(j.until_m, 3, false) + " m";
        s += "\n";
    }
    return s;
}

void spliceWells(VerbParser& verb, const std::vector<WellSource>& wells,
                 const std::vector<std::string>& files, InputSummary& summary) {
    LoadOptions load = inputOptionsFrom(verb.parser());
    std::vector<SpliceRun> runs;
    runs.reserve(wells.size());
    for (const WellSource& well : wells)
        runs.push_back(
            {reconstruction::loadWell(well, load, reconstruction::sceneOrigin({well})), nullptr});
    const std::vector<reconstruction::DepthMapping> maps = mappings(verb, runs);
    std::vector<const io::SectionTable*> tables;
    tables.reserve(runs.size());
    for (const SpliceRun& r : runs) tables.push_back(r.loaded.table.get());
    reconstruction::SpliceOptions options;
    options.at_m = numbers(verb, "at");
    if (options.at_m.size() > maps.size())
        throw UsageError("caliper3d splice: --at is given once per joined run at most");
    options.exactShift = verb.isSet("exact-shift");
    const reconstruction::SplicedLog log = reconstruction::spliceRuns(tables, maps, options);

    const std::string joins = describeJoins(log, files);
    io::LasWriteOptions las;
    las.wellName = tables.front()->wellName.empty() ? "CALIPER3D" : tables.front()->wellName;
    // Each run's casing program over its own rows (readCasingProgram reads it back).
    las.parameters = io::casingParameters(log.table.casing);
    las.other = "Spliced by caliper3d splice from " + std::to_string(files.size()) +
                " runs; depths are the first run's.\n" + joins;
    const std::string out = verb.value("output");
    if (out == "-")
        io::writeLas(std::cout, log.table, las);
    else
        io::writeLasFile(out, log.table, las);
    std::cout.flush();
    FILE* info = out == "-" ? stderr : stdout;
    std::fprintf(info, "%zu runs spliced into %zu rows, %.3f-%.3f m\n", files.size(),
                 log.table.rowCount(), log.table.depth_m.front(), log.table.depth_m.back());
    std::fputs(joins.c_str(), info);
    for (const SpliceRun& r : runs) {
        printWarnings(r.loaded.diagnostics);
        summary.addWarnings(r.loaded.diagnostics);
    }
    if (out != "-") {
        std::fprintf(info, "wrote %s\n", out.c_str());
        summary.outputs.push_back(out);
    }
    summary.rows = log.table.rowCount();
    summary.top_m = log.table.depth_m.front();
    summary.bottom_m = log.table.depth_m.back();
}

}  // namespace

int runSplice(const QStringList& args) {
    return guardedVerb("splice", [&]() -> int {
        VerbParser verb("splice", "RUN1 RUN2 ... -o OUT.las",
                        "Join runs of one well (the hole sections below each casing shoe, or a "
                        "repeat over a bad interval), given from the shallowest, into one log: "
                        "each run depth-matched to the one before in their overlap and joined at "
                        "the overlap's middle (--at), every row keeping its own run's curves and "
                        "bit size, and a curve RUN naming the run each row came from.");
        QCommandLineParser& p = verb.parser();
        addSpliceOptions(p);
        addInputOptions(p);
        addWellSourceOptions(p);
        addSummaryOption(p);
        if (!verb.parse(args, 0)) return kExitOk;
        rejectInapplicable(p, "splice", {OptionEffect::Picture},
                           "they shape the 3D picture, and splice writes a log");
        const std::vector<std::string> files = verb.positional();
        if (files.size() < 2)
            throw UsageError("caliper3d splice: give at least two runs, RUN1 RUN2 ...");
        if (!verb.isSet("output")) throw UsageError("caliper3d splice: -o OUT.las is required");
        if (verb.isSet("shift") && verb.isSet("match-curve"))
            throw UsageError("caliper3d splice: --shift and --match-curve exclude each other");
        const std::vector<WellSource> wells = wellSourcesFrom(p, files);
        SummaryFile summaries(verb.value("summary"));
        const double start = steadySeconds();
        InputSummary summary;
        summary.file = files[0];
        summary.verb = "splice";
        int status = kExitOk;
        try {
            spliceWells(verb, wells, files, summary);
        } catch (const UsageError&) {
            throw;
        } catch (const std::exception& e) {
            std::fprintf(stderr, "caliper3d splice: %s\n", e.what());
            summary.error = inputErrorFrom(e, files[0]);
            status = kExitBadInput;
        }
        stampCost(summary, start);
        nlohmann::ordered_json line = toJson(summary);
        line["runs"] = files;
        summaries.write(line);
        return status;
    });
}

}  // namespace caliper3d::app
