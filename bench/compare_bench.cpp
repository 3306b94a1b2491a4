// caliper3d compare on a 4 km pair (issue: two runs of one well): the time to read both runs
// against the time of everything `caliper3d compare` does with them (read, path and sections,
// analysis, depth match, earth-frame comparison, CSV), in one process, the same library calls
// the verb makes (app/compare_command.cpp).
//
//   compare_bench [--length M] [--step M] [--dir DIR] [--repeat N] [--threads N] [--keep 1]
//                 [--reuse 1] [--all-outlines 1] [--side-by-side 0]
//
// Run 1 is the synth profile "example" with a gamma ray; run 2 the same hole logged 0.35 m
// deeper by its counter, with the tool 90 degrees round and the breakout 10 mm wider. Both are
// written as LAS 2.0 and read once first, so every figure is from the page cache.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "io/las_writer.h"
#include "io/log_reader.h"
#include "reconstruction/analysis/comparison_writer.h"
#include "reconstruction/analysis/match_curve.h"
#include "reconstruction/analysis/run_comparison.h"
#include "reconstruction/load/load_well.h"
#include "reconstruction/synthetic/synthetic_well.h"

using namespace caliper3d;
using namespace caliper3d::reconstruction;

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

double peakMiB() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

// User and system time of the process, every thread: what a stage costs whatever else the
// machine runs (its wall time on a shared machine depends on the others).
double cpuSeconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const auto s = [](const timeval& t) { return static_cast<double>(t.tv_sec) + t.tv_usec / 1e6; };
    return s(usage.ru_utime) + s(usage.ru_stime);
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

struct Args {
    double length = 4000.0, step = 0.0025;
    std::string dir = "/tmp/caliper3d_compare_bench";
    int repeat = 3, threads = 2;
    bool keep = false;
    bool reuse = false;  // --reuse 1: the two runs already written there (by --keep 1)
    bool allOutlines = false;
    bool sideBySide = true;  // --side-by-side 0: the runs loaded one after the other  //
                             // --all-outlines 1: every oriented section's outline compared
};

Args parse(int argc, char** argv) {
    Args a;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string k = argv[i], v = argv[i + 1];
        if (k == "--length") a.length = std::atof(v.c_str());
        if (k == "--step") a.step = std::atof(v.c_str());
        if (k == "--dir") a.dir = v;
        if (k == "--repeat") a.repeat = std::atoi(v.c_str());
        if (k == "--threads") a.threads = std::atoi(v.c_str());
        if (k == "--keep") a.keep = v == "1";
        if (k == "--reuse") a.reuse = v == "1";
        if (k == "--all-outlines") a.allOutlines = v == "1";
        if (k == "--side-by-side") a.sideBySide = v != "0";
    }
    return a;
}

// What the verb does from the two file names to the CSV, timed by stage.
struct Stages {
    double load = 0.0, analyse = 0.0, match = 0.0, compare = 0.0, write = 0.0;
    // CPU time (every thread) of reading, placing and analysing both runs: work the verb cannot
    // skip, whatever the matching, the comparison and the CSV cost.
    double loadCpu = 0.0;
    double total() const { return load + analyse + match + compare + write; }
};

struct Run {
    LoadedWell well;
    WellAnalysis analysis;
};

// As the verb: both runs read and analysed side by side, each on half the threads; or (with
// `sideBySide` false, to see the stages apart) one after the other on all of them.
void loadBoth(const std::string& run1, const std::string& run2, int threads, bool sideBySide,
              Run& a, Run& b, Stages& s) {
    const double cpu = cpuSeconds();
    LoadOptions load;
    load.geometryWarnings = false;
    AnalysisOptions analysis;
    if (sideBySide && threads > 1) {
        const Clock::time_point t = Clock::now();
        const int half = std::max(1, threads / 2);
        load.readThreads = std::min(2, half);
        analysis.threads = half;
        const auto one = [&](const std::string& path, Run& run) {
            WellSource source;
            source.path = path;
            run.well = loadWell(source, load);
            run.analysis = analyseWell(*run.well.geometry, analysis);
        };
        std::thread second(one, run2, std::ref(b));
        one(run1, a);
        second.join();
        s.load = since(t);  // and the analysis
        s.loadCpu = cpuSeconds() - cpu;
        return;
    }
    load.readThreads = std::min(2, threads);
    analysis.threads = threads;
    Clock::time_point t = Clock::now();
    WellSource source1, source2;
    source1.path = run1;
    source2.path = run2;
    a.well = loadWell(source1, load);
    b.well = loadWell(source2, load);
    s.load = since(t);
    t = Clock::now();
    a.analysis = analyseWell(*a.well.geometry, analysis);
    b.analysis = analyseWell(*b.well.geometry, analysis);
    s.analyse = since(t);
    s.loadCpu = cpuSeconds() - cpu;
}

