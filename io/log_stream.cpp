#include "io/log_stream.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "io/azimuth_north.h"
#include "io/curve_plan.h"
#include "io/dlis/dlis_reader.h"
#include "io/dlis/dlis_stream.h"
#include "io/las_header.h"
#include "io/las_reader.h"
#include "io/layout/column_text_layout.h"
#include "io/layout/format_sniffing.h"
#include "io/layout/las_layout.h"
#include "io/number_parsing.h"
#include "io/parse_error.h"
#include "io/stream/depth_order.h"
#include "io/stream/mapped_file.h"
#include "io/stream/piece_sharing.h"
#include "io/stream/row_parser.h"
#include "io/stream/row_tally.h"
#include "io/stream/text_source.h"
#include "io/text.h"
#include "io/text_encoding.h"

namespace caliper3d::io {

namespace {

constexpr std::size_t kMinSplitBytes = 256u << 10;
constexpr std::size_t kMaxPieces = 16;

// Rows of one piece mapped through the plan into the product's units.
class PlanSink : public RowSink {
public:
    void reset(const CurvePlan& plan, const std::vector<ColumnSpec>& columns,
               const std::string& file) {
        m_plan = &plan;
        m_file = &file;
        // Reused from block to block: its pages are already mapped.
        if (table.extraCurves.size() != plan.extraColumns.size() || table.armCount == 0)
            table = plan.emptyTable(columns);
        table.clearRows();
        lines.clear();
        depthDiffer.assign(plan.otherDepthColumns.size(), 0);
    }

    void row(const double* raw, std::size_t line) override {
        const CurvePlan& plan = *m_plan;
        const double depth = raw[static_cast<std::size_t>(plan.depthColumn)];
        for (std::size_t k = 0; k < plan.otherDepthColumns.size(); ++k) {
            const double other = raw[static_cast<std::size_t>(plan.otherDepthColumns[k])];
            // Vendors round a second depth curve differently: only a centimetre or more counts.
            if (std::abs(other - depth) * plan.depthScale >= 0.01) ++depthDiffer[k];
        }
        plan.checkAngles(raw, *m_file, line);
        plan.mapRow(raw, table);
        lines.push_back(line);
    }

    SectionTable table;
    std::vector<std::size_t> lines;        // 1-based line of each row
    std::vector<std::size_t> depthDiffer;  // per plan.otherDepthColumns

private:
    const CurvePlan* m_plan = nullptr;
    const std::string* m_file = nullptr;
};

// One piece of a block: its rows and what parsing it found.
struct Piece {
    PlanSink rows;
    RowRun run;
};

// A piece's error, with its line moved from the piece to the file.
[[noreturn]] void rethrowAfter(const std::exception_ptr& error, std::size_t linesBefore) {
    try {
        std::rethrow_exception(error);
    } catch (const ParseError& e) {
        if (e.line() == 0) throw;
        throw ParseError(e.file(), e.line() + linesBefore, e.column(), e.message());
    }
}

// Reads one log: finds its format and layout from the start of the text, then
// parses block after block (the pieces of a block shared between threads),
// puts the rows in depth order and hands them on in chunks.
class LogStreamer {
public:
    LogStreamer(std::string name, const ReadOptions& options, const ChunkConsumer& consumer,
                const StreamOptions& stream)
        : m_name(std::move(name)), m_options(options), m_consumer(consumer), m_stream(stream) {
        m_info.file = m_name;
    }

