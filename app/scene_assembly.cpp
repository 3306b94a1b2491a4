#include "app/scene_assembly.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include "app/change_colouring.h"
#include "app/lean_well.h"
#include "io/parse_error.h"
#include "io/picks_reader.h"
#include "reconstruction/analysis/wall_colour_request.h"
#include "reconstruction/load/load_well.h"
#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/mesh/lod_tree.h"
#include "reconstruction/parallel/built_ahead.h"
#include "reconstruction/parallel/ordered_blocks.h"
#include "reconstruction/well_geometry.h"
#include "scenegraph/colour_legend.h"
#include "scenegraph/pick_markers.h"
#include "scenegraph/picture_scale.h"
#include "scenegraph/render_stats.h"
#include "scenegraph/well_scene.h"

namespace caliper3d::app {

AssembledScene assembleScene(const std::vector<std::string>& files, const LoadOptions& options) {
    std::vector<WellSource> wells;
    wells.reserve(files.size());
    for (const std::string& file : files) wells.push_back({file, {}, {}});
    return assembleScene(wells, options);
}

AssembledScene assembleScene(const std::vector<WellSource>& wells, const LoadOptions& options) {
    return assembleScene(wells, options, ScenePlan());
}

namespace {

// One well as its worker left it: loaded with its picks and the plan of its coarse meshes,
// or the exception that stopped it.
struct LoadSlot {
    reconstruction::LoadedWell well;
    std::vector<io::Pick> picks;
    std::shared_ptr<const reconstruction::CoarsePlan> plan;
    std::exception_ptr error;
    FileStamp stamp;  // the log as it was read
};

// What each well of a field plans of its coarse meshes as it is read, while it holds every
// row (reconstruction::planCoarseMeshes): its levels from `firstLevel` on, for every
// exaggeration the field may be drawn at (the one asked, and any chooseExaggeration picks).
struct MeshPlanning {
    int firstLevel = reconstruction::kFieldFirstCoarseLevel;
    std::vector<double> exaggerations;
};

// One well loaded with its picks (and, with `planning`, its coarse meshes' plan), or the
// exception that stopped it.
LoadSlot loadOne(const WellSource& well, const LoadOptions& options,
                 const reconstruction::Wellhead& origin, const MeshPlanning* planning = nullptr) {
    LoadSlot slot;
    try {
        slot.stamp = stampOf(well.path);
        slot.well = reconstruction::loadWell(well, options, origin);
        if (planning)
            slot.plan =
                std::make_shared<const reconstruction::CoarsePlan>(reconstruction::planCoarseMeshes(
                    *slot.well.geometry, planning->firstLevel, planning->exaggerations, 1));
        if (!well.picksPath.empty()) {
            io::PickFile picks = io::readPicks(well.picksPath);
            slot.well.diagnostics.merge(picks.diagnostics);
            slot.picks = std::move(picks.picks);
        }
    } catch (...) {
        slot.error = std::current_exception();
    }
    return slot;
}

// Loads every well, side by side when there are several: each on one of the machine's threads
// with a one-thread read (a small log's read does not split well in two, and two wells at once
// keep both cores busy through the path and the placement too). One well reads on its own
// options' threads. The slots are in the order of `wells`.
std::vector<LoadSlot> loadAll(const std::vector<WellSource>& wells, const LoadOptions& options,
                              const reconstruction::Wellhead& origin) {
    std::vector<LoadSlot> loads(wells.size());
    LoadOptions each = options;
    int threads = 1;
    if (wells.size() > 1) {
        threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
        each.readThreads = 1;
    }
    reconstruction::forEachBlockInOrder(
        wells.size(), threads,
        [&](std::size_t w, std::size_t) { loads[w] = loadOne(wells[w], each, origin); },
        [](std::size_t) {});
    return loads;
}

// The wells that loaded, in order, with what the scene keeps of each.
struct Loaded {
    std::vector<std::shared_ptr<const reconstruction::WellGeometry>> geometries;
    std::vector<std::string> files;
    std::vector<io::Diagnostics> diagnostics;
    std::vector<std::size_t> inputs;           // each loaded well's place in out.inputs
    std::vector<std::vector<io::Pick>> picks;  // each loaded well's image-log picks
    std::vector<std::size_t> sources;          // each loaded well's place in `wells`
    // A field held lean (FieldRows): the geometries are samples, but where kept whole; each
    // well's own colouring's legend, taken while it held every row.
    bool lean = false;
    std::exception_ptr colourError;  // why a well could not be coloured as asked
    std::vector<char> whole;
    std::vector<reconstruction::ColourLegend> legends;
    std::vector<FileStamp> stamps;  // each well's log as it was read
    // Each well's coarse meshes' plan (null: none was made). A field held lean: the whole
    // well's rows a well is held by (heldRows; empty: held whole), and its own colouring of
    // the rows it holds.
    std::vector<std::shared_ptr<const reconstruction::CoarsePlan>> plans;
    std::vector<std::vector<std::size_t>> heldRows;
    std::vector<std::shared_ptr<const reconstruction::WallColouring>> ownColouring;
};

// Well `w`'s line of out.inputs: its rows and warnings, or why it failed (said on stderr as
// well); a well that loaded joins `kept`. The slot is emptied: the geometry holds the table.
void takeOne(const std::vector<WellSource>& wells, std::size_t w, LoadSlot& slot,
             AssembledScene& out, Loaded& kept) {
    const WellSource& well = wells[w];
    InputSummary& input = out.inputs.emplace_back();
    input.file = well.path;
    try {
        if (slot.error) std::rethrow_exception(slot.error);
        reconstruction::LoadedWell& one = slot.well;
        kept.picks.push_back(std::move(slot.picks));
        kept.plans.push_back(std::move(slot.plan));
        kept.stamps.push_back(slot.stamp);
        kept.geometries.push_back(one.geometry);
        kept.files.push_back(well.path);
        kept.sources.push_back(w);
        const std::vector<double>& md = one.table->depth_m;
        input.rows = md.size();
        if (!md.empty()) std::tie(input.top_m, input.bottom_m) = std::pair(md.front(), md.back());
        input.addWarnings(one.diagnostics);
        kept.inputs.push_back(out.inputs.size() - 1);
        kept.diagnostics.push_back(std::move(one.diagnostics));
    } catch (const std::exception& e) {
        ++out.failures;
        std::fprintf(stderr, "caliper3d: %s\n", e.what());
        input.error = inputErrorFrom(e, well.path);
    }
    slot = LoadSlot{};
}

// Every well loaded fails for one reason (a colouring they share cannot be made): said once on
// stderr and on each well's line; none is drawn.
void failWells(Loaded& loaded, const std::exception& e, AssembledScene& out) {
    out.failures += static_cast<int>(loaded.geometries.size());
    std::fprintf(stderr, "caliper3d: %s\n", e.what());
    for (const std::size_t input : loaded.inputs)
        out.inputs[input].error = inputErrorFrom(e, out.inputs[input].file);
    loaded.geometries.clear();
}

// Each well's line of out.inputs, in order (takeOne).
Loaded takeLoaded(const std::vector<WellSource>& wells, std::vector<LoadSlot> loads,
                  AssembledScene& out) {
    Loaded kept;
    for (std::size_t w = 0; w < wells.size(); ++w) takeOne(wells, w, loads[w], out, kept);
    return kept;
}

// Loads every well as loadAll does, taking each in order as it arrives (takeOne); once the
// wells taken hold more rows than `rows.budget`, every well taken from then on, and those
// before, is kept by the rows its coarse meshes' plan draws and a sample of the rest
// (heldRows), with its own colouring of them (made on the whole well first).
Loaded loadLean(const std::vector<WellSource>& wells, const LoadOptions& options,
                const reconstruction::Wellhead& origin, const FieldRows& rows,
                const MeshPlanning& planning, AssembledScene& out) {
    Loaded kept;
    std::vector<LoadSlot> loads(wells.size());
    LoadOptions each = options;
    each.readThreads = 1;
    const int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    std::size_t held = 0;
    const auto sample = [&](std::size_t k) {
        if (kept.colourError) return;  // the field fails as a whole (failWells)
        std::shared_ptr<const reconstruction::WallColouring> own;
        try {
            own = reconstruction::makeWallColouring(*kept.geometries[k], options.colour);
            kept.legends[k] = own->legend();
        } catch (const std::invalid_argument&) {
            kept.colourError = std::current_exception();
            return;
        }
        kept.ownColouring[k] = own;
        if (rows.keepFirstWhole && kept.sources[k] == 0) return;
        kept.whole[k] = 0;
        const reconstruction::WellGeometry& whole = *kept.geometries[k];
        kept.heldRows[k] = heldRows(whole, *kept.plans[k]);
        kept.ownColouring[k] =
            std::make_shared<const reconstruction::WallColouring>(own->rowsOf(kept.heldRows[k]));
        kept.geometries[k] =
            std::make_shared<const reconstruction::WellGeometry>(whole.sampled(kept.heldRows[k]));
    };
    reconstruction::forEachBlockInOrder(
        wells.size(), threads,
        [&](std::size_t w, std::size_t) { loads[w] = loadOne(wells[w], each, origin, &planning); },
        [&](std::size_t w) {
            const std::size_t before = kept.geometries.size();
            takeOne(wells, w, loads[w], out, kept);
            if (kept.geometries.size() == before) return;  // failed
            kept.whole.push_back(1);
            kept.legends.emplace_back();
            kept.heldRows.emplace_back();
            kept.ownColouring.emplace_back();
            held += kept.geometries.back()->table().rowCount();
            if (kept.lean) {
                sample(before);
            } else if (held > rows.budget) {
                kept.lean = true;
                for (std::size_t k = 0; k < kept.geometries.size(); ++k) sample(k);
            }
        });
    return kept;
}

// Reads a well of a field held lean again from its log, as drawn: its colouring shared with
// the field's (or its own) and the field's exaggeration; what a picture asks for where its
// camera wants finer levels than the coarse meshes (scenegraph::refineForCamera). A log that
// changed since it was loaded is refused, naming it: its finer levels would draw another well.
// Copies what it needs: a picture keeps it.
struct WellReader {
    WellSource source;
    LoadOptions options;
    reconstruction::Wellhead origin;
    double exaggeration = 1.0;
    std::optional<reconstruction::ColourRequest> shared;
    reconstruction::ColourLegend own;
    std::size_t wells = 1;
    FileStamp stamp;

