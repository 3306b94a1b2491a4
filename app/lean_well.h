#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "reconstruction/load/load_well.h"
#include "reconstruction/mesh/lod_tree.h"
#include "reconstruction/well_geometry.h"

namespace caliper3d::app {

// What `render` and the window share to hold a field lean (docs/architecture.md, "A field held
// lean"): the rows a well is held by, and reading it whole again.

// What `render` and the window hold of a field before they hold it lean: about 330 MB of
// tables and paths.
inline constexpr std::size_t kFieldRowBudget = 2'000'000;

// A file's size and last change, to tell whether a log read again is the log that was read.
struct FileStamp {
    std::uintmax_t size = 0;
    std::filesystem::file_time_type changed{};
    bool operator==(const FileStamp& o) const { return size == o.size && changed == o.changed; }
    bool operator!=(const FileStamp& o) const { return !(*this == o); }
};
FileStamp stampOf(const std::string& path);

// A well of a field held lean keeps this many rows (WellGeometry::sampled) besides those its
// coarse meshes draw: about what a picture's scale and framing sample of it
// (scenegraph/picture_scale.cpp), and a row every 0.25 m of a kilometre for its labels.
inline constexpr std::size_t kLeanRows = 4096;

// The rows a well of a field held lean keeps when its coarse meshes were planned: those
// (every row they draw or step over), those of its path line, and kLeanRows of the rest.
std::vector<std::size_t> heldRows(const reconstruction::WellGeometry& whole,
                                  const reconstruction::CoarsePlan& plan);

// Well `source` read whole again from its log as it was loaded (`options`, the scene origin
// `origin`), its placement and geometry as at first. A log whose size or time of last change
// is no longer `stamp` is refused with std::runtime_error naming it: what is drawn from it would
// be another well's.
std::shared_ptr<const reconstruction::WellGeometry> readWholeAgain(
    const reconstruction::WellSource& source, const reconstruction::LoadOptions& options,
    const reconstruction::Wellhead& origin, const FileStamp& stamp);

}  // namespace caliper3d::app
