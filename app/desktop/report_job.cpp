#include "app/desktop/report_job.h"

#include <exception>

#include <QMetaObject>
#include <QObject>

#include "reconstruction/analysis/report_writer.h"

namespace caliper3d::app {

ReportJob::ReportJob(QObject* context, std::shared_ptr<const reconstruction::WellAnalysis> analysis,
                     std::string sectionsPath, std::string zonesPath, Done done)
    : m_alive(std::make_shared<bool>(true)) {
    m_worker = std::thread([context, analysis = std::move(analysis),
                            sections = std::move(sectionsPath), zones = std::move(zonesPath),
                            done = std::move(done), alive = m_alive]() mutable {
        bool ok = true;
        std::string message = sections + " and " + zones;
        try {
            reconstruction::writeSectionReport(sections, *analysis);
            reconstruction::writeZoneReport(zones, *analysis);
        } catch (const std::exception& e) {
            ok = false;
            message = e.what();
        }
        // `alive` is read on the main thread only, inside the queued call.
        QMetaObject::invokeMethod(
            context,
            [ok, message = std::move(message), done = std::move(done), alive]() {
                if (*alive) done(ok, message);
            },
            Qt::QueuedConnection);
    });
}

ReportJob::~ReportJob() {
    *m_alive = false;
    if (m_worker.joinable()) m_worker.join();
}

std::string ReportJob::zonesPathFor(const std::string& sectionsPath) {
    const std::size_t slash = sectionsPath.find_last_of('/');
    const std::size_t dot = sectionsPath.find_last_of('.');
    const bool hasExtension =
        dot != std::string::npos && (slash == std::string::npos || dot > slash);
    return hasExtension ? sectionsPath.substr(0, dot) + "-zones" + sectionsPath.substr(dot)
                        : sectionsPath + "-zones.csv";
}

}  // namespace caliper3d::app
