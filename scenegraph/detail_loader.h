#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <utility>

#include <glm/vec3.hpp>

#include "reconstruction/load/detail_worker.h"
#include "scenegraph/segment_node_builder.h"

class SoTimerSensor;
class SoSensor;

namespace caliper3d::scenegraph {

class WellScene;

// Where the picture is taken from, as the detail loader needs it.
struct DetailView {
    glm::vec3 eye{0.0f};  // scene frame
    LodView lod;
};

// Full detail near the camera, for the window: the main-thread end of a DetailWorker. A timer
// watches the camera; when it moves (or the viewport or field of view changes) each well says
// which finer levels its segments want (WellScene::wantedDetail), the worker builds them,
// nearest first, and the timer attaches what it built, then drops the finer levels least
// recently wanted beyond the triangle budget, one budget for every well of the scene. The
// coarse levels stay meanwhile, so a segment is never missing. Main thread only; the worker makes
// no Coin call.
class DetailLoader {
public:
    using CameraProbe = std::function<std::optional<DetailView>()>;
    // About 22 MiB of scene data per million strip triangles (platform notes).
    static constexpr std::size_t kDefaultBudgetTriangles = 4'000'000;

    explicit DetailLoader(CameraProbe probe, std::size_t budgetTriangles = kDefaultBudgetTriangles);
    ~DetailLoader();
    DetailLoader(const DetailLoader&) = delete;
    DetailLoader& operator=(const DetailLoader&) = delete;

    // The scene must stay alive until removeAll (or the loader's end).
    void addWell(WellScene& scene, std::shared_ptr<const reconstruction::WellGeometry> geometry);
    void removeAll();

    // One step (what the timer runs): attach what was built, then look at the camera.
    // Returns true when nothing is wanted or being built.
    bool tick();
    std::size_t budgetTriangles() const { return m_budget; }
    void setBudgetTriangles(std::size_t triangles) { m_budget = triangles; }

private:
    static void onTimer(void* data, SoSensor*);
    void request(const DetailView& view);
    // Drops the finer levels idle longest, across every well, until those held fit the budget.
    void evictBeyondBudget();

    struct Entry {
        WellScene* scene = nullptr;
        std::shared_ptr<const reconstruction::WellGeometry> geometry;
    };
    CameraProbe m_probe;
    std::size_t m_budget;
    std::map<std::size_t, Entry> m_wells;  // by key, never reused
    std::size_t m_nextKey = 0;
    std::set<std::pair<std::size_t, std::size_t>> m_requested;  // (well, segment) at the worker
    std::optional<DetailView> m_last;
    bool m_changed = true;
    std::unique_ptr<reconstruction::DetailWorker> m_worker;
    std::unique_ptr<SoTimerSensor> m_timer;
};

}  // namespace caliper3d::scenegraph