    LogInfo run(TextSource& source) {
        m_sourceSize = source.size();
        auto reader = std::make_unique<BlockReader>(source, m_stream.blockBytes);
        std::string_view run = reader->next();
        std::string decoded;
        std::unique_ptr<MemorySource> decodedSource;
        if (hasUtf16Mark(run)) {
            // Rare and small: decode it whole, then read the decoded text.
            std::string all(run);
            while (!reader->done()) all += reader->next();
            decoded = fromUtf16IfMarked(std::move(all), m_name);
            m_info.diagnostics.warn(m_name, 1, "text is UTF-16; decoded");
            decodedSource = std::make_unique<MemorySource>(decoded);
            m_sourceSize = decoded.size();
            reader = std::make_unique<BlockReader>(*decodedSource, m_stream.blockBytes);
            run = reader->next();
        }
        m_reader = reader.get();
        if (run.substr(0, 3) == "\xEF\xBB\xBF") run.remove_prefix(3);
        if (trim(run).empty() && m_reader->done())
            throw ParseError(m_name, 0, 0,
                             "expected a caliper log (column text or LAS), found an empty file");
        refuseWhatIsNotALog(run, m_name);
        if (looksLikeLas(run)) {
            readLasHeader(run);
        } else {
            m_layout = columnTextLayout(run, m_name, m_options, m_info);
            m_info.north = readAzimuthNorth(nullptr, m_layout.columns, m_layout.plan, nullptr);
            run = skipLines(run, m_layout.namesLines);
        }
        std::string wrappedText;
        if (m_layout.format.wrapped) {
            // Legacy and small: a depth's values run over lines, so the data is read whole
            // and parsed as one run.
            wrappedText.assign(run);
            while (!m_reader->done()) wrappedText.append(m_reader->next());
            run = wrappedText;
        } else if (m_layout.format.las) {
            settleLasColumns(run, m_lineNumber, m_layout.columns, m_layout.format,
                             m_info.diagnostics);
        }
        if (m_stream.onStart) m_stream.onStart(m_info, estimateRows(run));
        dataLoop(run);
        return finish();
    }

private:
    std::size_t estimateRows(std::string_view dataStart) const {
        const std::size_t sample = std::min<std::size_t>(dataStart.size(), 1u << 20);
        const std::size_t lines = static_cast<std::size_t>(std::count(
            dataStart.begin(), dataStart.begin() + static_cast<std::ptrdiff_t>(sample), '\n'));
        if (lines == 0) return 1;
        const double perLine = static_cast<double>(sample) / static_cast<double>(lines);
        return static_cast<std::size_t>(static_cast<double>(m_sourceSize) / perLine * 1.02) + 16;
    }

    std::string_view skipLines(std::string_view run, std::size_t count) {
        for (std::size_t i = 0; i < count; ++i) {
            const std::size_t nl = run.find('\n');
            run = nl == std::string_view::npos ? std::string_view() : run.substr(nl + 1);
            ++m_lineNumber;
        }
        return run;
    }

    // LAS: gathers the header lines up to the data title (over blocks if need
    // be), parses them in one go and leaves `run` at the first data line.
    void readLasHeader(std::string_view& run) {
        std::string headerText;
        std::size_t lines = 0;
        for (;;) {
            std::size_t pos = 0;
            while (pos < run.size()) {
                const std::size_t nl = run.find('\n', pos);
                const std::size_t end = nl == std::string_view::npos ? run.size() : nl + 1;
                const std::string_view line = trim(run.substr(pos, end - pos));
                ++lines;
                pos = end;
                if (line.empty() || line.front() != '~' || !isLasDataTitle(line)) continue;
                headerText.append(run.substr(0, end));
                run.remove_prefix(end);
                m_lineNumber = lines;
                const LasHeader header = parseLasHeader(headerText, m_name, &m_info.diagnostics);
                m_layout = lasLayout(header, m_name, m_options, m_info);
                keepDeclaredRange(header);
                m_info.north =
                    readAzimuthNorth(&header, m_layout.columns, m_layout.plan, &m_info.diagnostics);
                return;
            }
            headerText.append(run);
            if (m_reader->done()) break;
            run = m_reader->next();
        }
        const LasHeader header = parseLasHeader(headerText, m_name, &m_info.diagnostics);
        if (header.curves.empty())
            throw ParseError(m_name, 0, 0, "expected a ~C (curve information) section, found none");
        throw ParseError(m_name, 0, 0, "expected a ~A (data) section, found none");
    }

