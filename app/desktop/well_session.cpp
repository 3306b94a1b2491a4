#include "app/desktop/well_session.h"

#include <algorithm>
#include <cmath>
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
#include "reconstruction/load/well_load_pipeline.h"
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
    std::unique_ptr<AnalysisJob> analysisJob;  // after the load, until the analysis is in
    std::unique_ptr<BackgroundJob> matchJob;   // another run's depth match to its main run
    // The report's section values, computed the first time a colouring needs them.
    std::shared_ptr<const reconstruction::SectionValues> values;
    bool started = false;  // its pipeline runs (or has run); else it waits its turn
    bool done = false;
};

WellSession::WellSession(DeskModel& model, scenegraph::DetailLoader::CameraProbe probe,
                         QObject* parent)
    : QObject(parent),
      m_model(model),
      m_retired(std::make_unique<RetiredLoads>()),
      m_sceneRoot(scenegraph::makeRef(new SoSeparator)),
      m_detail(std::make_unique<scenegraph::DetailLoader>(std::move(probe))) {
    m_progressTimer.setInterval(kProgressInterval_ms);
    connect(&m_progressTimer, &QTimer::timeout, this, &WellSession::publishProgress);
    connect(&m_model, &DeskModel::currentChanged, this, [this] { tickCurrentWell(); });
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
    m_wells.clear();
    m_model.clearWells();
    emit warningsChanged();
    m_framed = false;
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
        m_detail->addWell(w.view->scene(), g);
        edit(w, [&g](DeskWell& record) {
            if (!g->table().wellName.empty())
                record.name = QString::fromStdString(g->table().wellName);
            record.geometry = g;
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
        // which the load's end may choose, is not filled by the numbers after it.
        m_loadedText =
            QString("%1: %2 segments, %3 triangles at full detail, radii x%4, %5 warning%6")
                .arg(w.name, QString::number(segments),
                     QString::number(w.view->scene().fullDetailTriangles()), QStringLiteral("%1"),
                     QString::number(warnings), warnings == 1 ? "" : "s");
        emit status(m_loadedText.arg(record.options.radialExaggeration));
        w.done = true;
        edit(w, [](DeskWell& r) { r.loadFraction = 1.0; });
        analyse(w);
        // Signalled from the event loop, not from inside the feeder's tick, so a slot may
        // open other wells (destroying this feeder) safely.
        ++m_endsQueued;
        QMetaObject::invokeMethod(
            this,
            [this, segments] {
                --m_endsQueued;
                emit wellLoaded(static_cast<int>(segments));
                wellDone();
            },
            Qt::QueuedConnection);
    };
    callbacks.failed = [this, &w](const std::string& message) {
        const QString error = QString::fromStdString(message);
        emit status(w.name + ": failed: " + error);
        w.done = true;
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

    // Survey, log and geometry are all read on the worker (loadWell).
    w.pipeline =
        std::make_unique<reconstruction::WellLoadPipeline>(source, options, m_origin, firstLevel);
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
    for (const auto& well : m_wells) {
        const auto& g = m_model.well(modelIndex(*well)).geometry;
        if (g) m_detail->addWell(well->view->scene(), g);
    }
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
        well->pipeline->start();
        ++running;
    }
}

void WellSession::wellDone() {
    startWaitingLoads();
    if (loading()) return;
    applyStyleAfterLoad();
    emit allWellsLoaded();
    // An analysis that ended while this end was queued found the session still loading.
    if (allAnalysed()) giveBackFreedMemory();
}

bool WellSession::loading() const {
    return m_endsQueued > 0 ||
           std::any_of(m_wells.begin(), m_wells.end(), [](const auto& w) { return !w->done; });
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
                                          const SbVec2s& pixel) const {
    std::vector<scenegraph::PickableWell> wells;
    std::vector<int> index;
    for (const auto& well : m_wells) {
        const int i = modelIndex(*well);
        const DeskWell& record = m_model.well(i);
        if (record.geometry && record.analysis && well->view->visible()) {
            wells.push_back({&well->view->scene(), record.geometry.get(), record.analysis.get(),
                             record.name.toStdString()});
            index.push_back(i);
        }
    }
    if (wells.empty()) return std::nullopt;
    const std::optional<scenegraph::SectionPick> hit =
        scenegraph::pickSection(root, viewport, pixel, wells);
    if (!hit) return std::nullopt;
    WellPick out;
    out.well = index[hit->well];
    out.row = hit->wall.row;
    out.azimuth_deg = hit->wall.azimuth_deg;
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
    QElapsedTimer clock;
    clock.start();
    static const std::vector<std::string> analysed{"diameter", "ellipticity", "class"};
    const bool needsValues =
        std::find(analysed.begin(), analysed.end(), colour.quantity) != analysed.end();
    std::vector<ColouredWell> coloured;
    std::vector<std::shared_ptr<const reconstruction::WellGeometry>> geometries;
    std::vector<const reconstruction::SectionValues*> values;
    QApplication::setOverrideCursor(Qt::WaitCursor);
    for (const auto& well : m_wells) {
        const DeskWell& record = m_model.well(modelIndex(*well));
        if (!record.geometry || (onlyId >= 0 && well->id != onlyId)) continue;
        if (needsValues && !well->values)
            well->values = std::make_shared<const reconstruction::SectionValues>(
                record.analysis ? reconstruction::sectionValues(*record.analysis)
                                : reconstruction::sectionValues(*record.geometry));
        geometries.push_back(record.geometry);
        values.push_back(well->values.get());
        coloured.push_back({well->id, record.geometry, nullptr});
    }
    try {
        const auto colourings = reconstruction::wallColourings(geometries, colour, values);
        for (std::size_t w = 0; w < coloured.size(); ++w) coloured[w].colouring = colourings[w];
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
    m_detail->removeAll();
    for (auto& well : m_wells) {
        const DeskWell& record = m_model.well(modelIndex(*well));
        // A well closed, or loaded again, since its colours were made keeps its own.
        const auto it = std::find_if(coloured.begin(), coloured.end(), [&](const ColouredWell& c) {
            return c.id == well->id && c.geometry == record.geometry;
        });
        if (it == coloured.end()) {
            if (record.geometry) m_detail->addWell(well->view->scene(), record.geometry);
            continue;
        }
        const auto restyled = std::make_shared<const reconstruction::WellGeometry>(
            record.geometry->restyled(radialExaggeration, it->colouring));
        well->view->rebuild(*restyled, radialExaggeration);
        ++m_annotationGeneration;
        m_detail->addWell(well->view->scene(), restyled);
        edit(*well, [&](DeskWell& r) {
            r.geometry = restyled;
            r.options.radialExaggeration = radialExaggeration;
            r.options.colour = colour;
        });
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
                    coloured.push_back({pairs[w].id, pairs[w].geometry, colourings[w]});
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

}  // namespace caliper3d::app
