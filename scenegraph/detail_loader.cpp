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
    m_wells[m_nextKey++] = Entry{&scene, std::move(geometry)};
    m_changed = true;
}

void DetailLoader::removeAll() {
    assertMainThread("DetailLoader::removeAll");
    m_worker->replaceJobs({});
    m_wells.clear();
    m_requested.clear();
    m_changed = true;
}

bool DetailLoader::tick() {
    assertMainThread("DetailLoader::tick");
    for (reconstruction::DetailResult& result : m_worker->results().drain(kAttachPerTick)) {
        m_requested.erase({result.well, result.mesh.index});
        const auto it = m_wells.find(result.well);
        if (it == m_wells.end()) continue;  // a well closed meanwhile
        it->second.scene->attachFinerLevels(result.mesh);
        m_changed = true;
    }
    const std::optional<DetailView> view = m_probe ? m_probe() : std::nullopt;
    if (view && (m_changed || !m_last || !sameView(*view, *m_last))) request(*view);
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
        for (const DetailRequest& r : entry.scene->wantedDetail(view.eye)) {
            if (m_requested.count({key, r.segment})) continue;
            wanted.push_back({r.distance, {key, entry.geometry, r.segment, r.level, r.heldFrom}});
        }
        entry.scene->evictFineLevels(m_budget / std::max<std::size_t>(m_wells.size(), 1));
    }
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

}  // namespace caliper3d::scenegraph
