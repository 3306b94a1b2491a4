// How long a new look costs the window once a well is loaded: recolouring by each quantity
// and re-exaggerating, from the geometry in memory (WellGeometry::restyled, the colouring,
// and every segment's coarse levels rebuilt into a new WellScene, as WellSession::restyle
// does). Prints one line a step and the peak resident memory.
//   restyle_bench FILE [QUANTITY...]   (default: departure diameter ellipticity class dls)
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "reconstruction/analysis/wall_colour_request.h"
#include "reconstruction/load/load_well.h"
#include "scenegraph/main_thread.h"
#include "scenegraph/render_stats.h"
#include "scenegraph/well_scene.h"

using namespace caliper3d;
using Clock = std::chrono::steady_clock;

namespace {
double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

void restyle(const reconstruction::WellGeometry& loaded, double exaggeration,
             const std::string& quantity, const reconstruction::SectionValues* values) {
    const auto start = Clock::now();
    reconstruction::ColourRequest request;
    request.quantity = quantity;
    const auto colouring = reconstruction::makeWallColouring(loaded, request, values);
    const double coloured = msSince(start);
    const reconstruction::WellGeometry styled = loaded.restyled(exaggeration, colouring);
    scenegraph::WellScene scene;
    scene.buildAll(styled);
    std::printf("%-12s x%-5g colouring %7.1f ms, with the scene rebuilt %7.1f ms (%zu segments)\n",
                quantity.c_str(), exaggeration, coloured, msSince(start), scene.segmentCount());
}
}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: restyle_bench FILE [QUANTITY...]\n");
        return 2;
    }
    std::vector<std::string> quantities(argv + 2, argv + argc);
    if (quantities.empty()) quantities = {"departure", "diameter", "ellipticity", "class", "dls"};
    scenegraph::initCoin();
    const auto start = Clock::now();
    const reconstruction::LoadedWell loaded =
        reconstruction::loadWell(reconstruction::WellSource{argv[1], {}, {}, {}}, {});
    std::printf("loaded %s: %zu sections in %.0f ms\n", argv[1], loaded.table->rowCount(),
                msSince(start));
    // The first new look also warms the allocator and Coin: it is timed again after.
    restyle(*loaded.geometry, 1.0, "departure", nullptr);
    const auto analysing = Clock::now();
    const reconstruction::SectionValues values = reconstruction::sectionValues(*loaded.geometry);
    std::printf("the report's section values (once, kept by the window): %.0f ms\n",
                msSince(analysing));
    for (const std::string& q : quantities) restyle(*loaded.geometry, 1.0, q, &values);
    restyle(*loaded.geometry, 50.0, quantities.front(), &values);
    std::printf("peak RSS %.0f MB\n", scenegraph::peakRss_mb());
    return 0;
}
