#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>

#include "reconstruction/load/well_load_pipeline.h"

class SoTimerSensor;
class SoSensor;

namespace caliper3d::scenegraph {

class WellScene;

// The main-thread end of the sensor queue: an SoTimerSensor that drains a
// load pipeline's events and attaches the segments to a WellScene, a few at a
// time for a few milliseconds each tick so the UI stays responsive. Workers never
// touch Coin; this is the only place their results enter the scene graph.
class SegmentFeeder {
public:
    struct Callbacks {
        std::function<void(const reconstruction::WellGeometry&)> started;
        // The same geometry, shared: for workers that build more of it (DetailLoader).
        std::function<void(std::shared_ptr<const reconstruction::WellGeometry>)> geometry;
        // The well's warnings (reader, survey, geometry), once, with `started`.
        std::function<void(const io::Diagnostics&)> warnings;
        std::function<void(std::size_t segmentsAttached)> progress;
        std::function<void(std::size_t segments)> finished;
        std::function<void(const std::string& message)> failed;
    };

    // Each tick takes `eventsAtOnce` events at a time until it has spent `tickBudget_ms` of
    // the main thread (at least one batch a tick).
    SegmentFeeder(reconstruction::WellLoadPipeline& pipeline, WellScene& scene, Callbacks callbacks,
                  std::size_t eventsAtOnce = 8, double tickBudget_ms = kTickBudget_ms);
    ~SegmentFeeder();
    SegmentFeeder(const SegmentFeeder&) = delete;
    SegmentFeeder& operator=(const SegmentFeeder&) = delete;

    // A tick's share of the main thread. Ticks come every 20 ms: two wells loading at once
    // leave the window most of it. (A fixed 8 events a tick held a field of 1 km wells, 120
    // events each, to 160 ms a well whatever the machine: docs/benchmarks.md.)
    static constexpr double kTickBudget_ms = 6.0;

    // Drains what is queued now, for one tick's budget (also what the timer calls);
    // returns true once the pipeline has finished or failed.
    bool drainOnce();
    bool done() const { return m_done; }
    std::size_t attached() const { return m_attached; }

private:
    static void onTimer(void* data, SoSensor*);
    void handle(reconstruction::LoadEvent& event);

    reconstruction::WellLoadPipeline& m_pipeline;
    WellScene& m_scene;
    Callbacks m_callbacks;
    std::size_t m_perTick;
    double m_budget_ms;
    std::size_t m_attached = 0;
    bool m_done = false;
    std::unique_ptr<SoTimerSensor> m_timer;
};

}  // namespace caliper3d::scenegraph
