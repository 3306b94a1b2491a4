#include "io/log_stream.h"

#include <fast_float/fast_float.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <cstring>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>
#include <utility>
#include <vector>

#include "io/curve_plan.h"
#include "io/las_header.h"
#include "io/las_reader.h"
#include "io/median.h"
#include "io/number_parsing.h"
#include "io/parse_error.h"
#include "io/survey_reader.h"
#include "io/text_encoding.h"

namespace caliper3d::io {

namespace {

constexpr double kMaxPlausibleRadius_in = 30.0;
constexpr std::size_t kStepSamples = 65536;
constexpr std::size_t kMinSplitBytes = 256u << 10;
constexpr std::size_t kMaxPieces = 16;

// Shares the pieces of one block between the calling thread and one worker
// thread that lives as long as the read. Pieces are claimed one at a time, so
// when the other core is busy with another job the caller simply parses more
// of them instead of waiting for a fixed half (which made two threads slower
// than one on a loaded machine).
class PieceSharing {
public:
    explicit PieceSharing(bool withWorker) {
        if (withWorker) m_worker = std::thread([this] { work(); });
    }
    ~PieceSharing() {
        {
            std::lock_guard<std::mutex> lock(m_mutex);
            m_stop = true;
        }
        m_wake.notify_all();
        if (m_worker.joinable()) m_worker.join();
    }
    PieceSharing(const PieceSharing&) = delete;
    PieceSharing& operator=(const PieceSharing&) = delete;

    // Runs task(i) for every i below count and returns when all have run.
    // The task must not throw (parseRows keeps its error).
    void run(std::size_t count, const std::function<void(std::size_t)>& task) {
        if (!m_worker.joinable()) {
            for (std::size_t i = 0; i < count; ++i) task(i);
            return;
        }
        {
            std::lock_guard<std::mutex> lock(m_mutex);
            m_task = &task;
            m_count = count;
            m_next = 0;
            m_done = 0;
            ++m_generation;
        }
        m_wake.notify_one();
        std::unique_lock<std::mutex> lock(m_mutex);
        while (m_next < m_count) {
            const std::size_t i = m_next++;
            lock.unlock();
            task(i);
            lock.lock();
            ++m_done;
        }
        m_finished.wait(lock, [&] { return m_done == m_count; });
        m_task = nullptr;
    }

private:
    void work() {
        std::unique_lock<std::mutex> lock(m_mutex);
        std::uint64_t seen = 0;
        for (;;) {
            m_wake.wait(lock, [&] { return m_stop || m_generation != seen; });
            if (m_stop) return;
            seen = m_generation;
            while (m_task && m_next < m_count) {
                const std::size_t i = m_next++;
                const std::function<void(std::size_t)>& task = *m_task;
                lock.unlock();
                task(i);
                lock.lock();
                if (++m_done == m_count) m_finished.notify_one();
            }
        }
    }

    std::thread m_worker;
    std::mutex m_mutex;
    std::condition_variable m_wake, m_finished;
    const std::function<void(std::size_t)>* m_task = nullptr;
    std::size_t m_count = 0, m_next = 0, m_done = 0;
    std::uint64_t m_generation = 0;
    bool m_stop = false;
};

// ---- where the text comes from ------------------------------------------------

class TextSource {
public:
    virtual ~TextSource() = default;
    virtual std::size_t read(char* to, std::size_t n) = 0;
    virtual std::size_t size() const = 0;
};

class FileSource : public TextSource {
public:
    explicit FileSource(const std::string& path) : m_path(path) {
        m_fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
        if (m_fd < 0)
            throw ParseError(path, 0, 0,
                             "cannot open file for reading: " + std::string(std::strerror(errno)));
        const off_t end = ::lseek(m_fd, 0, SEEK_END);
        m_size = end > 0 ? static_cast<std::size_t>(end) : 0;
        ::lseek(m_fd, 0, SEEK_SET);
#ifdef POSIX_FADV_SEQUENTIAL
        ::posix_fadvise(m_fd, 0, 0, POSIX_FADV_SEQUENTIAL);
#endif
    }
    ~FileSource() override {
        ::close(m_fd);
    }
    FileSource(const FileSource&) = delete;
    FileSource& operator=(const FileSource&) = delete;
    std::size_t read(char* to, std::size_t n) override {
        for (;;) {
            const ssize_t got = ::read(m_fd, to, n);
            if (got >= 0) return static_cast<std::size_t>(got);
            if (errno != EINTR)
                throw ParseError(m_path, 0, 0, "read failed: " + std::string(std::strerror(errno)));
        }
    }
    std::size_t size() const override {
        return m_size;
    }

private:
    std::string m_path;
    int m_fd = -1;
    std::size_t m_size = 0;
};

class MemorySource : public TextSource {
public:
    explicit MemorySource(std::string_view text) : m_text(text) {}
    std::size_t read(char* to, std::size_t n) override {
        n = std::min(n, m_text.size() - m_pos);
        std::memcpy(to, m_text.data() + m_pos, n);
        m_pos += n;
        return n;
    }
    std::size_t size() const override { return m_text.size(); }

private:
    std::string_view m_text;
    std::size_t m_pos = 0;
};

// Hands out runs of whole lines, a block at a time; the last run may end in
// an unterminated line.
class BlockReader {
public:
    BlockReader(TextSource& source, std::size_t blockBytes)
        : m_source(source), m_buffer(std::max<std::size_t>(blockBytes, 4096)) {}

