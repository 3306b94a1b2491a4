#include "app/lean_well.h"

#include <algorithm>
#include <stdexcept>
#include <system_error>

namespace caliper3d::app {

FileStamp stampOf(const std::string& path) {
    std::error_code error;
    FileStamp stamp;
    stamp.size = std::filesystem::file_size(path, error);
    if (!error) stamp.changed = std::filesystem::last_write_time(path, error);
    return stamp;
}

std::vector<std::size_t> heldRows(const reconstruction::WellGeometry& whole,
                                  const reconstruction::CoarsePlan& plan) {
    std::vector<std::size_t> rows = plan.rows();
    const std::vector<std::size_t> line = reconstruction::pathLineRows(whole);
    const std::vector<std::size_t> every =
        reconstruction::everyKthRow(whole.table().rowCount(), kLeanRows);
    rows.insert(rows.end(), line.begin(), line.end());
    rows.insert(rows.end(), every.begin(), every.end());
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    return rows;
}

std::shared_ptr<const reconstruction::WellGeometry> readWholeAgain(
    const reconstruction::WellSource& source, const reconstruction::LoadOptions& options,
    const reconstruction::Wellhead& origin, const FileStamp& stamp) {
    if (stampOf(source.path) != stamp)
        throw std::runtime_error(source.path +
                                 ": changed since it was loaded (its size or time of last change "
                                 "differs): its finer levels are not drawn from another log");
    return reconstruction::loadWell(source, options, origin).geometry;
}

}  // namespace caliper3d::app
