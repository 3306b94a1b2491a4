// Reconstruction of the 4 km well of docs/architecture.md, "Level of detail" (1.6 M sections at
// 2.5 mm, six arms, 48 spline points): path + spline + analysis, on one and
// two threads (geometry and analysis alike). Prints sections per second
// (docs/benchmarks.md, "Reconstruction").
#include <memory>
#include <vector>

#include <benchmark/benchmark.h>

#include "reconstruction/analysis/well_analysis.h"
#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/mesh/lod_tree.h"
#include "reconstruction/synthetic/synthetic_well.h"

using namespace caliper3d;
using namespace caliper3d::reconstruction;

namespace {

std::shared_ptr<const io::SectionTable> fourKilometreWell() {
    static const auto table = std::make_shared<const io::SectionTable>(
        makeSyntheticWell(syntheticProfile("example", 4000.0, 0.0025)));
    return table;
}

void pathSplineAnalysis(benchmark::State& state) {
    const auto table = fourKilometreWell();
    GeometryOptions geometryOptions;
    geometryOptions.threads = static_cast<int>(state.range(0));
    AnalysisOptions options;
    options.threads = static_cast<int>(state.range(0));
    for (auto _ : state) {
        const WellGeometry geometry(table, geometryOptions);
        const WellAnalysis analysis = analyseWell(geometry, options);
        benchmark::DoNotOptimize(analysis.sections.data());
    }
    state.counters["sections/s"] = benchmark::Counter(
        static_cast<double>(table->rowCount()) * state.iterations(), benchmark::Counter::kIsRate);
    state.counters["sections"] = static_cast<double>(table->rowCount());
}

void analysisOnly(benchmark::State& state) {
    const auto table = fourKilometreWell();
    const WellGeometry geometry(table, GeometryOptions{});
    AnalysisOptions options;
    options.threads = static_cast<int>(state.range(0));
    for (auto _ : state) {
        const WellAnalysis analysis = analyseWell(geometry, options);
        benchmark::DoNotOptimize(analysis.sections.data());
    }
    state.counters["sections/s"] = benchmark::Counter(
        static_cast<double>(table->rowCount()) * state.iterations(), benchmark::Counter::kIsRate);
}

// A well of a field held lean, planned as it is read (app/scene_assembly.cpp): the coarse
// meshes of 1 km at 2.5 mm (400,001 sections), level 3 on, for the thirteen radial
// exaggerations a picture may choose and one more, on one thread. Prints sections per second.
void planFieldWell(benchmark::State& state) {
    static const auto table = std::make_shared<const io::SectionTable>(
        makeSyntheticWell(syntheticProfile("example", 1000.0, 0.0025)));
    const WellGeometry geometry(table, GeometryOptions{});
    const std::vector<double> factors = {1, 2, 3, 5, 10, 20, 30, 50, 100, 200, 300, 500, 1000, 7};
    for (auto _ : state) {
        const CoarsePlan plan = planCoarseMeshes(geometry, kFieldFirstCoarseLevel, factors, 1);
        benchmark::DoNotOptimize(plan.spans.data());
    }
    state.counters["sections/s"] = benchmark::Counter(
        static_cast<double>(table->rowCount()) * state.iterations(), benchmark::Counter::kIsRate);
}

// The same well placed (the minimum-curvature path, each row's orientation reading and the
// dogleg severity over a 30 m course) on one thread, as a field's wells are read two at once.
void placeFieldWell(benchmark::State& state) {
    static const auto table = std::make_shared<const io::SectionTable>(
        makeSyntheticWell(syntheticProfile("example", 1000.0, 0.0025)));
    GeometryOptions options;
    options.threads = 1;
    for (auto _ : state) {
        const WellGeometry geometry(table, options);
        benchmark::DoNotOptimize(geometry.path().data());
    }
    state.counters["sections/s"] = benchmark::Counter(
        static_cast<double>(table->rowCount()) * state.iterations(), benchmark::Counter::kIsRate);
}

}  // namespace

BENCHMARK(planFieldWell)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(10);
BENCHMARK(placeFieldWell)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(10);
BENCHMARK(pathSplineAnalysis)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);
BENCHMARK(analysisOnly)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);

BENCHMARK_MAIN();