    // STRT, STOP and STEP as the header declares them, to check against the data.
    void keepDeclaredRange(const LasHeader& header) {
        const char* names[3] = {"STRT", "STOP", "STEP"};
        for (int k = 0; k < 3; ++k) {
            const LasItem* item = header.wellItem(names[k]);
            double v = 0.0;
            if (!item || !parseNumber(item->value, v) || !std::isfinite(v)) continue;
            // A declared range that is itself "unknown" says nothing.
            if ((header.hasNull && v == header.null) || isCommonNullNumber(v)) continue;
            m_declared[k] = *item;
            m_declaredValue[k] = v;
        }
    }

    // A counted warning for each of STRT, STOP, STEP that disagrees with the data read.
    void checkDeclaredRange() {
        const double scale = m_layout.plan.depthScale;
        if (!(scale > 0.0) || m_info.rows == 0) return;
        const double top = m_info.top_m / scale, bottom = m_info.bottom_m / scale;
        const double step = m_info.step_m / scale;
        // Written to three decimals at least: a thousandth of the file's unit is rounding.
        const double tolerance = 1e-3 + 1e-9 * std::max(std::abs(top), std::abs(bottom));
        auto text = [](double v) {
            char buffer[32];
            std::snprintf(buffer, sizeof buffer, "%g", v);
            return std::string(buffer);
        };
        const std::string unit = m_info.depthUnit.empty() ? "" : " " + m_info.depthUnit;
        const std::string range = "the data run from " + text(top) + " to " + text(bottom) + unit;
        if (m_declared[0] && m_declared[1]) {
            const double lo = std::min(m_declaredValue[0], m_declaredValue[1]);
            const double hi = std::max(m_declaredValue[0], m_declaredValue[1]);
            for (int k = 0; k < 2; ++k) {
                const double v = m_declaredValue[k];
                const double data = v == lo ? top : bottom;
                if (std::abs(v - data) <= tolerance && !(lo == hi && top != bottom)) continue;
                const LasItem& item = *m_declared[k];
                m_info.diagnostics.warn(m_name, item.line,
                                        "header " + item.mnemonic + " " + item.value +
                                            " disagrees with the data: " + range +
                                            "; the data are used");
            }
        }
        if (m_declared[2] && m_declaredValue[2] != 0.0 && m_info.rows > 1) {
            // STEP 0 declares a varying step (LAS 2.0).
            const double declared = std::abs(m_declaredValue[2]);
            if (std::abs(declared - step) > 1e-3 * std::max(declared, step) + 1e-9) {
                const LasItem& item = *m_declared[2];
                m_info.diagnostics.warn(m_name, item.line,
                                        "header STEP " + item.value +
                                            " disagrees with the data: their step is " +
                                            text(step) + unit + " (median); the data are used");
            }
        }
    }

    void dataLoop(std::string_view run) {
        m_order.emplace(m_layout.plan.emptyTable(m_layout.columns), m_options.depthOrder, m_name,
                        m_layout.plan.depthScale, m_stream.chunkRows);
        m_nulls.assign(m_layout.columns.size(), 0);
        m_bad.assign(m_layout.columns.size(), BadValues{});
        m_depthDiffer.assign(m_layout.plan.otherDepthColumns.size(), 0);
        m_pieces.resize(m_stream.threads > 1 && !m_layout.format.wrapped ? kMaxPieces : 1);
        // Joined when the data loop ends, however it ends, while the block it reads still exists.
        PieceSharing sharing(m_pieces.size() > 1);
        m_sharing = &sharing;
        for (;;) {
            if (cancelled()) return;
            const bool finalRun = m_layout.format.wrapped || m_reader->done();
            std::size_t stop = std::string_view::npos;
            processRun(run, finalRun, stop);
            if (stop != std::string_view::npos) {
                readTrailingSections(run.substr(stop));
                return;
            }
            if (finalRun) return;
            run = m_reader->next();
        }
    }

    bool cancelled() {
        if (m_stream.cancel && m_stream.cancel->load(std::memory_order_relaxed)) {
            m_info.cancelled = true;
            return true;
        }
        return false;
    }

