#include "app/desktop/retired_loads.h"

#include "reconstruction/load/well_load_pipeline.h"

namespace caliper3d::app {

RetiredLoads::~RetiredLoads() {
    const std::lock_guard<std::mutex> lock(m_mutex);
    for (std::thread& t : m_threads) t.join();
}

void RetiredLoads::retire(std::unique_ptr<reconstruction::WellLoadPipeline> pipeline) {
    if (!pipeline) return;
    pipeline->cancel();
    m_running.fetch_add(1);
    const std::lock_guard<std::mutex> lock(m_mutex);
    m_threads.emplace_back([this, p = std::move(pipeline)]() mutable {
        p.reset();  // joins its worker, which stops at the end of its block
        m_running.fetch_sub(1);
    });
}

}  // namespace caliper3d::app
