// caliper3d compare on a 4 km pair (issue: two runs of one well): the time to read both runs
// against the time of everything `caliper3d compare` does with them (read, path and sections,
// analysis, depth match, earth-frame comparison, CSV), in one process, the same library calls
// the verb makes (app/compare_command.cpp).
//
//   compare_bench [--length M] [--step M] [--dir DIR] [--repeat N] [--threads N] [--keep 1]
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

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

struct Args {
    double length = 4000.0, step = 0.0025;
    std::string dir = "/tmp/caliper3d_compare_bench";
    int repeat = 3, threads = 2;
    bool keep = false;
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
    }
    return a;
}

// What the verb does from the two file names to the CSV, timed by stage.
struct Stages {
    double load = 0.0, analyse = 0.0, match = 0.0, compare = 0.0, write = 0.0;
    double total() const { return load + analyse + match + compare + write; }
};

Stages compareOnce(const std::string& run1, const std::string& run2, const std::string& csv,
                   int threads) {
    Stages s;
    LoadOptions load;
    load.readThreads = std::min(2, threads);
    load.geometryWarnings = false;
    AnalysisOptions analysis;
    analysis.threads = threads;
    Clock::time_point t = Clock::now();
    const LoadedWell a = loadWell({run1}, load);
    const LoadedWell b = loadWell({run2}, load);
    s.load = since(t);
    t = Clock::now();
    const WellAnalysis aa = analyseWell(*a.geometry, analysis);
    const WellAnalysis ba = analyseWell(*b.geometry, analysis);
    s.analyse = since(t);
    t = Clock::now();
    RunComparisonOptions options;
    const std::string curve = chooseMatchCurve(*a.table, *b.table, "");
    options.mapping = fitDepthMapping(matchCurveOf(*a.table, aa, curve),
                                      matchCurveOf(*b.table, ba, curve), DepthMappingOptions{});
    options.mapping.curve = curve;
    s.match = since(t);
    t = Clock::now();
    options.repeatability95_mm = repeatabilityLimit_mm(a.table->armCount);
    options.threads = threads;
    const RunComparison r = compareRuns({a.geometry.get(), &aa}, {b.geometry.get(), &ba}, options);
    s.compare = since(t);
    t = Clock::now();
    writeComparisonCsv(csv, r);
    s.write = since(t);
    std::printf("  shift %+.4f m (correlation %.4f), %zu sections compared, %zu significant\n",
                r.mapping.shift_m, r.mapping.match.correlation, r.compared, r.significant);
    return s;
}

}  // namespace

int main(int argc, char** argv) {
    const Args args = parse(argc, argv);
    std::filesystem::create_directories(args.dir);
    const std::string run1 = args.dir + "/run1.las", run2 = args.dir + "/run2.las";
    SyntheticWellSpec spec = syntheticProfile("example", args.length, args.step);
    spec.gammaRay = true;
    io::writeLasFile(run1, makeSyntheticWell(spec));
    spec.depthOffset_m = 0.35;
    spec.initialToolAzimuth_deg = 90.0;
    spec.features[0].dmax_mm += 10.0;
    io::writeLasFile(run2, makeSyntheticWell(spec));
    std::printf("%s: %.1f MB, %s: %.1f MB\n", run1.c_str(), std::filesystem::file_size(run1) / 1e6,
                run2.c_str(), std::filesystem::file_size(run2) / 1e6);

    std::vector<double> reads, totals;
    std::vector<Stages> stages;
    for (int k = 0; k <= args.repeat; ++k) {
        io::ReadOptions options;
        const Clock::time_point t = Clock::now();
        io::Diagnostics d1, d2;
        const io::SectionTable a = io::readCaliperLog(run1, options, &d1);
        const io::SectionTable b = io::readCaliperLog(run2, options, &d2);
        const double read = since(t);
        std::printf("run %d: read both %.3f s (%zu + %zu rows)\n", k, read, a.rowCount(),
                    b.rowCount());
        const Stages s = compareOnce(run1, run2, args.dir + "/change.csv", args.threads);
        std::printf(
            "  compare %.3f s: load %.3f, analyse %.3f, match %.3f, compare %.3f, "
            "CSV %.3f; ratio %.2f\n",
            s.total(), s.load, s.analyse, s.match, s.compare, s.write, s.total() / read);
        if (k == 0) continue;  // the first run warms the page cache
        reads.push_back(read);
        totals.push_back(s.total());
        stages.push_back(s);
    }
    std::printf("median of %d: read both %.3f s, compare %.3f s, ratio %.2f; peak RSS %.0f MiB\n",
                args.repeat, median(reads), median(totals), median(totals) / median(reads),
                peakMiB());
    if (!args.keep) std::filesystem::remove_all(args.dir);
    return 0;
}