    // Cuts a block into pieces of whole lines for the threads to share: about
    // an eighth of a block each (1 MiB by default), at least two once the block
    // is worth splitting.
    std::size_t cutPieces(std::string_view run) {
        std::size_t pieces = 1;
        const std::size_t minSplit = std::min(kMinSplitBytes, m_stream.blockBytes / 2);
        if (m_pieces.size() > 1 && run.size() >= minSplit) {
            const std::size_t pieceBytes = std::max<std::size_t>(m_stream.blockBytes / 8, 1024);
            pieces = std::min(kMaxPieces, std::max<std::size_t>(2, run.size() / pieceBytes));
        }
        m_pieceBegin.assign(1, 0);
        for (std::size_t i = 1; i < pieces; ++i) {
            const std::size_t target = std::max(m_pieceBegin.back(), run.size() * i / pieces);
            const std::size_t nl =
                target == 0 ? std::string_view::npos : run.find('\n', target - 1);
            if (nl == std::string_view::npos || nl + 1 >= run.size()) break;
            if (nl + 1 > m_pieceBegin.back()) m_pieceBegin.push_back(nl + 1);
        }
        m_pieceBegin.push_back(run.size());
        return m_pieceBegin.size() - 1;
    }

    void processRun(std::string_view run, bool finalRun, std::size_t& stop) {
        const std::size_t pieces = cutPieces(run);
        // Lines are counted from 1 within each piece; the piece's place in the
        // file is added below, in order, so no thread has to count ahead.
        const std::function<void(std::size_t)> parsePiece = [&](std::size_t i) {
            const std::string_view text =
                run.substr(m_pieceBegin[i], m_pieceBegin[i + 1] - m_pieceBegin[i]);
            Piece& piece = m_pieces[i];
            piece.rows.reset(m_layout.plan, m_layout.columns, m_name);
            parseRows(m_layout.format, text, 1, finalRun && i + 1 == pieces, piece.rows, piece.run);
        };
        m_sharing->run(pieces, parsePiece);
        const DepthOrdering::Emit emit = [this](const SectionTable& rows) { deliver(rows); };
        for (std::size_t i = 0; i < pieces; ++i) {
            Piece& piece = m_pieces[i];
            const std::size_t before = m_lineNumber;
            if (piece.run.error) rethrowAfter(piece.run.error, before);
            for (std::size_t& line : piece.rows.lines) line += before;
            for (Warning& w : piece.run.diagnostics.warnings) w.line += before;
            take(piece, emit, before);
            m_lineNumber += piece.run.linesConsumed;
            if (piece.run.stopped) {
                stop = m_pieceBegin[i] + piece.run.stopOffset;
                break;
            }
        }
        m_order->emitReady(emit);
    }

    void take(Piece& piece, const DepthOrdering::Emit& emit, std::size_t linesBefore) {
        for (std::size_t c = 0; c < m_nulls.size(); ++c) m_nulls[c] += piece.run.nulls[c];
        for (std::size_t c = 0; c < m_bad.size() && c < piece.run.bad.size(); ++c)
            m_bad[c].add(piece.run.bad[c], linesBefore);
        if (m_info.firstDataLine == 0 && !piece.rows.lines.empty())
            m_info.firstDataLine = piece.rows.lines.front();
        for (std::size_t k = 0; k < m_depthDiffer.size(); ++k)
            m_depthDiffer[k] += piece.rows.depthDiffer[k];
        m_info.diagnostics.merge(piece.run.diagnostics);
        SectionTable& t = piece.rows.table;
        if (m_layout.radiiOnly)
            for (double& depth : t.depth_m)
                depth = static_cast<double>(m_rowIndex++) * m_options.rowStep_m;
        m_order->add(t, piece.rows.lines, emit);
    }

    void deliver(const SectionTable& chunk) {
        if (chunk.rowCount() == 0) return;
        m_tally.add(chunk, m_info);
        m_consumer(chunk);
    }

    void readTrailingSections(std::string_view rest) {
        std::string tail(rest);
        while (!m_reader->done()) tail += m_reader->next();
        forEachTrimmedLine(tail, m_lineNumber + 1, [&](std::string_view l, std::size_t line) {
            if (!l.empty() && l.front() == '~')
                m_info.diagnostics.warn(m_name, line,
                                        "section '" + std::string(l.substr(0, 40)) +
                                            "' after the data is not read; skipped");
            return true;
        });
    }

