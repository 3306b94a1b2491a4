#pragma once

#include <functional>
#include <memory>

#include "reconstruction/load/load_well.h"
#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/mesh/mesh.h"
#include "reconstruction/well_geometry.h"

namespace caliper3d::reconstruction {

// Where a streamed load hands its work while the log is still being read.
struct StreamedLoadSink {
    // The geometry (path and frames) of the next stretch of rows read; its first row is the
    // last row of the stretch before.
    std::function<void(const std::shared_ptr<const WellGeometry>& stretch)> stretch;
    // The next coarse segment (buildCoarseSegment from `firstCoarseLevel` on), numbered and
    // with rows as in the whole well's geometry, identical to it bit for bit.
    std::function<void(SegmentMesh&& segment)> segment;
    int firstCoarseLevel = kFirstCoarseLevel;
    // How much of the log is read, 0 to 1 (rows read over the reader's estimate of the
    // rows to come), after each block; called on the reading thread.
    std::function<void(double fraction)> read;
    // False: nothing is streamed (no stretch, no segment); the log is read on the reading thread
    // with its progress (`read`) and the whole well built once it is in. For a well drawn from
    // its whole geometry anyway (the window's well of a field held lean): each stretch's path
    // and frames, placed again with the whole well's, are work done twice.
    bool stream = true;
};

// loadWell, streamed: the log is read on a reading thread while this thread, the meshing
// thread, places the rows read so far stretch by stretch (the path extended from where the
// stretch before ended) and builds every segment a stretch completes, so coarse segments
// appear while the rest is still being read (docs/threading.md, "Loading a well"). Once the
// log is read the whole well is built as loadWell builds it and returned; the caller builds
// the segments the sink did not get from the whole geometry. Stops streaming, and leaves the rest
// to the whole geometry, when a stretch cannot be drawn alone (no caliper data in it) or the
// meshing falls far behind the reading. Throws as loadWell does (io::ReadCancelled once
// options.cancel is set). Makes no Coin or Qt call.
LoadedWell loadWellStreamed(const WellSource& source, const LoadOptions& options,
                            const Wellhead& origin, const StreamedLoadSink& sink);

}  // namespace caliper3d::reconstruction
