#include "scenegraph/segment_feeder.h"

#include <algorithm>
#include <chrono>
#include <vector>

#include <Inventor/sensors/SoTimerSensor.h>

#include "scenegraph/main_thread.h"
#include "scenegraph/well_scene.h"

namespace caliper3d::scenegraph {

SegmentFeeder::SegmentFeeder(reconstruction::WellLoadPipeline& pipeline, WellScene& scene,
                             Callbacks callbacks, std::size_t eventsAtOnce, double tickBudget_ms)
    : m_pipeline(pipeline),
      m_scene(scene),
      m_callbacks(std::move(callbacks)),
      m_perTick(std::max<std::size_t>(eventsAtOnce, 1)),
      m_budget_ms(tickBudget_ms) {
    assertMainThread("SegmentFeeder");
    m_timer = std::make_unique<SoTimerSensor>(&SegmentFeeder::onTimer, this);
    m_timer->setInterval(SbTime(0.02));
    m_timer->schedule();
}

SegmentFeeder::~SegmentFeeder() {
    if (m_timer) m_timer->unschedule();
}

void SegmentFeeder::onTimer(void* data, SoSensor*) {
    static_cast<SegmentFeeder*>(data)->drainOnce();
}

bool SegmentFeeder::drainOnce() {
    assertMainThread("SegmentFeeder::drainOnce");
    if (m_done) return true;
    const auto start = std::chrono::steady_clock::now();
    do {
        std::vector<reconstruction::LoadEvent> events = m_pipeline.events().drain(m_perTick);
        if (events.empty()) break;
        for (auto& event : events) handle(event);
    } while (!m_done &&
             std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                     .count() < m_budget_ms);
    if (m_done) m_timer->unschedule();
    return m_done;
}

void SegmentFeeder::handle(reconstruction::LoadEvent& event) {
    if (auto* stretch = std::get_if<reconstruction::LoadStretch>(&event)) {
        m_scene.extendPath(stretch->path);  // the rows read so far, until the whole
    } else if (auto* started = std::get_if<reconstruction::LoadStarted>(&event)) {
        m_scene.setPath(*started->geometry);
        if (m_callbacks.started) m_callbacks.started(*started->geometry);
        if (m_callbacks.geometry) m_callbacks.geometry(started->geometry);
        if (m_callbacks.warnings) m_callbacks.warnings(started->diagnostics);
    } else if (auto* segment = std::get_if<reconstruction::SegmentMesh>(&event)) {
        m_scene.addSegment(*segment);
        ++m_attached;
        if (m_callbacks.progress) m_callbacks.progress(m_attached);
    } else if (auto* span = std::get_if<reconstruction::SpanMesh>(&event)) {
        m_scene.addSpan(*span);
    } else if (auto* finished = std::get_if<reconstruction::LoadFinished>(&event)) {
        m_done = true;
        m_scene.cacheBounds();  // culling needs the spans' boxes
        if (m_callbacks.finished) m_callbacks.finished(finished->segments);
    } else if (auto* failed = std::get_if<reconstruction::LoadFailed>(&event)) {
        m_done = true;
        if (m_callbacks.failed) m_callbacks.failed(failed->message);
    }
}

}  // namespace caliper3d::scenegraph