    LogInfo finish() {
        Diagnostics& d = m_info.diagnostics;
        if (m_order)
            m_order->finish(
                !m_info.cancelled, [this](const SectionTable& rows) { deliver(rows); },
                [this] { return !cancelled(); }, d);
        const std::vector<ColumnSpec>& columns = m_layout.columns;
        const CurvePlan& plan = m_layout.plan;
        for (std::size_t k = 0; k < m_depthDiffer.size(); ++k) {
            if (!m_depthDiffer[k]) continue;
            const ColumnSpec& c = columns[static_cast<std::size_t>(plan.otherDepthColumns[k])];
            d.warn(m_name, c.line,
                   "depth curve " + c.mnemonic + " differs from the index " +
                       columns[static_cast<std::size_t>(plan.depthColumn)].mnemonic + " on " +
                       std::to_string(m_depthDiffer[k]) +
                       " rows by 1 cm or more; the index is used");
        }
        warnBadValues(m_layout.format, m_bad, d);
        for (std::size_t c = 0; c < m_info.curves.size() && c < m_nulls.size(); ++c)
            m_info.curves[c].nulls = m_nulls[c];
        if (m_layout.radiiOnly && !m_info.curves.empty()) m_info.curves.front().nulls = 0;
        m_info.arms = plan.armCount;
        m_tally.finish(m_info);
        if (!m_info.cancelled) checkDeclaredRange();
        if (m_info.rows == 0 && !m_info.cancelled) {
            if (m_layout.format.las)
                throw ParseError(m_name, m_lineNumber, 0,
                                 "expected data rows after ~A, found none");
            throw ParseError(
                m_name, 0, 0,
                "expected rows of numbers (" + m_layout.format.layout + "), found none");
        }
        return std::move(m_info);
    }

    std::string m_name;
    const ReadOptions& m_options;
    const ChunkConsumer& m_consumer;
    const StreamOptions& m_stream;
    LogInfo m_info;
    BlockReader* m_reader = nullptr;
    std::size_t m_sourceSize = 0;
    std::size_t m_lineNumber = 0;  // lines consumed so far

    LogLayout m_layout;
    std::optional<DepthOrdering> m_order;
    std::vector<Piece> m_pieces;  // one per piece of a block
    std::vector<std::size_t> m_pieceBegin;
    PieceSharing* m_sharing = nullptr;  // set while dataLoop runs
    std::size_t m_rowIndex = 0;         // radii-only text: rows so far
    std::vector<std::size_t> m_nulls, m_depthDiffer;
    std::vector<BadValues> m_bad;  // per column: values that were not numbers (lenient curves)
    std::optional<LasItem> m_declared[3];  // STRT, STOP, STEP of a LAS header, when numbers
    double m_declaredValue[3] = {0.0, 0.0, 0.0};
    RowTally m_tally;
};

}  // namespace

LogInfo streamCaliperLog(const std::string& path, const ReadOptions& options,
                         const ChunkConsumer& consumer, const StreamOptions& stream) {
    {
        // DLIS is binary and read by offset: mapped, not streamed as text.
        FileSource head(path);
        std::string start(512, '\0');
        start.resize(head.read(start.data(), start.size()));
        if (dlis::looksLikeDlis(start)) {
            const MappedFile file(path);
            return streamDlis(file.bytes(), path, options, consumer, stream,
                              [&file](std::size_t end) { file.release(end); });
        }
    }
    FileSource source(path);
    return LogStreamer(path, options, consumer, stream).run(source);
}

LogInfo streamCaliperText(std::string_view text, const std::string& name,
                          const ReadOptions& options, const ChunkConsumer& consumer,
                          const StreamOptions& stream) {
    if (dlis::looksLikeDlis(text.substr(0, 512)))
        return streamDlis(text, name, options, consumer, stream);
    MemorySource source(text);
    return LogStreamer(name, options, consumer, stream).run(source);
}

}  // namespace caliper3d::io
