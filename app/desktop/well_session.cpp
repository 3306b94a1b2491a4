#include "app/desktop/well_session.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <thread>

#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <QApplication>
#include <QElapsedTimer>
#include <QFileInfo>

#include <Inventor/nodes/SoSeparator.h>

#include "app/desktop/analysis_job.h"
#include "app/desktop/background_job.h"
#include "app/desktop/desk_model.h"
#include "app/desktop/retired_loads.h"
#include "io/picks_reader.h"
#include "io/warnings_text.h"
#include "reconstruction/analysis/run_change.h"
#include "reconstruction/analysis/wall_colour_request.h"
#include "reconstruction/analysis/well_analysis.h"
#include "reconstruction/load/well_load_pipeline.h"
#include "reconstruction/mesh/lod_tree.h"
#include "reconstruction/parallel/built_ahead.h"
#include "scenegraph/picture_scale.h"
#include "scenegraph/section_pick.h"
#include "scenegraph/segment_feeder.h"
#include "scenegraph/well_annotations.h"
#include "scenegraph/well_scene.h"
#include "scenegraph/well_view.h"

namespace caliper3d::app {

namespace {

constexpr double kReadShare = 0.7;         // of a well's progress: reading the log
constexpr int kRenderHeight_px = 768;      // caliper3d render's default picture height
constexpr int kProgressInterval_ms = 200;  // each loading well's fraction into its record
constexpr double kProgressStep = 0.01;     // a change smaller than this is not published

QString fileName(const std::string& path) {
    return QFileInfo(QString::fromStdString(path)).fileName();
}

}  // namespace

// One well being shown: what runs for it and its nodes; its data is in the model. Members
// are destroyed analysis first, then the feeder, the worker, and last the nodes.
struct WellSession::Well {
    int id = -1;
    QString name;  // the file's name, for messages
    std::unique_ptr<scenegraph::WellView> view;
    io::Diagnostics picksDiagnostics;  // the picks file's, kept beside the load's warnings
    std::unique_ptr<reconstruction::WellLoadPipeline> pipeline;
    std::unique_ptr<scenegraph::SegmentFeeder> feeder;
    // After the load (unless the well is made lean straight away), until the analysis is in.
    std::unique_ptr<AnalysisJob> analysisJob;
    std::unique_ptr<BackgroundJob> matchJob;  // another run's depth match to its main run
    // The report's section values, computed the first time a colouring needs them.
    std::shared_ptr<const reconstruction::SectionValues> values;
    bool started = false;  // its pipeline runs (or has run); else it waits its turn
    bool done = false;
    // False while a well loaded as its geometry only (LoadSends::geometryOnly) has no nodes
    // but its path: drawn once, from its plan as it is made lean (holdLean), else whole
    // (drawWhole). The load has not ended for the window until then.
    bool drawn = true;
    FileStamp stamp;  // its log as the load found it: a log read again must be the same
    // How its wall's colours were last made from its own colouring (applyColourings): under the
    // range `shared` gives `sharedWells` wells, else its own; not at all (coloured false) while
    // it is drawn as its load drew it.
    bool coloured = false;
    std::optional<reconstruction::ColourRequest> shared;
    std::size_t sharedWells = 1;
    std::shared_ptr<const LeanForm> lean;    // set while it is held lean
    std::unique_ptr<BackgroundJob> leanJob;  // making it lean, or reading it whole again
    bool leanJobRunning = false;
    // Not tried again (each said once): it could not be made lean, or read whole again (its
    // log changed since it was loaded).
    bool leanRefused = false;
    bool readRefused = false;
    // The lean form it was last drawn from in that form's own colours (holdLean while a field
    // loads), at its record's exaggeration: a restyle to the same draws it the same.
    std::weak_ptr<const LeanForm> drawnOwn;
    bool detailDeferred = false;  // held lean, not given its detail while the field loads
};

// What a well held lean keeps (docs/architecture.md, "The window holds a field lean"): the plan
// of its coarse meshes, made on the whole well for every exaggeration the window may choose and
// the one it is drawn at; the whole well's rows it holds (heldRows); those rows, uncoloured; and
// its own colouring of them. Immutable once made.
struct WellSession::LeanForm {
    std::shared_ptr<const reconstruction::CoarsePlan> plan;
    std::shared_ptr<const std::vector<std::size_t>> rows;
    std::shared_ptr<const reconstruction::WellGeometry> base;
    reconstruction::ColourRequest ownRequest;                      // what ownHeld colours by
    std::shared_ptr<const reconstruction::WallColouring> ownHeld;  // of `rows`, own range
    std::size_t wholeRows = 0;
    // Whether it can be drawn at `exaggeration` coloured by `colour` without reading it again.
    bool draws(double exaggeration, const reconstruction::ColourRequest& colour) const {
        return colour == ownRequest &&
               std::find(plan->exaggerations.begin(), plan->exaggerations.end(), exaggeration) !=
                   plan->exaggerations.end();
    }
};

namespace {

// The analysis the window makes of every well it loads.
reconstruction::AnalysisOptions windowAnalysis(const LoadOptions& options) {
    reconstruction::AnalysisOptions analysis;
    analysis.rules.minValidArmFraction = options.minValidArmFraction;
    analysis.threads = 2;
    return analysis;
}

bool needsSectionValues(const reconstruction::ColourRequest& colour) {
    static const std::vector<std::string> analysed{"diameter", "ellipticity", "class"};
    return std::find(analysed.begin(), analysed.end(), colour.quantity) != analysed.end();
}

// A well's own colouring by `colour` (its own range), made on the whole well: from the section
// values of `analysis` where the quantity needs them, else of the analysis made here.
std::shared_ptr<const reconstruction::WallColouring> ownColouring(
    const reconstruction::WellGeometry& whole, const reconstruction::ColourRequest& colour,
    const reconstruction::WellAnalysis* analysis, const reconstruction::AnalysisOptions& options) {
    std::optional<reconstruction::SectionValues> values;
    if (needsSectionValues(colour))
        values = analysis ? reconstruction::sectionValues(*analysis)
                          : reconstruction::sectionValues(whole, options);
    return reconstruction::makeWallColouring(whole, colour, values ? &*values : nullptr);
}

// The colours drawn from a well's own colouring `own` (whole or some rows): those under the
// shared range, or its own; none where the well is drawn as loaded.
std::shared_ptr<const reconstruction::WallColouring> drawnColouring(
    const std::shared_ptr<const reconstruction::WallColouring>& own, bool coloured,
    const std::optional<reconstruction::ColourRequest>& shared, std::size_t wells) {
    if (!coloured) return nullptr;
    return shared ? reconstruction::sharedWallColouring(*own, *shared, wells) : own;
}

// The exaggerations a well held lean is planned for: every one the window may choose
// (scenegraph::chooseExaggeration) and those of `more`.
std::vector<double> plannedExaggerations(const std::vector<double>& more) {
    std::vector<double> out = scenegraph::seriesExaggerations();
    for (double f : more)
        if (std::find(out.begin(), out.end(), f) == out.end()) out.push_back(f);
    return out;
}

}  // namespace

WellSession::WellSession(DeskModel& model, scenegraph::DetailLoader::CameraProbe probe,
                         QObject* parent)
    : QObject(parent),
      m_model(model),
      m_retired(std::make_unique<RetiredLoads>()),
      m_sceneRoot(scenegraph::makeRef(new SoSeparator)),
      m_detail(std::make_unique<scenegraph::DetailLoader>(std::move(probe))) {
    // A well held lean whose log changed since it was loaded draws no finer levels: said once.
    m_detail->setFailureReport(
        [this](const std::string& message) { emit status(QString::fromStdString(message)); });
    m_progressTimer.setInterval(kProgressInterval_ms);
    connect(&m_progressTimer, &QTimer::timeout, this, &WellSession::publishProgress);
    connect(&m_model, &DeskModel::currentChanged, this, [this] {
        tickCurrentWell();
        followCurrent();
    });
    connect(&m_model, &DeskModel::wellsChanged, this, [this] { tickCurrentWell(); });
}

void WellSession::tickCurrentWell() {
    int withGeometry = 0;
    for (const auto& well : m_wells) {
        const int index = well ? modelIndex(*well) : -1;  // a cancelled well leaves a null
        if (index >= 0 && m_model.well(index).geometry) ++withGeometry;
    }
    for (const auto& well : m_wells) {
        const int index = well ? modelIndex(*well) : -1;
        if (index < 0 || !well->view) continue;
        const DeskWell& record = m_model.well(index);
        if (!record.geometry) continue;
        const bool ticks = withGeometry <= 1 || index == m_model.currentWell();
        if (well->view->depthTicks() == ticks) continue;
        well->view->setDepthTicks(ticks);
        annotate(*well, *record.geometry, record.options.radialExaggeration);
    }
}

void WellSession::annotate(Well& well, const reconstruction::WellGeometry& geometry,
                           double radialExaggeration) {
    well.view->annotate(geometry, radialExaggeration);
    ++m_annotationGeneration;
}

scenegraph::NamesInView WellSession::placeLabels(
    const SoCamera& camera, int width, int height, bool tickMarks,
    const std::vector<scenegraph::ScreenBox>& obstacles) {
    std::vector<Well*> shown;
    std::vector<scenegraph::AnnotatedWell> annotated;
    for (const auto& well : m_wells) {
        const int index = well ? modelIndex(*well) : -1;  // a cancelled well leaves a null
        if (index < 0 || !well->view) continue;
        const DeskWell& record = m_model.well(index);
        if (!record.geometry || !record.visible) continue;
        shown.push_back(well.get());
        annotated.push_back({record.geometry.get(), 0.0, record.options.radialExaggeration,
                             well->view->depthTicks()});
    }
    if (shown.empty() || width <= 0 || height <= 0) return {};
    const scenegraph::PlacedAnnotations placed =
        scenegraph::placeAnnotations(annotated, camera, width, height,
                                     std::numeric_limits<double>::infinity(), tickMarks, obstacles);
    for (std::size_t i = 0; i < shown.size(); ++i)
        shown[i]->view->annotate(*annotated[i].geometry, placed.views[i], placed.labels[i]);
    return scenegraph::namesInView(placed);
}

WellSession::~WellSession() {
    // Stop the workers before the nodes go.
    m_detail.reset();
    m_wells.clear();
}

WellSession::Well* WellSession::find(int id) const {
    for (const auto& well : m_wells)
        if (well->id == id) return well.get();
    return nullptr;
}

int WellSession::modelIndex(const Well& well) const {
    return m_model.indexOf(well.id);
}

template <typename Edit>
void WellSession::edit(const Well& well, Edit change) {
    const int index = modelIndex(well);
    if (index < 0) return;
    DeskWell record = m_model.well(index);
    change(record);
    m_model.updateWell(index, std::move(record));
}

int WellSession::openWell(const QString& path, const LoadOptions& options) {
    return openWell(WellSource{path.toStdString(), {}, {}, {}}, options);
}

int WellSession::openWell(const WellSource& source, const LoadOptions& options) {
    m_detail->removeAll();
    // A restyle reading the wells shown again is for them only (waits for its worker).
    m_leanReadJob.reset();
    m_leanReading = false;
    m_leanPick = {};
    m_wells.clear();
    m_model.clearWells();
    emit warningsChanged();
    m_framed = false;
    m_loadExaggerationWells = 0;
    m_origin = reconstruction::sceneOrigin({source});
    return addWell(source, options);
}

int WellSession::addWell(const QString& path, const LoadOptions& options) {
    return addWell(WellSource{path.toStdString(), {}, {}, {}}, options);
}

int WellSession::addRun(const WellSource& source, const LoadOptions& options, int mainId) {
    const int id = addWell(source, options);
    const int main = m_model.indexOf(mainId);
    if (main < 0 || id == mainId) return id;
    m_model.setRunOf(main, mainId);
    m_model.setRunOf(m_model.indexOf(id), mainId);
    setWellVisible(m_model.indexOf(id), false);
    return id;
}

void WellSession::matchRuns(int index) {
    if (index < 0 || m_model.well(index).runOf < 0) return;
    const int main = m_model.mainRun(index);
    for (const int run : m_model.otherRuns(main)) {
        const DeskWell& a = m_model.well(main);
        const DeskWell& b = m_model.well(run);
        Well* well = find(b.id);
        if (!well || well->matchJob || b.mapping || !b.matchError.isEmpty() || !a.analysis ||
            !b.analysis)
            continue;
        // Matched on a worker (about a second for two 4 km runs at 2.5 mm); the geometries and
        // analyses are immutable and shared, so they stay whatever the window does meanwhile.
        well->matchJob = std::make_unique<BackgroundJob>(
            this,
            [this, id = b.id, mainId = a.id, ga = a.geometry, aa = a.analysis, gb = b.geometry,
             ab = b.analysis]() -> std::function<void()> {
                std::optional<reconstruction::DepthMapping> mapping;
                std::string error;
                try {
                    mapping = reconstruction::matchRuns({ga.get(), aa.get()}, {gb.get(), ab.get()});
                } catch (const std::exception& e) {
                    error = e.what();
                }
                return [this, id, mainId, mapping, error]() {
                    runMatched(id, mainId, mapping, error);
                };
            });
    }
}

void WellSession::runMatched(int id, int mainId,
                             const std::optional<reconstruction::DepthMapping>& mapping,
                             const std::string& error) {
    const int index = m_model.indexOf(id), main = m_model.indexOf(mainId);
    if (index < 0 || main < 0) return;  // closed meanwhile
    DeskWell record = m_model.well(index);
    const QString mainName = m_model.well(main).name;
    record.mapping = mapping;
    if (mapping) {
        emit status(QString("%1 matched to %2: %3 m (%4, correlation %5)")
                        .arg(record.name, mainName)
                        .arg(mapping->shift_m, 0, 'f', 3)
                        .arg(QString::fromStdString(mapping->curve))
                        .arg(mapping->match.correlation, 0, 'f', 3));
    } else {
        record.matchError = QString::fromStdString(error);
        emit status(record.name + ": not matched to " + mainName + ": " + record.matchError);
    }
    m_model.updateWell(index, std::move(record));
}

// The load and the analysis free far more than they keep (a 4 km well at 2.5 mm: the read's
// blocks, the meshes built on the workers, the analysis's scratch), spread over the workers'
// malloc arenas, which glibc keeps mapped. Once every well is in, they go back to the system:
// the window holding a 4 km well loaded and analysed went from 807 to 660 MB resident
// (docs/benchmarks.md, "The window, measured"). No library call does this but glibc's own.
void WellSession::giveBackFreedMemory() {
#ifdef __GLIBC__
    malloc_trim(0);
#endif
}

bool WellSession::allAnalysed() const {
    for (int i = 0; i < m_model.wellCount(); ++i)
        if (m_model.well(i).geometry && !m_model.well(i).analysis) return false;
    return true;
}

namespace {
// The size of the file at `path`; 0 where it cannot be told.
std::uintmax_t fileBytes(const std::string& path) {
    std::error_code error;
    const std::uintmax_t bytes = std::filesystem::file_size(path, error);
    return error ? 0 : bytes;
}

// A well's image-log picks (a small file, read where the markers are made); a file that
// cannot be read is a warning of the well, not a failed load.
io::PickFile picksOf(const std::string& path) {
    io::PickFile picks;
    try {
        picks = io::readPicks(path);
    } catch (const std::exception& e) {
        picks.diagnostics.warn(path, 0, std::string("picks not shown: ") + e.what());
    }
    return picks;
}
}  // namespace

scenegraph::SegmentFeeder::Callbacks WellSession::feederCallbacks(Well& w,
                                                                  const std::string& picksPath) {
    scenegraph::SegmentFeeder::Callbacks callbacks;
    callbacks.geometry = [this, &w,
                          picksPath](std::shared_ptr<const reconstruction::WellGeometry> g) {
        if (!picksPath.empty()) {
            io::PickFile picks = picksOf(picksPath);
            w.picksDiagnostics = picks.diagnostics;
            edit(w, [&picks](DeskWell& record) {
                record.diagnostics.merge(picks.diagnostics);
                record.picks = picks.picks;
            });
            w.view->setPicks(std::move(picks.picks));
        }
        annotate(w, *g, m_model.well(modelIndex(w)).options.radialExaggeration);
        if (w.drawn) m_detail->addWell(w.view->scene(), g);
        edit(w, [&g](DeskWell& record) {
            if (!g->table().wellName.empty())
                record.name = QString::fromStdString(g->table().wellName);
            record.geometry = g;
            // Once a load, not each time the dock shows the well (its row is filled on every
            // step of its load), and from every row, which a well held lean no longer has.
            record.smallestBit_mm = smallestBitSize_mm(g->table());
        });
        tickCurrentWell();
    };
    callbacks.warnings = [this, &w](const io::Diagnostics& diagnostics) {
        edit(w, [&diagnostics, &w](DeskWell& record) {
            record.diagnostics = diagnostics;
            record.diagnostics.merge(w.picksDiagnostics);
        });
        emit warningsChanged();
    };
    callbacks.progress = [this, &w](std::size_t attached) {
        if (!m_framed) {
            m_framed = true;
            emit firstSegmentsShown();
        }
        emit status(QString("Loading %1: %2 segments").arg(w.name).arg(attached));
    };
    callbacks.finished = [this, &w](std::size_t segments) {
        const DeskWell& record = m_model.well(modelIndex(w));
        const std::size_t warnings = record.diagnostics.warningCount;
        // One pass (QString::arg of several strings): the "%1" left for the exaggeration,
        // which the load's end may choose, is not filled by the numbers after it. (A well not
        // drawn yet has no triangles to count.)
        const QString triangles = w.drawn ? QString::number(w.view->scene().fullDetailTriangles()) +
                                                " triangles at full detail, "
                                          : QString();
        m_loadedText = QString("%1: %2 segments, %3radii x%4, %5 warning%6")
                           .arg(w.name, QString::number(segments), triangles, QStringLiteral("%1"),
                                QString::number(warnings), warnings == 1 ? "" : "s");
        emit status(m_loadedText.arg(record.options.radialExaggeration));
        w.done = true;
        edit(w, [](DeskWell& r) { r.loadFraction = 1.0; });
        // Signalled from the event loop, not from inside the feeder's tick, so a slot may
        // open other wells (destroying this feeder) safely; before what the jobs started next
        // hand back.
        ++m_endsQueued;
        QMetaObject::invokeMethod(
            this,
            [this, segments] {
                --m_endsQueued;
                emit wellLoaded(static_cast<int>(segments));
                wellDone();
            },
            Qt::QueuedConnection);
        analyseOrHoldLean(w);
    };
    callbacks.failed = [this, &w](const std::string& message) {
        const QString error = QString::fromStdString(message);
        emit status(w.name + ": failed: " + error);
        w.done = true;
        w.drawn = true;  // nothing to draw
        edit(w, [&error](DeskWell& record) { record.error = error; });
        ++m_endsQueued;
        QMetaObject::invokeMethod(
            this,
            [this, name = w.name, error] {
                --m_endsQueued;
                emit wellFailed(name, error);
                wellDone();
            },
            Qt::QueuedConnection);
    };
    return callbacks;
}

int WellSession::addWell(const WellSource& source, const LoadOptions& options) {
    auto owned = std::make_unique<Well>();
    Well& w = *owned;
    w.id = m_nextId++;
    w.name = fileName(source.path);
    w.stamp = stampOf(source.path);
    // The wells after the first come with their coarsest segment level only: a field seen
    // whole draws its spans' merged meshes, and the detail worker builds finer levels near
    // the camera, as for every well's finest ones.
    const int firstLevel = m_wells.empty() ? reconstruction::kFirstCoarseLevel
                                           : reconstruction::kFieldFirstCoarseLevel;
    w.view = std::make_unique<scenegraph::WellView>(m_sceneRoot.get(), firstLevel);
    m_wells.push_back(std::move(owned));
    m_look = options;

    DeskWell record;
    record.id = w.id;
    record.path = QString::fromStdString(source.path);
    record.name = w.name;
    record.source = source;
    record.options = options;
    m_model.addWell(record);
    emit lookChanged();

    // Survey, log and geometry are all read on the worker (loadWell). A well added while
    // others load reads and is placed on one thread, as render reads a field: the loads at
    // once keep the cores busy, and each thread more is made and ended for every well
    // (docs/benchmarks.md, "Frames while a field loads, and where the window's load still
    // spends"). Its record keeps the options as given.
    LoadOptions loadOptions = options;
    if (std::any_of(m_wells.begin(), m_wells.end() - 1,
                    [](const auto& other) { return other->pipeline && !other->done; }))
        loadOptions.readThreads = 1;
    w.pipeline = std::make_unique<reconstruction::WellLoadPipeline>(source, loadOptions, m_origin,
                                                                    firstLevel);
    emit status("Loading " + w.name + "...");
    w.feeder = std::make_unique<scenegraph::SegmentFeeder>(*w.pipeline, w.view->scene(),
                                                           feederCallbacks(w, source.picksPath));
    startWaitingLoads();
    m_progressTimer.start();
    emit loadStarted();
    return w.id;
}

void WellSession::cancelLoading() {
    std::size_t stopped = 0;
    for (auto& well : m_wells)
        if (!well->done && well->pipeline) {
            well->pipeline->cancel();
            ++stopped;
        }
    if (stopped == 0) return;
    m_detail->removeAll();  // it holds the scenes of wells about to go
    std::vector<std::unique_ptr<Well>> kept;
    for (auto& well : m_wells) {
        if (well->done) {
            kept.push_back(std::move(well));
            continue;
        }
        m_model.removeWell(modelIndex(*well));
        well->feeder.reset();                          // its sensor, on this thread
        m_retired->retire(std::move(well->pipeline));  // joined off this thread
        well.reset();                                  // its nodes leave the scene
    }
    m_wells = std::move(kept);
    for (const auto& well : m_wells) setDetail(*well);
    emit warningsChanged();
    emit status(QString("Loading cancelled: %1 well%2 not loaded")
                    .arg(stopped)
                    .arg(stopped == 1 ? "" : "s"));
    emit loadCancelled();
}

void WellSession::analyse(Well& well) {
    const DeskWell& record = m_model.well(modelIndex(well));
    if (!record.geometry) return;
    reconstruction::AnalysisOptions options;
    options.rules.minValidArmFraction = record.options.minValidArmFraction;
    options.threads = 2;
    well.analysisJob = std::make_unique<AnalysisJob>(
        this, record.geometry, options,
        [this, &well](std::shared_ptr<const reconstruction::WellAnalysis> analysis) {
            edit(well, [&analysis](DeskWell& r) { r.analysis = std::move(analysis); });
            matchRuns(modelIndex(well));
            // A colouring by change waits for the runs' analyses.
            if (m_look.colour.quantity == reconstruction::kChangeQuantity && !loading() &&
                allAnalysed())
                restyle(m_look.radialExaggeration, m_look.colour);
            emit wellAnalysed(modelIndex(well));
            holdLeanWhereDue();
            if (!loading() && allAnalysed()) giveBackFreedMemory();
        });
}

int WellSession::loadsAtOnce() {
    return static_cast<int>(std::max(2u, std::thread::hardware_concurrency()));
}

int WellSession::loadsRunning() const {
    return static_cast<int>(std::count_if(m_wells.begin(), m_wells.end(), [](const auto& well) {
        return well->started && !well->done;
    }));
}

void WellSession::startWaitingLoads() {
    int running = loadsRunning();
    for (const auto& well : m_wells) {
        if (running >= loadsAtOnce()) return;
        if (well->started || well->done || !well->pipeline) continue;
        well->started = true;
        // A well that starts loading with the field past the budget, or bound to pass it once
        // every well is read, is made lean as its load ends: it is read whole, and drawn once, from
        // its plan (holdLean), or whole where it is not made lean (drawWhole); no segment is built
        // to be thrown away. A run of a well stays whole (mayHoldLean): it streams.
        const int index = modelIndex(*well);
        const bool lean =
            (leanDue() || leanExpected()) && index >= 0 && m_model.well(index).runOf < 0;
        well->drawn = !lean;
        well->pipeline->start(lean ? reconstruction::LoadSends::geometryOnly
                                   : reconstruction::LoadSends::streamed);
        ++running;
    }
}

void WellSession::wellDone() {
    startWaitingLoads();
    endLoadWhenDone();
}

void WellSession::endLoadWhenDone() {
    if (loading()) return;
    applyStyleAfterLoad();
    for (const auto& well : m_wells)
        if (well->detailDeferred) setDetail(*well);
    emit allWellsLoaded();
    // An analysis that ended while this end was queued found the session still loading.
    if (allAnalysed()) giveBackFreedMemory();
}

bool WellSession::loading() const {
    return m_endsQueued > 0 || std::any_of(m_wells.begin(), m_wells.end(),
                                           [](const auto& w) { return !w->done || !w->drawn; });
}

double WellSession::loadFraction(const Well& well) const {
    if (well.done || !well.pipeline) return 1.0;
    const auto& g = m_model.well(modelIndex(well)).geometry;
    if (!g) return kReadShare * well.pipeline->readFraction();
    const double segments = std::max<double>(1.0, double(g->segmentCount()));
    return kReadShare +
           (1.0 - kReadShare) * std::min(1.0, double(well.feeder->attached()) / segments);
}

LoadProgress WellSession::progress() const {
    LoadProgress out;
    double sum = 0.0;
    int count = 0;
    for (const auto& well : m_wells) {
        if (well->done || !well->pipeline) continue;
        ++count;
        sum += loadFraction(*well);
        if (!m_model.well(modelIndex(*well)).geometry)
            // A streamed load draws the stretches read while it reads on.
            out.text =
                (well->feeder->attached() > 0 ? "Reading and drawing " : "Reading ") + well->name;
        else
            out.text = "Drawing " + well->name;
    }
    out.busy = count > 0;
    if (count > 1)
        out.text = QString("Loading %1 wells, %2 of %3 done")
                       .arg(count)
                       .arg(m_wells.size() - std::size_t(count))
                       .arg(m_wells.size());
    if (out.busy) out.fraction = sum / count;
    return out;
}

void WellSession::publishProgress() {
    for (const auto& well : m_wells) {
        if (well->done) continue;
        const double fraction = loadFraction(*well);
        const int index = modelIndex(*well);
        if (index >= 0 && std::abs(m_model.well(index).loadFraction - fraction) >= kProgressStep)
            edit(*well, [fraction](DeskWell& r) { r.loadFraction = fraction; });
    }
    if (!loading()) m_progressTimer.stop();
}

std::size_t WellSession::warningCount() const {
    std::size_t count = 0;
    for (int i = 0; i < m_model.wellCount(); ++i) count += m_model.well(i).diagnostics.warningCount;
    return count;
}

QString WellSession::warningsText() const {
    QString text;
    for (int i = 0; i < m_model.wellCount(); ++i)
        text += QString::fromStdString(io::formatWarnings(m_model.well(i).diagnostics));
    return text;
}

std::vector<WellSource> WellSession::wellSources() const {
    std::vector<WellSource> out;
    out.reserve(static_cast<std::size_t>(m_model.wellCount()));
    for (int i = 0; i < m_model.wellCount(); ++i) out.push_back(m_model.well(i).source);
    return out;
}

const reconstruction::ColourLegend* WellSession::legend() const {
    return m_legend ? &*m_legend : nullptr;
}

std::vector<SoNode*> WellSession::wellScenes() const {
    std::vector<SoNode*> out;
    for (const auto& well : m_wells)
        if (well->view->visible()) out.push_back(well->view->scene().root());
    return out;
}

std::shared_ptr<const reconstruction::WellGeometry> WellSession::geometry(std::size_t i) const {
    return i < std::size_t(m_model.wellCount()) ? m_model.well(int(i)).geometry : nullptr;
}

const scenegraph::WellScene* WellSession::scene(std::size_t i) const {
    if (i >= std::size_t(m_model.wellCount())) return nullptr;
    const Well* well = find(m_model.well(int(i)).id);
    return well && well->view ? &well->view->scene() : nullptr;
}

std::vector<std::string> WellSession::colourQuantities() const {
    std::vector<std::string> names{"departure", "diameter", "ellipticity", "class", "dls"};
    for (int i = 0; i < m_model.wellCount(); ++i)
        if (m_model.well(i).geometry) {
            names = reconstruction::colourQuantities(m_model.well(i).geometry->table());
            break;
        }
    for (int i = 0; i < m_model.wellCount(); ++i)
        if (m_model.well(i).runOf >= 0) {
            names.insert(names.begin() + 5, reconstruction::kChangeQuantity);
            break;
        }
    return names;
}

int WellSession::retiredLoadsRunning() const {
    return m_retired->running();
}

void WellSession::setWellVisible(int well, bool visible) {
    if (well < 0 || well >= m_model.wellCount()) return;
    Well* w = find(m_model.well(well).id);
    if (!w) return;
    w->view->setVisible(visible);
    m_model.setVisible(well, visible);
    ++m_annotationGeneration;  // the labels of the wells shown are placed again
}

std::optional<WellPick> WellSession::pick(SoNode* root, const SbViewportRegion& viewport,
                                          const SbVec2s& pixel) {
    std::vector<scenegraph::PickableWell> wells;
    std::vector<int> index;
    for (const auto& well : m_wells) {
        const int i = modelIndex(*well);
        const DeskWell& record = m_model.well(i);
        if (!record.geometry || !well->view->visible()) continue;
        if (well->lean) {
            wells.push_back({&well->view->scene(), record.geometry.get(), nullptr,
                             record.name.toStdString(), well->lean->rows.get()});
        } else if (record.analysis) {
            wells.push_back({&well->view->scene(), record.geometry.get(), record.analysis.get(),
                             record.name.toStdString(), nullptr});
        } else {
            continue;
        }
        index.push_back(i);
    }
    if (wells.empty()) return std::nullopt;
    const std::optional<scenegraph::SectionPick> hit =
        scenegraph::pickSection(root, viewport, pixel, wells);
    if (!hit) return std::nullopt;
    WellPick out;
    out.well = index[hit->well];
    out.row = hit->wall.row;
    out.azimuth_deg = hit->wall.azimuth_deg;
    const DeskWell& record = m_model.well(out.well);
    if (!hit->analysed) {
        m_leanPick = {record.id, hit->segment, hit->point};
        out.text = QString("%1 near %2 m MD: held lean, its log is read again for the section hit")
                       .arg(record.name)
                       .arg(record.geometry->table().depth_m[out.row], 0, 'f', 2);
        return out;
    }
    m_leanPick = {};
    out.text = QString("%1 at %2 m MD: radius %3 mm at azimuth %4")
                   .arg(QString::fromStdString(hit->wellName))
                   .arg(hit->section.md_m, 0, 'f', 2)
                   .arg(hit->wall.radius_mm, 0, 'f', 1)
                   .arg(hit->wall.azimuth_deg, 0, 'f', 0);
    return out;
}

bool WellSession::restyle(double radialExaggeration, const reconstruction::ColourRequest& colour) {
    return restyleWells(radialExaggeration, colour, -1, [this, radialExaggeration, colour] {
        m_look.radialExaggeration = radialExaggeration;
        m_look.colour = colour;
        emit lookChanged();
    });
}

bool WellSession::restyleWell(int well, const reconstruction::ColourRequest& colour) {
    if (well < 0 || well >= m_model.wellCount()) return false;
    const DeskWell& record = m_model.well(well);
    return restyleWells(record.options.radialExaggeration, colour, record.id, {});
}

bool WellSession::restyleWells(double radialExaggeration,
                               const reconstruction::ColourRequest& colour, int onlyId,
                               const std::function<void()>& applied) {
    if (m_wells.empty()) return false;
    if (loading()) {
        emit status("Wait for the wells to load before changing how they are drawn");
        return false;
    }
    if (colour.quantity == reconstruction::kChangeQuantity)
        return startChangeColouring(radialExaggeration, colour, onlyId, applied);
    // A well held lean that cannot be drawn so from what it holds is read again first.
    for (const auto& well : m_wells)
        if (well->lean && (onlyId < 0 || well->id == onlyId) &&
            !well->lean->draws(radialExaggeration, colour))
            return startLeanReading(radialExaggeration, colour, onlyId, applied);
    QElapsedTimer clock;
    clock.start();
    const bool needsValues = needsSectionValues(colour);
    std::vector<ColouredWell> coloured;
    // Each well's own colouring first (a well held lean has its own of the rows it holds),
    // then the range they share: reconstruction::wallColourings, in its two steps.
    std::vector<std::shared_ptr<const reconstruction::WallColouring>> own;
    std::vector<const reconstruction::SectionValues*> values;
    std::vector<reconstruction::ColourLegend> legends;
    QApplication::setOverrideCursor(Qt::WaitCursor);
    try {
        for (const auto& well : m_wells) {
            const DeskWell& record = m_model.well(modelIndex(*well));
            if (!record.geometry || (onlyId >= 0 && well->id != onlyId)) continue;
            if (well->lean) {
                own.push_back(well->lean->ownHeld);
                values.push_back(nullptr);
            } else {
                if (needsValues && !well->values)
                    well->values = std::make_shared<const reconstruction::SectionValues>(
                        record.analysis ? reconstruction::sectionValues(*record.analysis)
                                        : reconstruction::sectionValues(*record.geometry));
                values.push_back(well->values.get());
                own.push_back(
                    reconstruction::makeWallColouring(*record.geometry, colour, values.back()));
            }
            legends.push_back(own.back()->legend());
            coloured.push_back(
                {well->id, record.geometry, own.back(), well->lean, std::nullopt, 1});
        }
        const std::optional<reconstruction::ColourRequest> shared =
            reconstruction::sharedColourRequest(legends, colour);
        for (std::size_t w = 0; shared && w < coloured.size(); ++w) {
            coloured[w].shared = shared;
            coloured[w].wells = coloured.size();
            coloured[w].colouring =
                coloured[w].lean
                    ? reconstruction::sharedWallColouring(*own[w], *shared, coloured.size())
                    : reconstruction::sharedWallColouring(*coloured[w].geometry, *shared,
                                                          legends[w], coloured.size(), values[w]);
        }
    } catch (const std::exception& e) {
        QApplication::restoreOverrideCursor();
        emit status(QString::fromStdString(e.what()));
        return false;
    }
    applyColourings(radialExaggeration, colour, coloured, clock);
    QApplication::restoreOverrideCursor();
    if (applied) applied();
    return true;
}

void WellSession::applyColourings(double radialExaggeration,
                                  const reconstruction::ColourRequest& colour,
                                  const std::vector<ColouredWell>& coloured,
                                  const QElapsedTimer& clock) {
    ++m_styleGeneration;
    m_detail->removeAll();
    // The wells restyled, each with its new colours and what it is drawn from.
    struct Restyle {
        Well* well = nullptr;
        const ColouredWell* coloured = nullptr;
        std::shared_ptr<const reconstruction::WellGeometry> whole;  // held whole
        std::shared_ptr<const LeanForm> lean;                       // held lean
        int firstLevel = reconstruction::kFirstCoarseLevel;
    };
    std::vector<Restyle> restyles;
    for (auto& well : m_wells) {
        const DeskWell& record = m_model.well(modelIndex(*well));
        // A well closed, or loaded again, since its colours were made keeps its own.
        const auto it = std::find_if(coloured.begin(), coloured.end(), [&](const ColouredWell& c) {
            return c.id == well->id && c.geometry == record.geometry && c.lean == well->lean;
        });
        if (it == coloured.end()) {
            setDetail(*well);
            continue;
        }
        // Drawn from its plan in its own colours at this exaggeration while the field loaded
        // (holdLean): this restyle would draw it the same.
        if (well->lean && well->drawnOwn.lock() == well->lean && !it->shared &&
            it->colouring == well->lean->ownHeld && well->lean->ownRequest == colour &&
            record.geometry->options().radialExaggeration == radialExaggeration) {
            well->coloured = true;
            well->shared.reset();
            well->sharedWells = it->wells;
            edit(*well, [&](DeskWell& r) { r.options.colour = colour; });
            setDetail(*well);
            continue;
        }
        well->drawnOwn.reset();
        restyles.push_back(
            {well.get(), &*it, record.geometry, well->lean, well->view->firstCoarseLevel()});
    }
    // Each well's restyled geometry and coarse meshes, built on two workers ahead of the main
    // thread, which makes their nodes in order (Coin nodes are made on the main thread only:
    // docs/threading.md). A well held lean is drawn from its plan and the rows it holds, its
    // segments made when near (a few milliseconds); one held whole is planned and built whole.
    struct Drawn {
        std::shared_ptr<const reconstruction::WellGeometry> geometry;
        reconstruction::CoarseMeshes meshes;  // held whole
        scenegraph::PlannedWell planned;      // held lean
    };
    reconstruction::BuiltAhead<Drawn> ahead(
        restyles.size(),
        [&restyles, radialExaggeration](std::size_t k) {
            const Restyle& r = restyles[k];
            Drawn drawn;
            if (r.lean) {
                drawn.geometry = std::make_shared<const reconstruction::WellGeometry>(
                    r.lean->base->restyled(radialExaggeration, r.coloured->colouring));
                drawn.planned =
                    scenegraph::planWaitingWell(drawn.geometry, r.lean->plan, r.lean->rows, 1);
            } else {
                drawn.geometry = std::make_shared<const reconstruction::WellGeometry>(
                    r.whole->restyled(radialExaggeration, r.coloured->colouring));
                drawn.meshes = reconstruction::buildCoarseMeshes(*drawn.geometry, r.firstLevel);
            }
            return drawn;
        },
        2, 2);
    for (std::size_t k = 0; k < restyles.size(); ++k) {
        Well* const well = restyles[k].well;
        const ColouredWell* const it = restyles[k].coloured;
        Drawn drawn = ahead.take(k);
        const std::shared_ptr<const reconstruction::WellGeometry> restyled = drawn.geometry;
        if (restyles[k].lean)
            well->view->rebuild(*restyled, std::move(drawn.planned), radialExaggeration);
        else
            well->view->rebuild(*restyled, drawn.meshes, radialExaggeration);
        drawn.meshes = {};
        ++m_annotationGeneration;
        well->drawn = true;
        well->coloured = true;
        well->shared = it->shared;
        well->sharedWells = it->wells;
        edit(*well, [&](DeskWell& r) {
            r.geometry = restyled;
            r.options.radialExaggeration = radialExaggeration;
            r.options.colour = colour;
        });
        setDetail(*well);
    }
    m_legend.reset();
    if (!coloured.empty()) m_legend = coloured.front().colouring->legend();
    emit lookChanged();
    emit status(QString("Coloured by %1, radii x%2 (%3 ms, nothing read again)")
                    .arg(QString::fromStdString(colour.quantity))
                    .arg(radialExaggeration)
                    .arg(clock.elapsed()));
}

namespace {

// A drawn run and the run it is compared with, as the worker compares them.
struct RunPair {
    int id = -1;
    std::shared_ptr<const reconstruction::WellGeometry> geometry, otherGeometry;
    std::shared_ptr<const reconstruction::WellAnalysis> analysis, otherAnalysis;
    std::string name, otherName;
};

}  // namespace

// Each chosen well's wall against the run it is compared with: the main run's against its
// first other run, another run's against the main run (docs/analysis.md, "Colour by change").
// The runs are matched and compared on a worker (seconds for two 4 km runs at 2.5 mm); the
// colours are applied on the main thread when they are in.
bool WellSession::startChangeColouring(double radialExaggeration,
                                       const reconstruction::ColourRequest& colour, int onlyId,
                                       const std::function<void()>& applied) {
    std::vector<RunPair> pairs;
    for (const auto& well : m_wells) {
        const int i = modelIndex(*well);
        const DeskWell& record = m_model.well(i);
        if (!record.geometry || (onlyId >= 0 && well->id != onlyId)) continue;
        const std::vector<int> others = m_model.otherRuns(i);
        QString error;
        if (others.empty())
            error = record.name +
                    ": no other run of the well to compare with (open runs with view RUN1 RUN2 "
                    "--runs)";
        else if (!record.analysis || !m_model.well(others.front()).analysis)
            error = "Wait for the runs to be analysed before colouring by change";
        if (!error.isEmpty()) {
            emit status(error);
            return false;
        }
        const DeskWell& other = m_model.well(others.front());
        pairs.push_back({well->id, record.geometry, other.geometry, record.analysis, other.analysis,
                         fileName(record.source.path).toStdString(),
                         fileName(other.source.path).toStdString()});
    }
    QElapsedTimer clock;
    clock.start();
    m_changeJob = std::make_unique<BackgroundJob>(
        this, [this, pairs, radialExaggeration, colour, clock, applied]() -> std::function<void()> {
            std::vector<ColouredWell> coloured;
            std::string error;
            try {
                std::vector<reconstruction::RunChange> changes;
                std::vector<std::shared_ptr<const reconstruction::WellGeometry>> geometries;
                changes.reserve(pairs.size());
                geometries.reserve(pairs.size());
                for (const RunPair& p : pairs) {
                    changes.push_back(reconstruction::measureRunChange(
                        {p.geometry.get(), p.analysis.get()},
                        {p.otherGeometry.get(), p.otherAnalysis.get()}, p.name, p.otherName, {},
                        2));
                    geometries.push_back(p.geometry);
                }
                std::vector<const reconstruction::RunChange*> each;
                each.reserve(changes.size());
                for (const reconstruction::RunChange& change : changes) each.push_back(&change);
                const auto colourings =
                    reconstruction::changeColourings(geometries, each, colour.range);
                coloured.reserve(pairs.size());
                for (std::size_t w = 0; w < pairs.size(); ++w)
                    coloured.push_back(
                        {pairs[w].id, pairs[w].geometry, colourings[w], nullptr, std::nullopt, 1});
            } catch (const std::exception& e) {
                error = e.what();
            }
            return [this, coloured, error, radialExaggeration, colour, clock, applied]() {
                if (!error.empty()) {
                    emit status(QString::fromStdString(error));
                    return;
                }
                applyColourings(radialExaggeration, colour, coloured, clock);
                if (applied) applied();
            };
        });
    emit status("Comparing the runs to colour the wall by their change...");
    return true;
}

std::vector<double> WellSession::drawnExaggerations() const {
    std::vector<double> out;
    for (const auto& well : m_wells) {
        const int index = modelIndex(*well);
        if (index < 0 || !well->drawn || !m_model.well(index).geometry) continue;
        const double f = m_model.well(index).geometry->options().radialExaggeration;
        if (std::find(out.begin(), out.end(), f) == out.end()) out.push_back(f);
    }
    if (out.empty()) out.push_back(m_look.radialExaggeration);
    std::sort(out.begin(), out.end());
    return out;
}

double WellSession::loadExaggeration() {
    if (m_exaggerationKept) return m_look.radialExaggeration;
    std::vector<std::shared_ptr<const reconstruction::WellGeometry>> geometries;
    for (int i = 0; i < m_model.wellCount(); ++i)
        if (m_model.well(i).geometry) geometries.push_back(m_model.well(i).geometry);
    const int placed = static_cast<int>(geometries.size());
    if (m_loadExaggerationWells == 0 || placed >= 2 * m_loadExaggerationWells) {
        m_loadExaggeration = scenegraph::chooseExaggeration(
            geometries, 0.0, std::numeric_limits<double>::infinity(), kRenderHeight_px);
        m_loadExaggerationWells = std::max(1, placed);
    }
    return m_loadExaggeration;
}

// Once every well is loaded: its colours as asked (a quantity other than the departure from
// bit size, a range, a well without a bit size) and the legend.
void WellSession::applyStyleAfterLoad() {
    std::vector<std::shared_ptr<const reconstruction::WellGeometry>> geometries;
    for (int i = 0; i < m_model.wellCount(); ++i)
        if (m_model.well(i).geometry) geometries.push_back(m_model.well(i).geometry);
    if (geometries.empty()) return;
    const reconstruction::ColourRequest colour = m_look.colour;
    // Colouring by change waits for the runs' analyses (the analysis job restyles then).
    if (colour.quantity == reconstruction::kChangeQuantity && !allAnalysed()) return;
    bool rebuild = colour.quantity != "departure" || colour.range.has_value();
    double exaggeration = m_look.radialExaggeration;
    if (!m_exaggerationKept)  // what render's default picture draws: a hole that reads as a tube
        exaggeration = scenegraph::chooseExaggeration(
            geometries, 0.0, std::numeric_limits<double>::infinity(), kRenderHeight_px);
    const bool chosen = exaggeration != m_look.radialExaggeration;
    rebuild = rebuild || chosen;
    for (const auto& g : geometries) {
        bool anyBit = false;
        for (std::size_t row = 0; row < g->table().rowCount() && !anyBit; ++row)
            anyBit = std::isfinite(g->bitRadius_mm(row));
        rebuild = rebuild || !anyBit;
    }
    // A restyle here keeps the load's own status line.
    QSignalBlocker quiet(this);
    if (rebuild && restyle(exaggeration, colour)) {
        quiet.unblock();
        emit lookChanged();
        if (chosen) emit status(m_loadedText.arg(exaggeration));
        return;
    }
    // The streamed segments are coloured as asked already: only the legend is new.
    QString error;
    try {
        m_legend = reconstruction::wallColourings({geometries.front()}, colour).front()->legend();
    } catch (const std::exception& e) {
        error = QString::fromStdString(e.what());
        m_legend.reset();
    }
    quiet.unblock();
    if (!error.isEmpty()) emit status(error);
    emit lookChanged();
}

std::vector<scenegraph::PictureWell> WellSession::pictureWells() const {
    std::vector<scenegraph::PictureWell> out;
    for (int i = 0; i < m_model.wellCount(); ++i) {
        const DeskWell& record = m_model.well(i);
        if (!record.geometry || !record.visible) continue;
        const Well* well = find(record.id);
        if (!well || !well->lean) {
            out.push_back(scenegraph::pictureWells({record.geometry}).front());
            continue;
        }
        auto scene = std::make_shared<scenegraph::WellScene>();
        scene->attachAll(*record.geometry,
                         reconstruction::buildCoarseMeshes(*record.geometry, *well->lean->plan,
                                                           well->lean->rows.get(), 2));
        out.push_back({record.geometry, std::move(scene), wholeReader(*well)});
    }
    return out;
}

bool WellSession::heldLean(int well) const {
    if (well < 0 || well >= m_model.wellCount()) return false;
    const Well* w = find(m_model.well(well).id);
    return w && w->lean;
}

int WellSession::leanJobsRunning() const {
    int running = m_leanReading ? 1 : 0;
    for (const auto& well : m_wells)
        if (well && well->leanJobRunning) ++running;
    return running;
}

bool WellSession::settled() const {
    if (loading() || leanJobsRunning() > 0) return false;
    for (int i = 0; i < m_model.wellCount(); ++i)
        if (m_model.well(i).geometry && !m_model.well(i).analysis && !heldLean(i)) return false;
    return true;
}

bool WellSession::mayBeLean() const {
    return m_rowBudget != 0 && m_wells.size() >= 2 &&
           m_look.colour.quantity != reconstruction::kChangeQuantity;
}

std::optional<std::size_t> WellSession::placedRows(const Well& well) const {
    const int index = modelIndex(well);
    if (index < 0) return std::nullopt;
    if (well.lean) return well.lean->wholeRows;
    const auto& geometry = m_model.well(index).geometry;
    if (geometry) return geometry->table().rowCount();
    return std::nullopt;
}

bool WellSession::leanDue() const {
    if (!mayBeLean()) return false;
    std::size_t rows = 0;
    for (const auto& well : m_wells)
        if (well) rows += placedRows(*well).value_or(0);
    return rows > m_rowBudget;
}

bool WellSession::leanExpected() const {
    if (!mayBeLean()) return false;
    // The rows and file bytes of the wells placed, and the bytes of the files of those not yet
    // placed.
    std::size_t rows = 0;
    std::uintmax_t placedBytes = 0, waitingBytes = 0;
    for (const auto& well : m_wells) {
        const int index = well ? modelIndex(*well) : -1;
        if (index < 0) continue;
        const DeskWell& record = m_model.well(index);
        if (const std::optional<std::size_t> placed = placedRows(*well)) {
            rows += *placed;
            placedBytes += fileBytes(record.source.path);
        } else if (record.error.isEmpty()) {
            waitingBytes += fileBytes(record.source.path);
        }
    }
    if (rows == 0 || placedBytes == 0) return false;  // nothing to go by yet
    // The waiting files' rows at the bytes a row took in the files placed, halved: a log of
    // the field may write twice the bytes a row (more curves, wider numbers). Where that
    // still overestimates, the wells loaded as their geometry only are drawn whole as their
    // loads end (drawWhole), as a well no longer due to be lean is.
    const double perByte = static_cast<double>(rows) / static_cast<double>(placedBytes);
    return static_cast<double>(rows) + 0.5 * perByte * static_cast<double>(waitingBytes) >
           static_cast<double>(m_rowBudget);
}

bool WellSession::mayHoldLean(const Well& well) const {
    const int index = modelIndex(well);
    if (index < 0 || index == m_model.currentWell() || well.lean || well.leanJobRunning ||
        !well.done || well.leanRefused)
        return false;
    const DeskWell& record = m_model.well(index);
    // The runs of one well stay whole: their depth match and comparison read every row.
    return record.geometry && record.runOf < 0;
}

void WellSession::analyseOrHoldLean(Well& well) {
    if (mayHoldLean(well) && leanDue()) {
        startLeanForm(well);
        // And the wells loaded and analysed whole before this one took the field past the
        // budget: no analysis ending after it would make them lean.
        holdLeanWhereDue();
    } else {
        drawWhole(well);
        analyse(well);
    }
}

void WellSession::drawWhole(Well& well) {
    if (well.drawn) return;
    well.drawn = true;
    const int index = modelIndex(well);
    if (index < 0 || !well.view) return;
    const auto& geometry = m_model.well(index).geometry;
    if (geometry)
        drawNow(well,
                [&] { well.view->rebuild(*geometry, geometry->options().radialExaggeration); });
    else
        endLoadWhenDone();
}

void WellSession::drawNow(Well& well, const std::function<void()>& rebuild) {
    m_detail->removeWell(well.view->scene());  // the scene goes
    rebuild();
    ++m_annotationGeneration;
    well.drawn = true;
    setDetail(well);
    endLoadWhenDone();
}

void WellSession::analyseIfWhole(Well& well) {
    const int index = modelIndex(well);
    if (index < 0 || well.lean || well.leanJobRunning || m_model.well(index).analysis ||
        well.analysisJob)
        return;
    analyse(well);
}

void WellSession::holdLeanWhereDue() {
    if (!leanDue()) return;
    for (const auto& well : m_wells) {
        // A well whose analysis is under way is made lean once it is in.
        if (!well || !mayHoldLean(*well) ||
            (well->analysisJob && !m_model.well(modelIndex(*well)).analysis))
            continue;
        startLeanForm(*well);
    }
}

void WellSession::startLeanForm(Well& well) {
    const DeskWell& record = m_model.well(modelIndex(well));
    well.leanJobRunning = true;
    well.leanJob = std::make_unique<BackgroundJob>(
        this,
        [this, id = well.id, generation = m_styleGeneration, whole = record.geometry,
         analysis = record.analysis, colour = record.options.colour,
         options = windowAnalysis(record.options), firstLevel = well.view->firstCoarseLevel(),
         // While the field loads its loads keep the cores busy: the plan takes one thread.
         threads = loading() ? 1 : 2]() -> std::function<void()> {
            auto form = std::make_shared<LeanForm>();
            std::string error;
            try {
                form->plan = std::make_shared<const reconstruction::CoarsePlan>(
                    reconstruction::planCoarseMeshes(
                        *whole, firstLevel,
                        plannedExaggerations({whole->options().radialExaggeration}), threads));
                form->rows =
                    std::make_shared<const std::vector<std::size_t>>(heldRows(*whole, *form->plan));
                form->base = std::make_shared<const reconstruction::WellGeometry>(
                    whole->sampled(*form->rows));
                form->ownRequest = colour;
                form->ownHeld = std::make_shared<const reconstruction::WallColouring>(
                    ownColouring(*whole, colour, analysis.get(), options)->rowsOf(*form->rows));
                form->wholeRows = whole->table().rowCount();
            } catch (const std::exception& e) {
                error = e.what();
            }
            return [this, id, generation, whole, form, error]() {
                Well* w = find(id);
                if (!w) return;
                w->leanJobRunning = false;
                const int index = modelIndex(*w);
                if (index < 0) return;
                edit(*w, [](DeskWell& r) { r.makingLean = false; });
                if (!error.empty()) {  // it stays whole
                    w->leanRefused = true;
                    emit status(w->name + ": not held lean: " + QString::fromStdString(error));
                } else if (generation != m_styleGeneration ||
                           m_model.well(index).geometry != whole) {
                    holdLeanWhereDue();  // restyled meanwhile: made again from the well as drawn
                } else if (index != m_model.currentWell() && leanDue()) {
                    holdLean(*w, form);
                }
                // Not made lean (refused, made current meanwhile, no longer due): drawn whole
                // where its load drew nothing, and analysed.
                if (!w->leanJobRunning) drawWhole(*w);
                analyseIfWhole(*w);
                // Not while the field loads: the next wells' reads would fault in fresh pages
                // for what the trim gave back (docs/benchmarks.md, "The window's field load").
                if (leanJobsRunning() == 0 && !loading()) giveBackFreedMemory();
            };
        });
    edit(well, [](DeskWell& r) { r.makingLean = true; });  // after `record` is read
}

void WellSession::holdLean(Well& well, std::shared_ptr<const LeanForm> form) {
    const DeskWell& record = m_model.well(modelIndex(well));
    // A well its load drew nothing of, while a field loads: drawn at the exaggeration the
    // wells placed so far would get, in its own colours, as the restyle at the load's end
    // draws it where the field gets that exaggeration too (applyColourings then keeps it): the
    // field reads as tubes while it loads, and its end rebuilds only the wells drawn otherwise.
    double exaggeration = record.geometry->options().radialExaggeration;
    bool ownLook = false;
    if (!well.drawn && !well.coloured) {
        const double bound = loadExaggeration();
        ownLook = form->draws(bound, form->ownRequest);
        if (ownLook) exaggeration = bound;
    }
    const auto sample = std::make_shared<const reconstruction::WellGeometry>(form->base->restyled(
        exaggeration,
        ownLook ? form->ownHeld
                : drawnColouring(form->ownHeld, well.coloured, well.shared, well.sharedWells)));
    well.drawnOwn = ownLook ? std::weak_ptr<const LeanForm>(form) : std::weak_ptr<const LeanForm>();
    well.lean = std::move(form);
    well.values.reset();
    edit(well, [&sample, rows = well.lean->wholeRows, exaggeration](DeskWell& r) {
        r.geometry = sample;
        r.analysis.reset();
        r.wholeRows = rows;
        r.options.radialExaggeration = exaggeration;
    });
    if (!well.drawn) {
        // Its load drew nothing: drawn once, here, from its plan and the rows it holds, its
        // segments made when near (a few milliseconds a well), as render draws a field held
        // lean.
        const std::vector<double> before = drawnExaggerations();
        drawNow(well, [&] {
            well.view->rebuild(
                *sample, scenegraph::planWaitingWell(sample, well.lean->plan, well.lean->rows, 1),
                sample->options().radialExaggeration);
        });
        if (drawnExaggerations() != before) emit lookChanged();  // the caption says them
        return;
    }
    setDetail(well);
}

reconstruction::WholeWellReader WellSession::wholeReader(const Well& well) const {
    const DeskWell& record = m_model.well(modelIndex(well));
    LoadOptions options = record.options;
    options.cancel = nullptr;
    return [source = record.source, options, origin = m_origin, stamp = well.stamp,
            exaggeration = record.geometry->options().radialExaggeration,
            colour = record.options.colour, coloured = well.coloured, shared = well.shared,
            wells = well.sharedWells]() {
        const std::shared_ptr<const reconstruction::WellGeometry> whole =
            readWholeAgain(source, options, origin, stamp);
        std::shared_ptr<const reconstruction::WallColouring> own;
        if (coloured) own = ownColouring(*whole, colour, nullptr, windowAnalysis(options));
        return std::make_shared<const reconstruction::WellGeometry>(
            whole->restyled(exaggeration, drawnColouring(own, coloured, shared, wells)));
    };
}

void WellSession::setDetail(Well& well) {
    const int index = modelIndex(well);
    if (index < 0 || !well.view) return;
    const auto& geometry = m_model.well(index).geometry;
    if (!geometry) return;
    // A well held lean reads its log again for what its camera wants finer: not while the
    // field loads, beside the load's own reads (endLoadWhenDone gives it its detail then).
    well.detailDeferred = well.lean && loading();
    if (well.detailDeferred) {
        m_detail->removeWell(well.view->scene());
        return;
    }
    if (well.lean)
        m_detail->setWell(well.view->scene(), wholeReader(well));
    else
        m_detail->setWell(well.view->scene(), geometry);
}

void WellSession::startWholeRead(Well& well) {
    const DeskWell& record = m_model.well(modelIndex(well));
    well.leanJobRunning = true;
    emit status("Reading " + record.name + " whole for its analysis...");
    well.leanJob = std::make_unique<BackgroundJob>(
        this,
        [this, id = well.id, generation = m_styleGeneration, read = wholeReader(well),
         options = windowAnalysis(record.options)]() -> std::function<void()> {
            std::shared_ptr<const reconstruction::WellGeometry> whole;
            std::shared_ptr<const reconstruction::WellAnalysis> analysis;
            std::string error;
            try {
                whole = read();
                analysis = std::make_shared<const reconstruction::WellAnalysis>(
                    reconstruction::analyseWell(*whole, options));
            } catch (const std::exception& e) {
                error = e.what();
            }
            return [this, id, generation, whole, analysis, error]() {
                Well* w = find(id);
                if (!w) return;
                w->leanJobRunning = false;
                const int index = modelIndex(*w);
                if (index < 0 || !w->lean) return;
                if (!error.empty()) {  // it stays lean
                    w->readRefused = true;
                    emit status(QString::fromStdString(error));
                    return;
                }
                if (index != m_model.currentWell()) return;  // moved on: it stays lean
                if (generation != m_styleGeneration) {       // restyled meanwhile
                    startWholeRead(*w);
                    return;
                }
                w->lean.reset();
                edit(*w, [&](DeskWell& r) {
                    r.geometry = whole;
                    r.analysis = analysis;
                    r.wholeRows = 0;
                });
                setDetail(*w);
                if (m_leanPick.id == id) {  // the section a pick hit, now that every row is here
                    const auto [first, last] = whole->segmentRows(m_leanPick.segment);
                    const reconstruction::WallPoint wall = reconstruction::locateWallPoint(
                        *whole, first, last, glm::dvec3(m_leanPick.point));
                    m_leanPick = {};
                    m_model.setCurrentRow(index, wall.row);
                    m_model.setCurrentAzimuth(wall.azimuth_deg);
                }
                emit status(m_model.well(index).name + " read whole: analysed");
                emit wellAnalysed(index);
            };
        });
}

void WellSession::followCurrent() {
    const int current = m_model.currentWell();
    if (current >= 0) {
        Well* well = find(m_model.well(current).id);
        if (well && well->lean && !well->leanJobRunning && !well->readRefused)
            startWholeRead(*well);
    }
    holdLeanWhereDue();
}

bool WellSession::startLeanReading(double radialExaggeration,
                                   const reconstruction::ColourRequest& colour, int onlyId,
                                   const std::function<void()>& applied) {
    if (m_leanReading) {
        emit status("Wait for the wells held lean to be read again");
        return false;
    }
    struct Reading {
        int id = -1;
        WellSource source;
        LoadOptions options;
        FileStamp stamp;
        int firstLevel = 0;
        std::shared_ptr<const LeanForm> form;
    };
    std::vector<Reading> readings;
    for (const auto& well : m_wells) {
        if (!well->lean || (onlyId >= 0 && well->id != onlyId) ||
            well->lean->draws(radialExaggeration, colour))
            continue;
        const DeskWell& record = m_model.well(modelIndex(*well));
        LoadOptions options = record.options;
        options.cancel = nullptr;
        readings.push_back({well->id, record.source, options, well->stamp,
                            well->view->firstCoarseLevel(), well->lean});
    }
    m_leanReading = true;
    emit status(QString("Reading %1 well%2 held lean again to draw them so...")
                    .arg(readings.size())
                    .arg(readings.size() == 1 ? "" : "s"));
    m_leanReadJob = std::make_unique<BackgroundJob>(
        this,
        [this, readings, origin = m_origin, radialExaggeration, colour, onlyId,
         applied]() -> std::function<void()> {
            std::vector<std::pair<int, std::shared_ptr<const LeanForm>>> made;
            std::string error;
            try {
                for (const Reading& r : readings) {
                    const auto whole = readWholeAgain(r.source, r.options, origin, r.stamp);
                    auto form = std::make_shared<LeanForm>(*r.form);
                    if (!form->draws(radialExaggeration, form->ownRequest)) {
                        std::vector<double> more = r.form->plan->exaggerations;
                        more.push_back(radialExaggeration);
                        form->plan = std::make_shared<const reconstruction::CoarsePlan>(
                            reconstruction::planCoarseMeshes(*whole, r.firstLevel,
                                                             plannedExaggerations(more), 2));
                        form->rows = std::make_shared<const std::vector<std::size_t>>(
                            heldRows(*whole, *form->plan));
                        form->base = std::make_shared<const reconstruction::WellGeometry>(
                            whole->sampled(*form->rows));
                    }
                    form->ownRequest = colour;
                    form->ownHeld = std::make_shared<const reconstruction::WallColouring>(
                        ownColouring(*whole, colour, nullptr, windowAnalysis(r.options))
                            ->rowsOf(*form->rows));
                    made.emplace_back(r.id, std::move(form));
                }
            } catch (const std::exception& e) {
                error = e.what();
            }
            return [this, made, error, radialExaggeration, colour, onlyId, applied]() {
                m_leanReading = false;
                if (!error.empty()) {
                    emit status(QString::fromStdString(error));
                    return;
                }
                for (const auto& [id, form] : made) {
                    Well* w = find(id);
                    if (w && w->lean) w->lean = form;
                }
                restyleWells(radialExaggeration, colour, onlyId, applied);
            };
        });
    return true;
}

}  // namespace caliper3d::app
