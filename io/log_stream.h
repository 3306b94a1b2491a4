#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "io/log_info.h"
#include "io/read_options.h"
#include "io/section_table.h"

namespace caliper3d::io {

// How the streaming reader works through a file. Defaults suit a 2-core
// machine; none changes what is read.
struct StreamOptions {
    std::size_t chunkRows = 4096;       // rows per delivered chunk at least (the last may hold
                                        //   fewer); an in-order piece of a block goes on whole,
                                        //   without a copy, when it holds that many
    std::size_t blockBytes = 8u << 20;  // text read per step; the text is never held whole
    int threads = 2;                    // 1 or 2 parsing threads, sharing the pieces of each block
                                        //   (about blockBytes / 8 each, cut at line ends)
    const std::atomic<bool>* cancel = nullptr;  // checked per block; set from any thread
    // Called once before the first chunk, with the curves and roles known
    // (info.rows still 0) and an estimate of the rows to come (for reserving).
    std::function<void(const LogInfo& info, std::size_t estimatedRows)> onStart;
    // loadCaliperLog only: shown each chunk once it is kept (on the reading thread), so that
    // another stage may work on the rows read so far while the rest is read.
    std::function<void(const SectionTable& chunk)> onChunk;
};

// Receives sections in increasing depth order, in the product's units.
// The chunk is only valid during the call.
using ChunkConsumer = std::function<void(const SectionTable& chunk)>;

// Reads a column-text or LAS 1.2/2.0/3.0 file in chunks. Returns the log's
// description; `cancelled` is true when the token stopped it (the consumer
// then has a prefix of the log). Throws ParseError for what cannot be read
// safely. A log recorded upwards is held whole (as parsed arrays), sorted,
// then delivered.
LogInfo streamCaliperLog(const std::string& path, const ReadOptions& options,
                         const ChunkConsumer& consumer, const StreamOptions& stream = {});

// The same over text in memory; `name` is used in messages.
LogInfo streamCaliperText(std::string_view text, const std::string& name,
                          const ReadOptions& options, const ChunkConsumer& consumer,
                          const StreamOptions& stream = {});

}  // namespace caliper3d::io
