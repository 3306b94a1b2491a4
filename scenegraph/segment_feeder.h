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
// load pipeline's events and attaches the segments to a WellScene, a few per
// tick so the UI stays responsive. Workers never touch Coin; this is the only
// place their results enter the scene graph.
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

    SegmentFeeder(reconstruction::WellLoadPipeline& pipeline, WellScene& scene, Callbacks callbacks,
                  std::size_t segmentsPerTick = 8);
    ~SegmentFeeder();
    SegmentFeeder(const SegmentFeeder&) = delete;
    SegmentFeeder& operator=(const SegmentFeeder&) = delete;

    // Drains what is queued now (also what the timer calls); returns true once
    // the pipeline has finished or failed.
    bool drainOnce();
    bool done() const { return m_done; }
    std::size_t attached() const { return m_attached; }

private:
    static void onTimer(void* data, SoSensor*);

    reconstruction::WellLoadPipeline& m_pipeline;
    WellScene& m_scene;
    Callbacks m_callbacks;
    std::size_t m_perTick;
    std::size_t m_attached = 0;
    bool m_done = false;
    std::unique_ptr<SoTimerSensor> m_timer;
};

}  // namespace caliper3d::scenegraph
