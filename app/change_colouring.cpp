#include "app/change_colouring.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "reconstruction/analysis/wall_colour_request.h"

namespace caliper3d::app {

namespace {

std::string fileName(const std::string& path) {
    return std::filesystem::path(path).filename().string();
}

}  // namespace

ComparedRuns comparedRuns(const reconstruction::RunChange& change, const std::string& otherPath) {
    return {otherPath, change.figures, change.md_m.size(),
            change.drawnName + " minus " + change.otherName + ", wall movement in mm"};
}

bool coloursByChange(const LoadOptions& options) {
    return options.colour.quantity == reconstruction::kChangeQuantity;
}

void checkChangeOptions(const LoadOptions& options, const std::string& verb) {
    const bool change = coloursByChange(options);
    if (change && options.colour.compareWith.empty())
        throw UsageError("caliper3d " + verb +
                         ": --colour-by change needs --compare-with RUN, the other run of the "
                         "well");
    if (!change && !options.colour.compareWith.empty())
        throw UsageError("caliper3d " + verb +
                         ": --compare-with names the run a wall coloured by change is compared "
                         "with; give --colour-by change");
}

ChangeReference::ChangeReference(const LoadOptions& options)
    : m_path(options.colour.compareWith),
      m_threads(static_cast<int>(std::max(1u, std::thread::hardware_concurrency()))) {
    if (m_path.empty()) throw UsageError("--colour-by change needs --compare-with RUN");
    WellSource source;
    source.path = m_path;
    LoadOptions load = options;
    load.geometryWarnings = false;
    m_other = reconstruction::loadWell(source, load, reconstruction::sceneOrigin({source}));
    reconstruction::AnalysisOptions analysis;
    analysis.threads = m_threads;
    m_analysis = reconstruction::analyseWell(*m_other.geometry, analysis);
}

reconstruction::RunChange ChangeReference::against(
    const reconstruction::WellGeometry& drawn) const {
    reconstruction::AnalysisOptions options;
    options.threads = m_threads;
    const reconstruction::WellAnalysis analysis = reconstruction::analyseWell(drawn, options);
    reconstruction::RunChange change = reconstruction::measureRunChange(
        {&drawn, &analysis}, {m_other.geometry.get(), &m_analysis}, fileName(drawn.table().source),
        fileName(m_path), {}, m_threads);
    const reconstruction::DepthMapping& m = change.mapping;
    std::printf(
        "colour by change: %s minus %s (wall movement), %s depth = %s depth %+.3f m "
        "(%s, correlation %.3f), %zu of %zu depths compared\n",
        change.drawnName.c_str(), change.otherName.c_str(), change.otherName.c_str(),
        change.drawnName.c_str(), m.shift_m, m.curve.c_str(), m.match.correlation, change.compared,
        drawn.table().rowCount());
    if (!(m.match.correlation >= 0.5))
        std::fprintf(stderr,
                     "caliper3d: %s and %s match weakly (correlation %.2f): the runs may not be "
                     "of one well, or the shift lies beyond 2 m\n",
                     change.drawnName.c_str(), change.otherName.c_str(), m.match.correlation);
    return change;
}

}  // namespace caliper3d::app
