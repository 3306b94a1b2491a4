#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>

#include "io/log_info.h"
#include "io/log_stream.h"
#include "io/read_options.h"
#include "io/well_location.h"

namespace caliper3d::io {

// Reads a DLIS file held in `bytes` (mapped, or in memory) as a caliper log, through the
// same roles, units, parameters and depth ordering as a LAS file: one logical file
// (ReadOptions::logicalFile, else the first that holds caliper curves) and, in it, the
// frame that holds the most arms. Array channels become columns NAME[1]..NAME[n]; arrays
// of more than one dimension are listed, not read. `info.details` describes the file.
// Throws ParseError naming `name` and a byte offset for what cannot be read.
// `release`, when given, is told the byte before which the file will not be read again
// (after the index, then as the frames are read), so that a mapped file's pages may go.
LogInfo streamDlis(std::string_view bytes, const std::string& name, const ReadOptions& options,
                   const ChunkConsumer& consumer, const StreamOptions& stream,
                   const std::function<void(std::size_t end)>& release = {});

// The well reference point a DLIS file's parameters give (LATI, LONG, EKB...: as a LAS
// header's, io/well_location.h), from the first logical file that gives one; empty when none
// does. Reads the explicitly formatted records only.
WellLocation readDlisWellLocation(std::string_view bytes, const std::string& name,
                                  Diagnostics* diagnostics);

}  // namespace caliper3d::io