    std::string_view next() {
        std::memmove(m_buffer.data(), m_buffer.data() + m_begin, m_end - m_begin);
        m_end -= m_begin;
        m_begin = 0;
        for (;;) {
            while (!m_eof && m_end < m_buffer.size()) {
                const std::size_t got =
                    m_source.read(m_buffer.data() + m_end, m_buffer.size() - m_end);
                if (got == 0) m_eof = true;
                m_end += got;
            }
            if (m_eof) {
                m_begin = m_end;
                return {m_buffer.data(), m_end};
            }
            const void* nl = memrchr(m_buffer.data(), '\n', m_end);
            if (nl != nullptr) {
                m_begin =
                    static_cast<std::size_t>(static_cast<const char*>(nl) - m_buffer.data()) + 1;
                return {m_buffer.data(), m_begin};
            }
            m_buffer.resize(m_buffer.size() * 2);  // a line longer than a block
        }
    }
    bool done() const { return m_eof && m_begin == m_end; }

private:
    TextSource& m_source;
    std::vector<char> m_buffer;
    std::size_t m_begin = 0, m_end = 0;
    bool m_eof = false;
};

// ---- tables -----------------------------------------------------------------------

void appendRange(const std::vector<double>& from, std::vector<double>& to, std::size_t a,
                 std::size_t b, std::size_t width) {
    if (from.empty()) return;
    to.insert(to.end(), from.begin() + static_cast<std::ptrdiff_t>(a * width),
              from.begin() + static_cast<std::ptrdiff_t>(b * width));
}

void appendRows(const SectionTable& from, SectionTable& to, std::size_t a, std::size_t b) {
    if (a >= b) return;
    const std::size_t arms = static_cast<std::size_t>(from.armCount);
    appendRange(from.depth_m, to.depth_m, a, b, 1);
    appendRange(from.radius_mm, to.radius_mm, a, b, arms);
    appendRange(from.p1az_deg, to.p1az_deg, a, b, 1);
    appendRange(from.devi_deg, to.devi_deg, a, b, 1);
    appendRange(from.hazi_deg, to.hazi_deg, a, b, 1);
    appendRange(from.rb_deg, to.rb_deg, a, b, 1);
    appendRange(from.bitSize_mm, to.bitSize_mm, a, b, 1);
    for (std::size_t e = 0; e < from.extraCurves.size(); ++e)
        appendRange(from.extraCurves[e].values, to.extraCurves[e].values, a, b, 1);
}

void clearRows(SectionTable& t) {
    t.depth_m.clear();
    t.radius_mm.clear();
    t.p1az_deg.clear();
    t.devi_deg.clear();
    t.hazi_deg.clear();
    t.rb_deg.clear();
    t.bitSize_mm.clear();
    for (ExtraCurve& e : t.extraCurves) e.values.clear();
}

void permute(SectionTable& t, const std::vector<std::size_t>& order) {
    auto apply = [&](std::vector<double>& v, std::size_t width) {
        if (v.empty()) return;
        std::vector<double> out;
        out.reserve(order.size() * width);
        for (std::size_t r : order)
            out.insert(out.end(), v.begin() + static_cast<std::ptrdiff_t>(r * width),
                       v.begin() + static_cast<std::ptrdiff_t>((r + 1) * width));
        v.swap(out);
    };
    apply(t.depth_m, 1);
    apply(t.radius_mm, static_cast<std::size_t>(t.armCount));
    apply(t.p1az_deg, 1);
    apply(t.devi_deg, 1);
    apply(t.hazi_deg, 1);
    apply(t.rb_deg, 1);
    apply(t.bitSize_mm, 1);
    for (ExtraCurve& c : t.extraCurves) apply(c.values, 1);
}

// ---- rows -----------------------------------------------------------------------

bool isBlank(char c) {
    return c == ' ' || c == '\t' || c == '\r';
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && (isBlank(s.front()) || s.front() == '\n')) s.remove_prefix(1);
    while (!s.empty() && (isBlank(s.back()) || s.back() == '\n')) s.remove_suffix(1);
    return s;
}

std::vector<std::string_view> splitBlank(std::string_view s) {
    std::vector<std::string_view> out;
    for (std::size_t i = 0; i < s.size();) {
        while (i < s.size() && isBlank(s[i])) ++i;
        std::size_t j = i;
        while (j < s.size() && !isBlank(s[j])) ++j;
        if (j > i) out.push_back(s.substr(i, j - i));
        i = j;
    }
    return out;
}

// What a data line looks like and how its values become a row.
struct RowFormat {
    std::string file;
    bool las = false;
    char delimiter = ' ';          // ' ' = runs of blanks; ',' = commas
    std::size_t declared = 0;      // columns of the raw row
    std::size_t tokens = 0;        // values per line in the file
    std::size_t firstColumn = 0;   // raw column of the first token (1 for radii-only text)
    std::vector<char> textColumn;  // per raw column
    bool hasNull = false;
    double null = 0.0;
    NullPolicy nullPolicy = NullPolicy::Common;
    int depthColumn = 0;
    std::string layout;              // for messages: "10 columns (depth R1..R6 ...)"
    std::vector<std::string> names;  // per raw column, for messages
    const CurvePlan* plan = nullptr;
};

// Rows parsed from one run of lines (one thread's share of a block).
struct ParsedRows {
    SectionTable table;
    std::vector<std::size_t> lines;        // 1-based line of each row
    std::vector<std::size_t> nulls;        // per raw column
    std::vector<std::size_t> depthDiffer;  // per plan.otherDepthColumns
    Diagnostics diagnostics;
    std::size_t linesConsumed = 0;
    bool stopped = false;  // a '~' section line ended the data
    std::size_t stopOffset = 0;
    std::exception_ptr error;
};

bool restIsBlank(std::string_view text, std::size_t from) {
    for (std::size_t i = from; i < text.size(); ++i)
        if (!isBlank(text[i]) && text[i] != '\n') return false;
    return true;
}

void parseRows(const RowFormat& f, std::string_view text, std::size_t firstLine, bool finalRun,
               const std::vector<ColumnSpec>& columns, ParsedRows& out) {
    try {
        const CurvePlan& plan = *f.plan;
        // Reused from block to block: its pages are already mapped.
        if (out.table.extraCurves.size() != plan.extraColumns.size())
            out.table = plan.emptyTable(columns);
        clearRows(out.table);
        out.lines.clear();
        out.diagnostics = Diagnostics{};
        out.linesConsumed = 0;
        out.stopped = false;
        out.error = nullptr;
        out.nulls.assign(f.declared, 0);
        out.depthDiffer.assign(plan.otherDepthColumns.size(), 0);
        std::vector<double> raw(f.declared, kNaN);
        const bool commaDelimited = f.delimiter == ',';
        const char* const base = text.data();
        std::size_t pos = 0, lineNumber = firstLine - 1;
        while (pos < text.size()) {
            const char* lineBegin = base + pos;
            const void* nl = std::memchr(lineBegin, '\n', text.size() - pos);
            const char* lineEnd = nl ? static_cast<const char*>(nl) : base + text.size();
            const std::size_t lineStart = pos;
            pos = static_cast<std::size_t>(lineEnd - base) + 1;
            ++lineNumber;
            ++out.linesConsumed;
            const char* p = lineBegin;
            while (p < lineEnd && isBlank(*p)) ++p;
            if (p == lineEnd || *p == '#') continue;
            if (*p == '~' && f.las) {
                out.stopped = true;
                out.stopOffset = lineStart;
                --out.linesConsumed;
                return;
            }
            auto column = [&](const char* at) {
                return static_cast<std::size_t>(at - lineBegin) + 1;
            };
            std::size_t t = 0;
            bool overflow = false;
            for (; t < f.tokens; ++t) {
                if (t > 0 && commaDelimited) {
                    while (p < lineEnd && isBlank(*p)) ++p;
                    if (p < lineEnd && *p == ',')
                        ++p;
                    else
                        break;
                }
                while (p < lineEnd && isBlank(*p)) ++p;
                if (p == lineEnd && !commaDelimited) break;
                const std::size_t c = f.firstColumn + t;
                const char* tokenBegin = p;
                double v = 0.0;
                auto [end, ec] = fast_float::from_chars(p, lineEnd, v);
                const bool clean = ec == std::errc() && (end == lineEnd || isBlank(*end) ||
                                                         (commaDelimited && *end == ','));
                if (clean && !f.textColumn[c]) {
                    p = end;
                } else {
                    const char* tokenEnd = p;
                    if (f.textColumn[c] && p < lineEnd && *p == '"') {
                        // LAS 3.0 quotes a string that holds the delimiter: "SAND, SHALY".
                        const void* close =
                            std::memchr(p + 1, '"', static_cast<std::size_t>(lineEnd - p - 1));
                        if (!close)
                            throw ParseError(f.file, lineNumber, column(p),
                                             "expected a closing '\"' for the text of curve " +
                                                 f.names[c] + ", found the end of the line");
                        tokenEnd = static_cast<const char*>(close) + 1;
                    } else {
                        while (tokenEnd < lineEnd && !isBlank(*tokenEnd) &&
                               !(commaDelimited && *tokenEnd == ','))
                            ++tokenEnd;
                        if (commaDelimited && f.textColumn[c])  // text may hold blanks
                            while (tokenEnd < lineEnd && *tokenEnd != ',') ++tokenEnd;
                    }
                    const std::string_view token(tokenBegin,
                                                 static_cast<std::size_t>(tokenEnd - tokenBegin));
                    p = tokenEnd;
                    if (f.textColumn[c]) {
                        v = kNaN;
                    } else if (parseNumber(token, v)) {
                    } else if (f.las && c != static_cast<std::size_t>(f.depthColumn) &&
                               isNullToken(token, f.nullPolicy)) {
                        v = kNaN;
                        overflow = !token.empty() &&
                                   token.find_first_not_of('*') == std::string_view::npos;
                    } else {
                        throw ParseError(f.file, lineNumber, column(tokenBegin),
                                         "expected a number for " +
                                             (f.las ? "curve " : std::string()) + f.names[c] +
                                             ", found '" + std::string(token.substr(0, 40)) + "'");
                    }
                }
                if (!std::isfinite(v)) {
                    v = kNaN;
                } else if (f.las && c != static_cast<std::size_t>(f.depthColumn) &&
                           ((f.hasNull && v == f.null) ||
                            (f.nullPolicy == NullPolicy::Common && isCommonNullNumber(v)))) {
                    v = kNaN;
                }
                raw[c] = v;
            }
            while (p < lineEnd && isBlank(*p)) ++p;
            if (t == f.tokens && p < lineEnd)
                throw ParseError(f.file, lineNumber, column(p),
                                 "expected " + f.layout + ", found more values");
            if (t < f.tokens) {
                if (overflow) {
                    // An overflowed field ran into the next ones: they are unknown, not lost.
                    out.diagnostics.warn(f.file, lineNumber,
                                         "field overflow covers the last " +
                                             std::to_string(f.tokens - t + 1) +
                                             " values; read as null");
                    for (; t < f.tokens; ++t) raw[f.firstColumn + t] = kNaN;
                } else if (finalRun && restIsBlank(text, pos)) {
                    out.diagnostics.warn(f.file, lineNumber,
                                         "last line holds " + std::to_string(t) + " of " +
                                             std::to_string(f.tokens) +
                                             " values (truncated file?); skipped");
                    continue;
                } else {
                    throw ParseError(
                        f.file, lineNumber, 0,
                        "expected " + f.layout + ", found " + std::to_string(t) + " values");
                }
            }
            for (std::size_t c = 0; c < f.declared; ++c) out.nulls[c] += std::isnan(raw[c]);
            const double depth = raw[static_cast<std::size_t>(plan.depthColumn)];
            for (std::size_t k = 0; k < plan.otherDepthColumns.size(); ++k) {
                const double other = raw[static_cast<std::size_t>(plan.otherDepthColumns[k])];
                // Vendors round a second depth curve differently: only a centimetre or more counts.
                if (std::abs(other - depth) * plan.depthScale >= 0.01) ++out.depthDiffer[k];
            }
            plan.checkAngles(raw.data(), f.file, lineNumber);
            plan.mapRow(raw.data(), out.table);
            out.lines.push_back(lineNumber);
        }
    } catch (...) {
        out.error = std::current_exception();
    }
}

std::string lasVersionText(const LasHeader& h) {
    std::ostringstream version;
    version << "LAS " << h.version << (h.version == std::floor(h.version) ? ".0" : "")
            << (h.wrap ? ", wrapped" : "");
    return version.str();
}

// ---- the reader -------------------------------------------------------------------

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
        std::size_t offset = 0;
        if (run.substr(0, 3) == "\xEF\xBB\xBF") offset = 3;
        if (trim(run).empty() && m_reader->done())
            throw ParseError(m_name, 0, 0,
                             "expected a caliper log (column text or LAS), found an empty file");
        refuseWhatIsNotALog(run.substr(offset));
        if (looksLikeLas(run.substr(offset)))
            readLasHeader(run, offset);
        else
            prepareColumnText(run, offset);
        if (m_wrapped) return finishWrapped(run.substr(offset));
        if (m_stream.onStart) m_stream.onStart(m_info, estimateRows(run.substr(offset)));
        dataLoop(run.substr(offset), offset);
        return finish();
    }

