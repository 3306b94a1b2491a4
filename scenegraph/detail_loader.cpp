#include "scenegraph/detail_loader.h"

#include <algorithm>
#include <vector>

#include <Inventor/sensors/SoTimerSensor.h>
#include <glm/geometric.hpp>

#include "scenegraph/main_thread.h"
#include "scenegraph/well_scene.h"

namespace caliper3d::scenegraph {

namespace {
constexpr std::size_t kAttachPerTick = 16;
constexpr float kMoved_m = 0.01f;

bool sameView(const DetailView& a, const DetailView& b) {
    return glm::length(a.eye - b.eye) < kMoved_m && a.lod.focal_px == b.lod.focal_px &&
           a.lod.pixelTolerance == b.lod.pixelTolerance;
}
}  // namespace

DetailLoader::DetailLoader(CameraProbe probe, std::size_t budgetTriangles)
    : m_probe(std::move(probe)),
      m_budget(budgetTriangles),
      m_worker(std::make_unique<reconstruction::DetailWorker>()) {
    assertMainThread("DetailLoader");
    m_timer = std::make_unique<SoTimerSensor>(&DetailLoader::onTimer, this);
    m_timer->setInterval(SbTime(0.05));
    m_timer->schedule();
}

DetailLoader::~DetailLoader() {
    if (m_timer) m_timer->unschedule();
    m_worker.reset();  // stops and joins before the wells' entries go
}

void DetailLoader::onTimer(void* data, SoSensor*) {
    static_cast<DetailLoader*>(data)->tick();
}

void DetailLoader::addWell(WellScene& scene,
                           std::shared_ptr<const reconstruction::WellGeometry> geometry) {
    assertMainThread("DetailLoader::addWell");
    m_wells[m_nextKey++] = Entry{&scene, std::move(geometry), nullptr, false};
    m_changed = true;
}

void DetailLoader::setEntry(Entry entry) {
    assertMainThread("DetailLoader::setWell");
    m_changed = true;
    for (auto& [key, held] : m_wells)
        if (held.scene == entry.scene) {
            if (held.readWhole) m_worker->forgetWholeWells();  // the whole well read for it
            held = std::move(entry);
            return;
        }
    m_wells[m_nextKey++] = std::move(entry);
}

void DetailLoader::setWell(WellScene& scene,
                           std::shared_ptr<const reconstruction::WellGeometry> geometry) {
    setEntry(Entry{&scene, std::move(geometry), nullptr, false});
}

void DetailLoader::setWell(WellScene& scene, reconstruction::WholeWellReader readWhole) {
    setEntry(Entry{&scene, nullptr,
                   std::make_shared<const reconstruction::WholeWellReader>(std::move(readWhole)),
                   false});
}

void DetailLoader::removeAll() {
    assertMainThread("DetailLoader::removeAll");
    m_worker->replaceJobs({});
    m_worker->forgetWholeWells();
    m_wells.clear();
    m_requested.clear();
    m_changed = true;
}

void DetailLoader::removeWell(const WellScene& scene) {
    assertMainThread("DetailLoader::removeWell");
    for (auto it = m_wells.begin(); it != m_wells.end(); ++it)
        if (it->second.scene == &scene) {
            if (it->second.readWhole) m_worker->forgetWholeWells();  // the whole well read for it
            m_wells.erase(it);
            m_changed = true;
            return;
        }
}

bool DetailLoader::tick() {
    assertMainThread("DetailLoader::tick");
    for (reconstruction::DetailResult& result : m_worker->results().drain(kAttachPerTick)) {
        m_requested.erase({result.well, result.mesh.index});
        const auto it = m_wells.find(result.well);
        if (it == m_wells.end()) continue;  // a well closed meanwhile
        if (!result.error.empty()) {
            if (!it->second.failed && m_failureReport) m_failureReport(result.error);
            it->second.failed = true;
            continue;
        }
        it->second.scene->attachFinerLevels(result.mesh);
        m_changed = true;
    }
    const std::optional<DetailView> view = m_probe ? m_probe() : std::nullopt;
    if (view && (m_changed || !m_last || !sameView(*view, *m_last))) request(*view);
    // Levels attached or dropped left their spans' boxes stale (no culling there until
    // recomputed); where nothing changed the root's valid cache answers at once.
    for (auto& [key, entry] : m_wells) entry.scene->cacheBounds();
    return m_requested.empty() && m_worker->pending() == 0;
}

void DetailLoader::request(const DetailView& view) {
    const bool newLod = !m_last || m_last->lod.focal_px != view.lod.focal_px ||
                        m_last->lod.pixelTolerance != view.lod.pixelTolerance;
    m_last = view;
    m_changed = false;
    // Jobs not started yet are asked again below if still wanted; the one being built stays.
    for (const reconstruction::DetailJob& dropped : m_worker->replaceJobs({}))
        m_requested.erase({dropped.well, dropped.segment});
    struct Wanted {
        float distance;
        reconstruction::DetailJob job;
    };
    std::vector<Wanted> wanted;
    for (auto& [key, entry] : m_wells) {
        if (newLod) entry.scene->setLodView(view.lod);
        if (entry.failed) continue;
        for (const DetailRequest& r : entry.scene->wantedDetail(view.eye)) {
            if (m_requested.count({key, r.segment})) continue;
            wanted.push_back(
                {r.distance,
                 {key, entry.geometry, entry.readWhole, r.segment, r.level, r.heldFrom}});
        }
    }
    evictBeyondBudget();
    std::sort(wanted.begin(), wanted.end(),
              [](const Wanted& a, const Wanted& b) { return a.distance < b.distance; });
    std::vector<reconstruction::DetailJob> jobs;
    jobs.reserve(wanted.size());
    for (Wanted& w : wanted) {
        m_requested.insert({w.job.well, w.job.segment});
        jobs.push_back(std::move(w.job));
    }
    m_worker->replaceJobs(std::move(jobs));
}

void DetailLoader::evictBeyondBudget() {
    // One budget for the whole scene: the segments idle longest go first, whichever well
    // holds them (each well counts its wants alike: every request asks every well).
    std::size_t held = 0;
    struct Idle {
        WellScene* scene;
        WellScene::IdleDetail detail;
    };
    std::vector<Idle> idle;
    for (auto& [key, entry] : m_wells) {
        held += entry.scene->fineTriangles();
        for (const WellScene::IdleDetail& d : entry.scene->idleDetail())
            idle.push_back({entry.scene, d});
    }
    if (held <= m_budget) return;
    std::sort(idle.begin(), idle.end(),
              [](const Idle& a, const Idle& b) { return a.detail.idleFor > b.detail.idleFor; });
    for (const Idle& i : idle) {
        if (held <= m_budget) break;
        i.scene->dropFineLevels(i.detail.segment);
        held -= i.detail.triangles;
    }
}

}  // namespace caliper3d::scenegraph