Stages compareOnce(const std::string& run1, const std::string& run2, const std::string& csv,
                   int threads, bool allOutlines, bool sideBySide) {
    Stages s;
    Run ra, rb;
    loadBoth(run1, run2, threads, sideBySide, ra, rb, s);
    const LoadedWell& a = ra.well;
    const LoadedWell& b = rb.well;
    const WellAnalysis& aa = ra.analysis;
    const WellAnalysis& ba = rb.analysis;
    Clock::time_point t = Clock::now();
    RunComparisonOptions options;
    const std::string curve = chooseMatchCurve(*a.table, *b.table, "");
    DepthMappingOptions matching;
    matching.match.threads = threads;  // as the verb
    options.mapping = fitDepthMapping(matchCurveOf(*a.table, aa, curve),
                                      matchCurveOf(*b.table, ba, curve), matching);
    options.mapping.curve = curve;
    s.match = since(t);
    t = Clock::now();
    options.repeatability95_mm = repeatabilityLimit_mm(a.table->armCount);
    options.threads = threads;
    options.outlineGate = allOutlines ? 0.0 : kCompareOutlineGate;
    const RunComparison r = compareRuns({a.geometry.get(), &aa}, {b.geometry.get(), &ba}, options);
    s.compare = since(t);
    t = Clock::now();
    writeComparisonCsv(csv, r, threads);
    s.write = since(t);
    std::printf(
        "  shift %+.4f m (correlation %.4f), %zu sections compared, %zu significant, %zu "
        "outlines compared, %zu not (gate %.2f mm)\n",
        r.mapping.shift_m, r.mapping.match.correlation, r.compared, r.significant, r.oriented,
        r.outlinesSkipped, r.outlineGate_mm);
    return s;
}

}  // namespace

int main(int argc, char** argv) {
    const Args args = parse(argc, argv);
    std::filesystem::create_directories(args.dir);
    const std::string run1 = args.dir + "/run1.las", run2 = args.dir + "/run2.las";
    if (!args.reuse || !std::filesystem::exists(run1) || !std::filesystem::exists(run2)) {
        SyntheticWellSpec spec = syntheticProfile("example", args.length, args.step);
        spec.gammaRay = true;
        io::writeLasFile(run1, makeSyntheticWell(spec));
        spec.depthOffset_m = 0.35;
        spec.initialToolAzimuth_deg = 90.0;
        spec.features[0].dmax_mm += 10.0;
        io::writeLasFile(run2, makeSyntheticWell(spec));
    }
    std::printf("%s: %.1f MB, %s: %.1f MB\n", run1.c_str(), std::filesystem::file_size(run1) / 1e6,
                run2.c_str(), std::filesystem::file_size(run2) / 1e6);

    std::vector<double> reads, totals, cpuReads, cpuTotals;
    std::vector<Stages> stages;
    for (int k = 0; k <= args.repeat; ++k) {
        io::ReadOptions options;
        const Clock::time_point t = Clock::now();
        const double cpu0 = cpuSeconds();
        io::Diagnostics d1, d2;
        const io::SectionTable a = io::readCaliperLog(run1, options, &d1);
        const io::SectionTable b = io::readCaliperLog(run2, options, &d2);
        const double read = since(t);
        const double cpuRead = cpuSeconds() - cpu0;
        const double cpu1 = cpuSeconds();
        std::printf("run %d: read both %.3f s (%zu + %zu rows)\n", k, read, a.rowCount(),
                    b.rowCount());
        const Stages s = compareOnce(run1, run2, args.dir + "/change.csv", args.threads,
                                     args.allOutlines, args.sideBySide);
        const double cpuCompare = cpuSeconds() - cpu1;
        std::printf(
            "  CPU time: read both %.3f s, compare %.3f s, ratio %.2f; of it reading and "
            "analysing both %.3f s, %.2f x the read\n",
            cpuRead, cpuCompare, cpuCompare / cpuRead, s.loadCpu, s.loadCpu / cpuRead);
        std::printf(
            "  compare %.3f s: load %.3f, analyse %.3f%s, match %.3f, compare %.3f, "
            "CSV %.3f; ratio %.2f\n",
            s.total(), s.load, s.analyse,
            args.sideBySide && args.threads > 1 ? " (side by side: in load)" : "", s.match,
            s.compare, s.write, s.total() / read);
        if (k == 0) continue;  // the first run warms the page cache
        reads.push_back(read);
        totals.push_back(s.total());
        cpuReads.push_back(cpuRead);
        cpuTotals.push_back(cpuCompare);
        stages.push_back(s);
    }
    std::printf("median of %d: read both %.3f s, compare %.3f s, ratio %.2f; peak RSS %.0f MiB\n",
                args.repeat, median(reads), median(totals), median(totals) / median(reads),
                peakMiB());
    std::printf("median CPU time: read both %.3f s, compare %.3f s, ratio %.2f\n", median(cpuReads),
                median(cpuTotals), median(cpuTotals) / median(cpuReads));
    if (!args.keep) std::filesystem::remove_all(args.dir);
    return 0;
}