private:
    // Files that are text but not a caliper log would otherwise read as column
    // text and fail late with a misleading message, or worse, a survey of 11
    // numbers per line would read as an 11-arm log.
    void refuseWhatIsNotALog(std::string_view start) const {
        const std::string_view head = start.substr(0, 64u << 10);
        if (const void* nul = std::memchr(head.data(), '\0', head.size())) {
            const std::size_t at =
                static_cast<std::size_t>(static_cast<const char*>(nul) - head.data());
            const std::size_t line =
                1 + static_cast<std::size_t>(std::count(
                        head.begin(), head.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
            const std::size_t newline = at == 0 ? std::string_view::npos : head.rfind('\n', at - 1);
            const std::size_t column = newline == std::string_view::npos ? at + 1 : at - newline;
            throw ParseError(m_name, line, column,
                             "expected text, found a NUL byte (a binary file, or UTF-16 without a "
                             "byte-order mark)");
        }
        const std::size_t first = head.find_first_not_of(" \t\r\n");
        if (first != std::string_view::npos && (head[first] == '{' || head[first] == '['))
            throw ParseError(
                m_name,
                1 + static_cast<std::size_t>(std::count(
                        head.begin(), head.begin() + static_cast<std::ptrdiff_t>(first), '\n')),
                0, "expected a caliper log (LAS or column text), found JSON");
        if (!looksLikeLas(head) && looksLikeSurvey(head))
            throw ParseError(
                m_name, 0, 0,
                "expected a caliper log, found a deviation survey (a line names measured depth, "
                "inclination and azimuth columns, and no caliper curves): give it with --survey, "
                "or see it with caliper3d info");
    }

    static bool looksLikeLas(std::string_view text) {
        std::size_t i = 0;
        while (i < text.size()) {
            while (i < text.size() && (isBlank(text[i]) || text[i] == '\n')) ++i;
            if (i < text.size() && text[i] == '#') {
                const std::size_t nl = text.find('\n', i);
                if (nl == std::string_view::npos) return false;
                i = nl + 1;
                continue;
            }
            return i < text.size() && text[i] == '~';
        }
        return false;
    }

    std::size_t estimateRows(std::string_view dataStart) const {
        const std::size_t sample = std::min<std::size_t>(dataStart.size(), 1u << 20);
        const std::size_t lines = static_cast<std::size_t>(std::count(
            dataStart.begin(), dataStart.begin() + static_cast<std::ptrdiff_t>(sample), '\n'));
        if (lines == 0) return 1;
        const double perLine = static_cast<double>(sample) / static_cast<double>(lines);
        return static_cast<std::size_t>(static_cast<double>(m_sourceSize) / perLine * 1.02) + 16;
    }

    // LAS: gather header lines up to the data title, then parse them in one go.
    void readLasHeader(std::string_view& run, std::size_t& offset) {
        std::string headerText;
        std::size_t lines = 0;
        for (;;) {
            std::size_t pos = offset;
            while (pos < run.size()) {
                std::size_t nl = run.find('\n', pos);
                const std::size_t end = nl == std::string_view::npos ? run.size() : nl + 1;
                const std::string_view line = trim(run.substr(pos, end - pos));
                ++lines;
                if (!line.empty() && line.front() == '~' && isLasDataTitle(line)) {
                    headerText.append(run.substr(offset, end - offset));
                    offset = end;
                    m_lineNumber = lines;
                    m_header = parseLasHeader(headerText, m_name, &m_info.diagnostics);
                    m_headerText = std::move(headerText);
                    startLas();
                    return;
                }
                pos = end;
            }
            headerText.append(run.substr(offset));
            offset = 0;
            if (m_reader->done()) break;
            run = m_reader->next();
        }
        m_header = parseLasHeader(headerText, m_name, &m_info.diagnostics);
        if (m_header.curves.empty())
            throw ParseError(m_name, 0, 0, "expected a ~C (curve information) section, found none");
        throw ParseError(m_name, 0, 0, "expected a ~A (data) section, found none");
    }

    void startLas() {
        const LasHeader& h = m_header;
        m_info.format = lasVersionText(h);
        if (const LasItem* well = h.wellItem("WELL")) m_info.wellName = well->value;
        m_info.location = readWellLocation(h, m_name, &m_info.diagnostics);
        if (h.curves.empty())
            throw ParseError(m_name, 0, 0, "expected a ~C (curve information) section, found none");
        m_columns = lasColumns(h, &m_info.diagnostics);
        if (h.wrap) {
            m_wrapped = true;
            return;
        }
        m_plan = makeCurvePlan(m_columns, &h, m_options, m_name, m_info, m_info.diagnostics);
        m_format.file = m_name;
        m_format.las = true;
        m_format.delimiter = h.delimiter == ',' ? ',' : ' ';
        m_format.declared = m_columns.size();
        m_format.tokens = m_columns.size();  // settled on the first data line
        m_format.hasNull = h.hasNull;
        m_format.null = h.null;
        m_format.nullPolicy = h.onlyDeclaredNull ? NullPolicy::Declared : m_options.nullPolicy;
        m_format.depthColumn = m_plan.depthColumn;
        for (const ColumnSpec& c : m_columns) {
            m_format.textColumn.push_back(c.text);
            m_format.names.push_back(c.mnemonic);
        }
        m_format.layout = std::to_string(m_columns.size()) + " values (one per ~C curve)";
        m_format.plan = &m_plan;
        m_settleLasColumns = true;
    }

    // LAS files may hold fewer data columns than ~C curves ("excess curves").
    void settleLasColumns(std::string_view text) {
        m_settleLasColumns = false;
        std::size_t pos = 0, line = m_lineNumber;
        while (pos < text.size()) {
            const std::size_t nl = text.find('\n', pos);
            const std::size_t end = nl == std::string_view::npos ? text.size() : nl;
            const std::string_view l = trim(text.substr(pos, end - pos));
            pos = end + 1;
            ++line;
            if (l.empty() || l.front() == '#') continue;
            if (l.front() == '~') return;
            std::size_t count = 0;
            if (m_format.delimiter == ',') {
                count = static_cast<std::size_t>(std::count(l.begin(), l.end(), ',')) + 1;
            } else {
                for (std::size_t i = 0; i < l.size();) {
                    while (i < l.size() && isBlank(l[i])) ++i;
                    if (i == l.size()) break;
                    ++count;
                    while (i < l.size() && !isBlank(l[i])) ++i;
                }
            }
            const std::size_t declared = m_columns.size();
            if (count < declared && count > 0 && m_format.delimiter != ',') {
                std::string missing;
                for (std::size_t c = count; c < declared; ++c)
                    missing += (missing.empty() ? "" : ", ") + m_columns[c].mnemonic;
                if (static_cast<std::size_t>(m_plan.depthColumn) >= count)
                    throw ParseError(m_name, line, 0,
                                     "expected the depth curve among the data columns, found " +
                                         std::to_string(count) + " values");
                m_info.diagnostics.warn(
                    m_name, line,
                    std::to_string(declared) + " curves declared but rows hold " +
                        std::to_string(count) + " values; no data for " + missing);
                m_format.tokens = count;
                m_format.layout = std::to_string(count) + " values";
            }
            return;
        }
    }

    // Column text with a line of names: each name is a mnemonic with an optional unit
    // ("R1_in", "BS(mm)", "DEVI[deg]"), and the roles come from the mnemonics as in LAS, so
    // any order and any extra curve (GR, RB, BS, ...) reads right. Without units the text
    // defaults apply (depth in metres, radii in inches unless implausible).
    void prepareNamedColumns(const std::vector<std::string_view>& names, std::size_t line,
                             const std::vector<std::string_view>& firstRow) {
        bool anyUnit = false;
        for (std::string_view n : names) {
            auto [mnemonic, unit] = splitColumnName(n);
            anyUnit = anyUnit || !unit.empty();
            m_columns.push_back({std::string(mnemonic), std::string(unit), "", false, line});
        }
        ReadOptions options = m_options;
        if (!anyUnit) {
            if (!options.depthUnit) options.depthUnit = LengthUnit::Metre;
            if (!options.radiusUnit) {
                std::vector<double> radii;
                for (std::size_t c = 0; c < names.size() && c < firstRow.size(); ++c) {
                    const CurveRole role = guessRole(m_columns[c].mnemonic).role;
                    double v = 0.0;
                    if ((role == CurveRole::Radius || role == CurveRole::Finger) &&
                        parseNumber(firstRow[c], v))
                        radii.push_back(v);
                }
                options.radiusUnit = unitlessRadiusUnit(std::move(radii), line);
            }
        }
        m_plan = makeCurvePlan(m_columns, nullptr, options, m_name, m_info, m_info.diagnostics);
        if (!anyUnit) {
            // Say which units were assumed.
            m_info.depthUnit = std::string(unitName(*options.depthUnit));
            m_info.curves[static_cast<std::size_t>(m_plan.depthColumn)].unit =
                m_info.depthUnit + " (assumed)";
            for (int c : m_plan.armColumn)
                m_info.curves[static_cast<std::size_t>(c)].unit =
                    std::string(unitName(*options.radiusUnit)) + " (assumed)";
            if (m_plan.bitSizeColumn >= 0)
                m_info.curves[static_cast<std::size_t>(m_plan.bitSizeColumn)].unit =
                    std::string(unitName(*options.radiusUnit)) + " (assumed)";
        }
        m_info.format = "column text (" + std::to_string(names.size()) +
                        " named columns, names on line " + std::to_string(line) + ")";
        m_format.file = m_name;
        m_format.las = false;
        m_format.declared = m_columns.size();
        m_format.tokens = m_columns.size();
        m_format.firstColumn = 0;
        m_format.textColumn.assign(m_columns.size(), 0);
        for (const ColumnSpec& c : m_columns) m_format.names.push_back(c.mnemonic);
        m_format.layout = std::to_string(m_columns.size()) + " named columns";
        m_format.depthColumn = m_plan.depthColumn;
        m_format.plan = &m_plan;
    }

    // Column text without units: radii in inches, unless the first row's median
    // radius is over kMaxPlausibleRadius_in inches (a 1.5 m wide hole): those are
    // far likelier millimetres, read so with a warning.
    LengthUnit unitlessRadiusUnit(std::vector<double> radii, std::size_t line) {
        if (radii.empty()) return LengthUnit::Inch;
        const double median = medianInPlace(radii);
        if (!(median > kMaxPlausibleRadius_in)) return LengthUnit::Inch;
        m_info.diagnostics.warn(m_name, line,
                                "radii near " + std::to_string(median) +
                                    " would be inches, far too large: read as millimetres (give "
                                    "--radius-unit to choose)");
        return LengthUnit::Millimetre;
    }

    void prepareColumnText(std::string_view run, std::size_t offset) {
        if (m_options.armCount < kMinArms || m_options.armCount > kMaxArms)
            throw ParseError(m_name, 0, 0,
                             "arm count must be between " + std::to_string(kMinArms) + " and " +
                                 std::to_string(kMaxArms));
        int arms = m_options.armCount;
        // The first content line decides: named columns, radii only, or the reference layout.
        // A line of names before it (or a '#' comment line of names right before it, as our
        // writer and many scripts write) names the columns when it has one name per column.
        std::size_t pos = offset, line = 0;
        std::vector<std::string_view> tokens, names, commentNames;
        std::size_t namesLine = 0, commentLine = 0;
        while (pos < run.size()) {
            const std::size_t nl = run.find('\n', pos);
            const std::size_t end = nl == std::string_view::npos ? run.size() : nl;
            const std::string_view l = trim(run.substr(pos, end - pos));
            pos = end + 1;
            ++line;
            if (l.empty()) continue;
            if (l.front() == '#') {
                const std::size_t text = l.find_first_not_of('#');
                commentNames = text == std::string_view::npos ? std::vector<std::string_view>()
                                                              : splitBlank(trim(l.substr(text)));
                commentLine = line;
                continue;
            }
            for (std::size_t i = 0; i < l.size();) {
                while (i < l.size() && isBlank(l[i])) ++i;
                std::size_t j = i;
                while (j < l.size() && !isBlank(l[j])) ++j;
                if (j > i) tokens.push_back(l.substr(i, j - i));
                i = j;
            }
            double v = 0.0;
            bool anyNumber = false;
            for (std::string_view t : tokens) anyNumber = anyNumber || parseNumber(t, v);
            if (!anyNumber) {
                m_skipFirstLines = line;  // a line of column names
                names = tokens;
                namesLine = line;
                commentNames.clear();
                tokens.clear();
                continue;
            }
            break;
        }
        const int found = static_cast<int>(tokens.size());
        if (!names.empty() && static_cast<int>(names.size()) != found)
            m_info.diagnostics.warn(
                m_name, namesLine,
                std::to_string(names.size()) + " column names over " + std::to_string(found) +
                    " columns of numbers: names ignored, columns read as the reference layout");
        if (static_cast<int>(names.size()) != found) {
            names.clear();
            // A comment line of names counts only when it matches and starts with a depth.
            if (static_cast<int>(commentNames.size()) == found && found > 0 &&
                guessRole(splitColumnName(commentNames.front()).first).role == CurveRole::Depth) {
                names = commentNames;
                namesLine = commentLine;
            }
        }
        if (!names.empty()) {
            prepareNamedColumns(names, namesLine, tokens);
            return;
        }
        m_radiiOnly = found != arms + 4 && m_options.allowRadiiOnly && found >= kMinRadiiOnlyColumns && found <= kMaxArms;
        if (m_radiiOnly) {
            arms = found;
            m_info.diagnostics.warn(m_name, line,
                                    std::to_string(found) +
                                        " numbers per line and no depth column: read as " +
                                        std::to_string(found) + " radii per row, depth = row x " +
                                        std::to_string(m_options.rowStep_m) + " m");
        }
        LengthUnit radiusUnit = m_options.radiusUnit.value_or(LengthUnit::Inch);
        if (!m_options.radiusUnit && !tokens.empty()) {
            std::vector<double> radii;
            for (int k = 0; k < arms; ++k) {
                const std::size_t at = static_cast<std::size_t>(m_radiiOnly ? k : k + 1);
                double v = 0.0;
                if (at < tokens.size() && parseNumber(tokens[at], v)) radii.push_back(v);
            }
            radiusUnit = unitlessRadiusUnit(std::move(radii), line);
        }
        const LengthUnit depthUnit = m_options.depthUnit.value_or(LengthUnit::Metre);
        const std::string radiusUnitName(unitName(radiusUnit));
        m_columns.push_back(
            {m_radiiOnly ? "ROW" : "DEPTH", std::string(unitName(depthUnit)), "", false, 0});
        for (int k = 1; k <= arms; ++k)
            m_columns.push_back({"R" + std::to_string(k), radiusUnitName, "", false, 0});
        if (!m_radiiOnly)
            for (const char* angle : {"P1AZ", "DEVI", "HAZI"})
                m_columns.push_back({angle, "deg", "", false, 0});
        ReadOptions plain = m_options;
        plain.roles = {};
        plain.radiusUnit = radiusUnit;
        plain.depthUnit = depthUnit;
        RoleOverrides overrides;
        m_plan = makeCurvePlan(m_columns, nullptr, plain, m_name, m_info, m_info.diagnostics);
        if (m_radiiOnly) {
            m_info.curves.front().role =
                "depth (row x " + std::to_string(m_options.rowStep_m) + " m)";
            m_info.format = "column text (" + std::to_string(arms) + " radii per line, no depth)";
        } else {
            m_info.format = "column text (depth R1..R" + std::to_string(arms) + " P1AZ DEVI HAZI)";
        }
        m_info.depthUnit = std::string(unitName(depthUnit));
        m_info.armSource = "radii R1..R" + std::to_string(arms) + " (" + radiusUnitName + ")";
        m_format.file = m_name;
        m_format.las = false;
        m_format.declared = m_columns.size();
        m_format.tokens = m_radiiOnly ? static_cast<std::size_t>(arms) : m_columns.size();
        m_format.firstColumn = m_radiiOnly ? 1 : 0;
        m_format.textColumn.assign(m_columns.size(), 0);
        for (const ColumnSpec& c : m_columns)
            m_format.names.push_back(c.mnemonic == "DEPTH" ? "depth" : c.mnemonic);
        m_format.layout = m_radiiOnly ? std::to_string(arms) + " radii"
                                      : std::to_string(arms + 4) + " columns (depth R1..R" +
                                            std::to_string(arms) + " P1AZ DEVI HAZI)";
        m_format.depthColumn = 0;
        m_format.plan = &m_plan;
    }

    void dataLoop(std::string_view run, std::size_t) {
        m_current = m_plan.emptyTable(m_columns);
        m_held = m_plan.emptyTable(m_columns);
        m_nulls.assign(m_columns.size(), 0);
        m_depthDiffer.assign(m_plan.otherDepthColumns.size(), 0);
        m_parts.resize(m_stream.threads > 1 ? kMaxPieces : 1);
        for (ParsedRows& part : m_parts) part.table = m_plan.emptyTable(m_columns);
        // Joined when the data loop ends, however it ends, while the block it reads still exists.
        PieceSharing sharing(m_stream.threads > 1);
        m_sharing = &sharing;
        if (m_skipFirstLines) {
            // Skip the names line(s) of column text.
            for (std::size_t i = 0; i < m_skipFirstLines; ++i) {
                const std::size_t nl = run.find('\n');
                run = nl == std::string_view::npos ? std::string_view() : run.substr(nl + 1);
                ++m_lineNumber;
            }
        }
        if (m_settleLasColumns) settleLasColumns(run);
        for (;;) {
            if (cancelled()) return;
            const bool finalRun = m_reader->done();
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
        if (m_stream.threads > 1 && run.size() >= minSplit) {
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
            parseRows(m_format, text, 1, finalRun && i + 1 == pieces, m_columns, m_parts[i]);
        };
        m_sharing->run(pieces, parsePiece);
        for (std::size_t i = 0; i < pieces; ++i) {
            ParsedRows& part = m_parts[i];
            const std::size_t before = m_lineNumber;
            if (part.error) rethrowAfter(part.error, before);
            for (std::size_t& line : part.lines) line += before;
            for (Warning& w : part.diagnostics.warnings) w.line += before;
            commit(part);
            m_lineNumber += part.linesConsumed;
            if (part.stopped) {
                stop = m_pieceBegin[i] + part.stopOffset;
                break;
            }
        }
        deliverReady();
    }

    // A piece's error, with its line moved from the piece to the file.
    static void rethrowAfter(const std::exception_ptr& error, std::size_t linesBefore) {
        try {
            std::rethrow_exception(error);
        } catch (const ParseError& e) {
            if (e.line() == 0) throw;
            throw ParseError(e.file(), e.line() + linesBefore, e.column(), e.message());
        }
    }

    void commit(ParsedRows& part) {
        for (std::size_t c = 0; c < m_nulls.size(); ++c) m_nulls[c] += part.nulls[c];
        for (std::size_t k = 0; k < m_depthDiffer.size(); ++k)
            m_depthDiffer[k] += part.depthDiffer[k];
        m_info.diagnostics.merge(part.diagnostics);

        SectionTable& t = part.table;
        const std::size_t n = t.rowCount();
        if (m_radiiOnly)
            for (std::size_t r = 0; r < n; ++r)
                t.depth_m[r] = static_cast<double>(m_rowIndex++) * m_options.rowStep_m;
        if (!m_directionKnown) decideDirection(t);
        std::size_t runStart = 0;
        m_kept.clear();
        auto flush = [&](std::size_t end) {
            if (end > runStart) m_kept.emplace_back(runStart, end);
            runStart = end + 1;
        };
        for (std::size_t r = 0; r < n; ++r) {
            const double d = t.depth_m[r];
            if (!std::isfinite(d)) {
                if (!m_nullDepths++) m_firstNullDepthLine = part.lines[r];
                flush(r);
                continue;
            }
            if (m_haveLast && !m_descending) {
                if (d == m_last) {
                    if (!m_repeated++) m_firstRepeatedLine = part.lines[r];
                    flush(r);
                    continue;
                }
                if (d < m_last) {
                    if (!m_directionKnown) {
                        // Recorded upwards: hold everything, sort at the end.
                        m_descending = true;
                        m_directionKnown = true;
                        appendRows(m_current, m_held, 0, m_current.rowCount());
                        clearRows(m_current);
                    } else if (m_options.depthOrder == DepthOrder::Reject) {
                        throw ParseError(m_name, part.lines[r], 0,
                                         "expected depth increasing past " +
                                             std::to_string(m_last / m_plan.depthScale) +
                                             ", found " + std::to_string(d / m_plan.depthScale));
                    } else {
                        if (!m_backwards++) m_firstBackwardsLine = part.lines[r];
                        flush(r);
                        continue;
                    }
                } else {
                    m_directionKnown = true;
                }
            }
            m_haveLast = true;
            m_last = d;
        }
        flush(n);
        // The common case, a whole block in order: hand it on without a copy.
        if (m_directionKnown && !m_descending && m_current.rowCount() == 0 && m_kept.size() == 1 &&
            m_kept.front().first == 0 && m_kept.front().second == n && n >= m_stream.chunkRows) {
            deliver(t);
            return;
        }
        for (const auto& [a, b] : m_kept) appendRows(t, m_descending ? m_held : m_current, a, b);
    }

    // The trend over the rows read so far decides the direction, not the first
    // pair of rows: a log recorded upwards that starts with one row out of order
    // is sorted whole, not cut down to the rows after that pair. (A thread's
    // share of a block holds thousands of rows, so the trend is clear.)
    void decideDirection(const SectionTable& t) {
        const std::size_t n = t.rowCount();
        std::size_t first = 0;
        while (!m_haveFirst && first < n) {
            if (std::isfinite(t.depth_m[first])) {
                m_first = t.depth_m[first];
                m_haveFirst = true;
            }
            ++first;
        }
        std::size_t last = n;
        while (last > 0 && !std::isfinite(t.depth_m[last - 1])) --last;
        if (!m_haveFirst || last == 0 || t.depth_m[last - 1] == m_first) return;
        m_directionKnown = true;
        m_descending = t.depth_m[last - 1] < m_first;
        if (m_descending) {
            appendRows(m_current, m_held, 0, m_current.rowCount());
            clearRows(m_current);
        }
    }

    void deliver(const SectionTable& chunk) {
        if (chunk.rowCount() == 0) return;
        const std::size_t before = m_info.rows;
        m_info.rows += chunk.rowCount();
        if (before == 0) m_info.top_m = chunk.depth_m.front();
        m_info.bottom_m = chunk.depth_m.back();
        for (double b : chunk.bitSize_mm)
            if (std::isfinite(b)) {
                m_bitSizeMin = std::min(m_bitSizeMin, b);
                m_bitSizeMax = std::max(m_bitSizeMax, b);
            }
        for (std::size_t r = 1; r < chunk.rowCount() && m_steps.size() < kStepSamples; ++r)
            m_steps.push_back(chunk.depth_m[r] - chunk.depth_m[r - 1]);
        m_consumer(chunk);
    }

    void deliverReady() {
        if (m_descending || !m_directionKnown || m_current.rowCount() < m_stream.chunkRows) return;
        deliver(m_current);
        clearRows(m_current);
    }

    void readTrailingSections(std::string_view rest) {
        std::string tail(rest);
        while (!m_reader->done()) tail += m_reader->next();
        std::size_t pos = 0, line = m_lineNumber;
        while (pos < tail.size()) {
            const std::size_t nl = tail.find('\n', pos);
            const std::size_t end = nl == std::string::npos ? tail.size() : nl;
            const std::string_view l = trim(std::string_view(tail).substr(pos, end - pos));
            pos = end + 1;
            ++line;
            if (!l.empty() && l.front() == '~')
                m_info.diagnostics.warn(m_name, line,
                                        "section '" + std::string(l.substr(0, 40)) +
                                            "' after the data is not read; skipped");
        }
    }

    // Wrapped LAS (legacy, small): read whole by the in-memory reader, then
    // map each depth's values through the same plan and ordering.
    LogInfo finishWrapped(std::string_view rest) {
        std::string all = m_headerText;
        all.append(rest);
        while (!m_reader->done()) all.append(m_reader->next());
        Diagnostics lasDiagnostics;
        LasReadOptions lasOptions;
        lasOptions.nullPolicy = m_options.nullPolicy;
        const LasLog las = readLas(all, m_name, lasOptions, &lasDiagnostics);
        // The header's warnings were given once already.
        for (const Warning& w : lasDiagnostics.warnings)
            if (w.line > m_lineNumber || w.line == 0)
                m_info.diagnostics.warn(w.file, w.line, w.message);
        m_plan = makeCurvePlan(m_columns, &m_header, m_options, m_name, m_info, m_info.diagnostics);
        m_format.las = true;
        m_current = m_plan.emptyTable(m_columns);
        m_held = m_plan.emptyTable(m_columns);
        m_nulls.assign(m_columns.size(), 0);
        m_depthDiffer.assign(m_plan.otherDepthColumns.size(), 0);
        ParsedRows part;
        part.table = m_plan.emptyTable(m_columns);
        part.nulls.assign(m_columns.size(), 0);
        part.depthDiffer.assign(m_plan.otherDepthColumns.size(), 0);
        std::vector<double> raw(m_columns.size());
        for (std::size_t r = 0; r < las.rowCount(); ++r) {
            for (std::size_t c = 0; c < raw.size(); ++c) raw[c] = las.curves[c].values[r];
            m_plan.checkAngles(raw.data(), m_name, las.rowLines[r]);
            m_plan.mapRow(raw.data(), part.table);
            part.lines.push_back(las.rowLines[r]);
        }
        for (std::size_t c = 0; c < raw.size(); ++c) part.nulls[c] = las.curves[c].nulls;
        if (m_stream.onStart) m_stream.onStart(m_info, las.rowCount());
        commit(part);
        deliverReady();
        return finish();
    }

    LogInfo finish() {
        if (!m_info.cancelled) {
            if (m_descending) {
                std::vector<std::size_t> order(m_held.rowCount());
                for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
                std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
                    return m_held.depth_m[a] < m_held.depth_m[b];
                });
                std::size_t outOfOrder = 0;
                for (std::size_t i = 1; i < m_held.rowCount(); ++i)
                    outOfOrder += m_held.depth_m[i] > m_held.depth_m[i - 1];
                std::vector<std::size_t> kept;
                kept.reserve(order.size());
                for (std::size_t r : order) {
                    if (!kept.empty() && m_held.depth_m[r] == m_held.depth_m[kept.back()]) {
                        ++m_repeated;
                        continue;
                    }
                    kept.push_back(r);
                }
                permute(m_held, kept);
                m_info.diagnostics.warn(
                    m_name, 0,
                    outOfOrder == 0 ? "log recorded upwards; rows sorted by increasing depth"
                                    : "log recorded upwards with " + std::to_string(outOfOrder) +
                                          " rows out of order; rows sorted by increasing depth");
                SectionTable chunk = m_plan.emptyTable(m_columns);
                for (std::size_t a = 0; a < m_held.rowCount(); a += m_stream.chunkRows) {
                    if (cancelled()) break;
                    clearRows(chunk);
                    appendRows(m_held, chunk, a,
                               std::min(m_held.rowCount(), a + m_stream.chunkRows));
                    deliver(chunk);
                }
            } else {
                deliver(m_current);
            }
        }
        Diagnostics& d = m_info.diagnostics;
        if (m_nullDepths)
            d.warn(m_name, m_firstNullDepthLine,
                   std::to_string(m_nullDepths) + " rows without a depth skipped");
        if (m_repeated)
            d.warn(
                m_name, m_firstRepeatedLine,
                std::to_string(m_repeated) + " rows repeat the depth of the row before; skipped");
        if (m_backwards)
            d.warn(m_name, m_firstBackwardsLine,
                   std::to_string(m_backwards) +
                       " rows go back up the hole in a log recorded downwards; skipped");
        for (std::size_t k = 0; k < m_depthDiffer.size(); ++k) {
            if (!m_depthDiffer[k]) continue;
            const ColumnSpec& c = m_columns[static_cast<std::size_t>(m_plan.otherDepthColumns[k])];
            d.warn(m_name, c.line,
                   "depth curve " + c.mnemonic + " differs from the index " +
                       m_columns[static_cast<std::size_t>(m_plan.depthColumn)].mnemonic + " on " +
                       std::to_string(m_depthDiffer[k]) +
                       " rows by 1 cm or more; the index is used");
        }
        for (std::size_t c = 0; c < m_info.curves.size() && c < m_nulls.size(); ++c)
            m_info.curves[c].nulls = m_nulls[c];
        if (m_radiiOnly && !m_info.curves.empty()) m_info.curves.front().nulls = 0;
        m_info.arms = m_plan.armCount;
        if (m_bitSizeMin <= m_bitSizeMax) {
            m_info.bitSize_mm = m_bitSizeMin;
            m_info.bitSizeMax_mm = m_bitSizeMax;
        }
        if (!m_steps.empty()) {
            m_info.step_m = medianInPlace(m_steps);
        }
        if (m_info.rows == 0 && !m_info.cancelled) {
            if (m_format.las)
                throw ParseError(m_name, m_lineNumber, 0,
                                 "expected data rows after ~A, found none");
            throw ParseError(m_name, 0, 0,
                             "expected rows of numbers (" + m_format.layout + "), found none");
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

    LasHeader m_header;
    std::string m_headerText;
    bool m_wrapped = false;
    bool m_settleLasColumns = false;
    bool m_radiiOnly = false;
    std::size_t m_skipFirstLines = 0;
    std::size_t m_rowIndex = 0;
    std::vector<ColumnSpec> m_columns;
    CurvePlan m_plan;
    RowFormat m_format;

    SectionTable m_current, m_held;
    std::vector<ParsedRows> m_parts;  // one per piece of a block
    std::vector<std::size_t> m_pieceBegin;
    PieceSharing* m_sharing = nullptr;  // set while dataLoop runs
    std::vector<std::pair<std::size_t, std::size_t>> m_kept;
    std::vector<std::size_t> m_nulls, m_depthDiffer;
    std::vector<double> m_steps;
    bool m_haveLast = false, m_directionKnown = false, m_descending = false, m_haveFirst = false;
    double m_last = 0.0, m_first = 0.0;
    double m_bitSizeMin = 1e300, m_bitSizeMax = -1e300;
    std::size_t m_nullDepths = 0, m_repeated = 0, m_backwards = 0;
    std::size_t m_firstNullDepthLine = 0, m_firstRepeatedLine = 0, m_firstBackwardsLine = 0;
};

}  // namespace

LogInfo streamCaliperLog(const std::string& path, const ReadOptions& options,
                         const ChunkConsumer& consumer, const StreamOptions& stream) {
    FileSource source(path);
    return LogStreamer(path, options, consumer, stream).run(source);
}

LogInfo streamCaliperText(std::string_view text, const std::string& name,
                          const ReadOptions& options, const ChunkConsumer& consumer,
                          const StreamOptions& stream) {
    MemorySource source(text);
    return LogStreamer(name, options, consumer, stream).run(source);
}

}  // namespace caliper3d::io
