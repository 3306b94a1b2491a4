#pragma once

#include <functional>
#include <memory>
#include <string>
#include <thread>

#include "reconstruction/analysis/well_analysis.h"

class QObject;

namespace caliper3d::app {

// File > Save report: writes a well's section report (the CSV `caliper3d report -o` writes)
// and its zone table (`--zones`) on a worker thread from the analysis the model holds, and
// hands the outcome to `done` on the main thread through `context`'s event queue. The
// destructor waits for the worker; `done` is not called after it.
class ReportJob {
public:
    // ok false: `message` says why, naming the file.
    using Done = std::function<void(bool ok, const std::string& message)>;

    ReportJob(QObject* context, std::shared_ptr<const reconstruction::WellAnalysis> analysis,
              std::string sectionsPath, std::string zonesPath, Done done);
    ~ReportJob();
    ReportJob(const ReportJob&) = delete;
    ReportJob& operator=(const ReportJob&) = delete;

    // "dir/name.csv" -> "dir/name-zones.csv".
    static std::string zonesPathFor(const std::string& sectionsPath);

private:
    std::shared_ptr<bool> m_alive;  // main thread only: false once destroyed
    std::thread m_worker;
};

}  // namespace caliper3d::app