    std::shared_ptr<const reconstruction::WellGeometry> operator()() const {
        const std::shared_ptr<const reconstruction::WellGeometry> whole =
            readWholeAgain(source, options, origin, stamp);
        return std::make_shared<const reconstruction::WellGeometry>(
            whole->restyled(exaggeration, colouring(*whole)));
    }
    std::shared_ptr<const reconstruction::WallColouring> colouring(
        const reconstruction::WellGeometry& whole) const {
        return shared ? reconstruction::sharedWallColouring(whole, *shared, own, wells)
                      : reconstruction::makeWallColouring(whole, options.colour);
    }
};

// Each well's drawn geometry and coarse meshes, built on a worker up to two wells ahead of
// the main thread, which makes their nodes in order (Coin nodes are made on the main thread
// only: docs/threading.md).
struct BuiltWell {
    std::shared_ptr<const reconstruction::WellGeometry> geometry;
    reconstruction::CoarseMeshes meshes;             // the spans only where the segments wait
    scenegraph::WellScene::WaitingSegments waiting;  // segments made when near (build set)
};

// Well `drawn`'s meshes as `plan` says (wholeRows and threads: as buildCoarseMeshes), the
// segments left to be made when a camera comes near where `nodes` says so.
BuiltWell buildPlanned(std::shared_ptr<const reconstruction::WellGeometry> drawn,
                       const std::shared_ptr<const reconstruction::CoarsePlan>& plan,
                       const std::shared_ptr<const std::vector<std::size_t>>& wholeRows,
                       scenegraph::SegmentNodes nodes, int threads) {
    BuiltWell built;
    if (nodes == scenegraph::SegmentNodes::now) {
        built.meshes = reconstruction::buildCoarseMeshes(*drawn, *plan, wholeRows.get(), threads);
    } else {
        scenegraph::PlannedWell planned =
            scenegraph::planWaitingWell(drawn, plan, wholeRows, threads);
        built.meshes.spans = std::move(planned.spans);
        built.waiting = std::move(planned.waiting);
    }
    built.geometry = std::move(drawn);
    return built;
}
using MeshesAhead = reconstruction::BuiltAhead<BuiltWell>;

// A well's scene from its coarse meshes, added to `out` and announced: `drawn` is the geometry
// the meshes were built from, `kept` what the scene keeps of it (a sample, or `drawn`).
void addWell(AssembledScene& out, BuiltWell& built,
             std::shared_ptr<const reconstruction::WellGeometry> kept,
             std::function<std::shared_ptr<const reconstruction::WellGeometry>()> rows,
             const std::vector<io::Pick>& picks, double exaggeration, const std::string& file,
             const io::Diagnostics& diagnostics) {
    const reconstruction::WellGeometry& drawn = *built.geometry;
    auto scene = std::make_shared<scenegraph::WellScene>();
    if (built.waiting.build)
        scene->attachAll(drawn, built.meshes.spans, std::move(built.waiting));
    else
        scene->attachAll(drawn, built.meshes);
    built.meshes = {};
    out.geometries.push_back(std::move(kept));
    out.rows.push_back(std::move(rows));
    out.scenes.push_back(scene);
    out.root->addChild(scene->root());
    if (!picks.empty()) out.root->addChild(scenegraph::makePickMarkers(drawn, picks, exaggeration));
    ++out.wells;
    std::printf("%s: %zu sections, %zu segments, %zu triangles at full detail, %zu warnings\n",
                file.c_str(), drawn.table().rowCount(), scene->segmentCount(),
                scene->fullDetailTriangles(), diagnostics.warningCount);
    printWarnings(diagnostics);
}

// The scene of a field held lean: the exaggeration planned over the samples, the colours shared
// from each well's own legend, and each well's coarse meshes built (a worker ahead of the
// nodes, as MeshesAhead does) from the rows it holds, as its plan says, in its own colouring
// of them under the shared range.
void buildLean(const std::vector<WellSource>& wells, const LoadOptions& options,
               const reconstruction::Wellhead& origin, const ScenePlan& plan,
               const FieldRows& fieldRows, Loaded& loaded, AssembledScene& out) {
    double exaggeration = options.radialExaggeration;
    if (plan) plan(loaded.geometries, exaggeration);
    const std::size_t count = loaded.geometries.size();
    const std::optional<reconstruction::ColourRequest> shared =
        reconstruction::sharedColourRequest(loaded.legends, options.colour);
    std::vector<WellReader> readers;
    readers.reserve(count);
    for (std::size_t k = 0; k < count; ++k)
        readers.push_back({wells[loaded.sources[k]], options, origin, exaggeration, shared,
                           loaded.legends[k], count, loaded.stamps[k]});
    // Two wells at a time, each on one thread (the machine's two cores), while the main thread
    // makes nodes: a well held by its planned rows draws its meshes in a few milliseconds.
    MeshesAhead ahead(
        count,
        [&](std::size_t k) {
            const auto& own = loaded.ownColouring[k];
            return buildPlanned(
                std::make_shared<const reconstruction::WellGeometry>(loaded.geometries[k]->restyled(
                    exaggeration,
                    shared ? reconstruction::sharedWallColouring(*own, *shared, count) : own)),
                loaded.plans[k],
                loaded.whole[k] ? nullptr
                                : std::make_shared<const std::vector<std::size_t>>(
                                      std::move(loaded.heldRows[k])),
                fieldRows.segmentNodes, 1);
        },
        3, 2);
    for (std::size_t k = 0; k < count; ++k) {
        BuiltWell built = ahead.take(k);
        if (k == 0) out.legendColouring = built.geometry->options().colouring;
        std::shared_ptr<const reconstruction::WellGeometry> kept = built.geometry;
        std::function<std::shared_ptr<const reconstruction::WellGeometry>()> rows;
        if (!loaded.whole[k]) {
            kept = std::make_shared<const reconstruction::WellGeometry>(
                loaded.geometries[k]->restyled(exaggeration, nullptr));
            rows = readers[k];
        }
        addWell(out, built, std::move(kept), std::move(rows), loaded.picks[k], exaggeration,
                loaded.files[k], loaded.diagnostics[k]);
    }
}

}  // namespace

AssembledScene assembleScene(const std::vector<WellSource>& wells, const LoadOptions& options,
                             const ScenePlan& plan, int firstCoarseLevel, const FieldRows& rows) {
    const auto start = std::chrono::steady_clock::now();
    AssembledScene out;
    out.root = scenegraph::NodeRef<SoSeparator>(new SoSeparator);
    out.root->setName("caliper3d_scene");
    const reconstruction::Wellhead origin = reconstruction::sceneOrigin(wells);
    const bool mayHoldLean = rows.budget > 0 && wells.size() > 1 && !coloursByChange(options);
    MeshPlanning planning;
    if (mayHoldLean) {
        planning.firstLevel = firstCoarseLevel;
        planning.exaggerations = scenegraph::seriesExaggerations();
        planning.exaggerations.push_back(options.radialExaggeration);
    }
    Loaded wellsLoaded = mayHoldLean ? loadLean(wells, options, origin, rows, planning, out)
                                     : takeLoaded(wells, loadAll(wells, options, origin), out);
    if (wellsLoaded.lean) {
        try {
            if (wellsLoaded.colourError) std::rethrow_exception(wellsLoaded.colourError);
            buildLean(wells, options, origin, plan, rows, wellsLoaded, out);
        } catch (const std::invalid_argument& e) {
            if (!wellsLoaded.colourError) throw;
            failWells(wellsLoaded, e, out);
        }
        out.load_ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        return out;
    }
    // (References, not a structured binding: the lambdas below capture them.)
    auto& loaded = wellsLoaded.geometries;
    const auto& files = wellsLoaded.files;
    const auto& diagnostics = wellsLoaded.diagnostics;
    const auto& loadedInput = wellsLoaded.inputs;
    const auto& picks = wellsLoaded.picks;
    double exaggeration = options.radialExaggeration;
    // A well that cannot be coloured as asked fails them all: they share one legend.
    const auto failAll = [&](const std::exception& e) { failWells(wellsLoaded, e, out); };
    // Colour by change: each whole log against the other run, before a plan cuts an interval
    // out of it (the depth match wants the whole overlap).
    std::vector<reconstruction::RunChange> changes;
    if (coloursByChange(options) && !loaded.empty()) {
        try {
            const ChangeReference reference(options);
            for (const auto& well : loaded) changes.push_back(reference.against(*well));
            for (std::size_t w = 0; w < changes.size(); ++w)
                out.inputs[loadedInput[w]].compared = comparedRuns(changes[w], reference.path());
        } catch (const UsageError&) {
            throw;
        } catch (const std::exception& e) {
            failAll(e);
        }
    }
    // The wells as read (held, so that a well the plan cuts is told apart from them).
    const std::vector<std::shared_ptr<const reconstruction::WellGeometry>> asRead = loaded;
    if (plan && !loaded.empty()) plan(loaded, exaggeration);
    std::vector<std::shared_ptr<const reconstruction::WallColouring>> colourings;
    try {
        if (coloursByChange(options)) {
            std::vector<const reconstruction::RunChange*> each;
            each.reserve(changes.size());
            for (const reconstruction::RunChange& change : changes) each.push_back(&change);
            colourings = reconstruction::changeColourings(loaded, each, options.colour.range);
        } else {
            colourings = reconstruction::wallColourings(loaded, options.colour);
        }
    } catch (const std::exception& e) {
        failAll(e);
    }
    MeshesAhead ahead(loaded.size(), [&](std::size_t w) {
        auto drawn = std::make_shared<const reconstruction::WellGeometry>(
            loaded[w]->restyled(exaggeration, colourings[w]));
        // The plan made as the well was read, unless the scene's plan cut the well.
        std::shared_ptr<const reconstruction::CoarsePlan> planned =
            asRead[w] == loaded[w] ? wellsLoaded.plans[w] : nullptr;
        // (A plan starts at level 1: level 0 keeps every row.)
        if (planned ||
            (rows.segmentNodes == scenegraph::SegmentNodes::whenNear && firstCoarseLevel >= 1)) {
            if (!planned)  // (buildCoarseMeshes(drawn, firstCoarseLevel) plans the same way)
                planned = std::make_shared<const reconstruction::CoarsePlan>(
                    reconstruction::planCoarseMeshes(*drawn, firstCoarseLevel,
                                                     {drawn->options().radialExaggeration}));
            return buildPlanned(std::move(drawn), planned, nullptr, rows.segmentNodes, 2);
        }
        BuiltWell built;
        built.meshes = reconstruction::buildCoarseMeshes(*drawn, firstCoarseLevel);
        built.geometry = std::move(drawn);
        return built;
    });
    for (std::size_t w = 0; w < loaded.size(); ++w) {
        BuiltWell built = ahead.take(w);
        std::shared_ptr<const reconstruction::WellGeometry> kept = built.geometry;
        addWell(out, built, std::move(kept), {}, picks[w], exaggeration, files[w], diagnostics[w]);
    }
    out.load_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return out;
}

const reconstruction::ColourLegend* AssembledScene::legend() const {
    if (legendColouring) return &legendColouring->legend();
    if (geometries.empty() || !geometries.front()->options().colouring) return nullptr;
    return &geometries.front()->options().colouring->legend();
}

std::vector<scenegraph::PictureWell> AssembledScene::pictureWells() const {
    std::vector<scenegraph::PictureWell> wells;
    for (std::size_t w = 0; w < geometries.size(); ++w)
        wells.push_back({geometries[w], scenes[w], w < rows.size() ? rows[w] : nullptr});
    return wells;
}

}  // namespace caliper3d::app
