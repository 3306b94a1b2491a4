#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
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
    // Forgets `scene` (one about to be replaced or to go): what was asked for it is dropped as
    // it comes back. Nothing where it has no entry.
    void removeWell(const WellScene& scene);
    // What `scene`'s finer levels are built from from now on (added when it has no entry): its
    // geometry, or, held lean (docs/architecture.md, "A field held lean"), `readWhole`, which
    // reads the whole well as drawn, on the worker, when the camera first wants its finer levels.
    // A well that cannot be read again is reported (setFailureReport) once, and asks for nothing
    // more. Its detail held stays.
    void setWell(WellScene& scene, std::shared_ptr<const reconstruction::WellGeometry> geometry);
    void setWell(WellScene& scene, reconstruction::WholeWellReader readWhole);
    // Where a well held lean that could not be read again is said (the reader's message).
    void setFailureReport(std::function<void(const std::string&)> report) {
        m_failureReport = std::move(report);
    }
    // The wells held lean read whole and kept by the worker now.
    std::size_t wholeWellsKept() const { return m_worker->wholeWellsKept(); }

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
    struct Entry;
    void setEntry(Entry entry);

    struct Entry {
        WellScene* scene = nullptr;
        std::shared_ptr<const reconstruction::WellGeometry> geometry;  // null: held lean
        std::shared_ptr<const reconstruction::WholeWellReader> readWhole;
        bool failed = false;  // could not be read again: nothing more asked
    };
    CameraProbe m_probe;
    std::function<void(const std::string&)> m_failureReport;
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
