#include "io/stream/row_parser.h"

#include <fast_float/fast_float.h>

#include <cmath>
#include <cstring>

#include "io/las_reader.h"
#include "io/number_parsing.h"
#include "io/parse_error.h"
#include "io/section_table.h"
#include "io/text.h"

namespace caliper3d::io {

namespace {

bool restIsBlank(std::string_view text, std::size_t from) {
    for (std::size_t i = from; i < text.size(); ++i)
        if (!isBlank(text[i]) && text[i] != '\n') return false;
    return true;
}

const char* skipBlanks(const char* p, const char* end) {
    while (p < end && isBlank(*p)) ++p;
    return p;
}

// Blanks around a value when `separator` (',' or '\t') parts the values.
const char* skipPadding(const char* p, const char* end, char separator) {
    while (p < end && isBlank(*p) && *p != separator) ++p;
    return p;
}

// Reads the values of one line. Hand-written rather than a general tokenizer:
// this is the hot loop of every read (fast_float on the line in place, no
// token copies), and it must give the column of a bad field.
class LineScanner {
public:
    LineScanner(const RowFormat& format, double* raw, std::vector<BadValues>& bad)
        : f(format), m_raw(raw), m_bad(bad) {}

    struct Result {
        std::size_t next = 0;        // index of the value after the last one read
        bool overflow = false;       // an overflowed field ("****") ran into the next ones
        const char* rest = nullptr;  // first non-blank after the values read
    };

    // Reads values t, t+1, ... up to f.tokens from [p, lineEnd).
    Result scan(const char* lineBegin, const char* p, const char* lineEnd, std::size_t t,
                std::size_t lineNumber) {
        m_lineBegin = lineBegin;
        m_lineNumber = lineNumber;
        // DLM TAB: only a line that holds a tab is read tab by tab.
        m_separator = f.delimiter == ',' ? ','
                      : f.delimiter == '\t' &&
                              std::memchr(lineBegin, '\t',
                                          static_cast<std::size_t>(lineEnd - lineBegin)) != nullptr
                          ? '\t'
                          : ' ';
        const bool separated = m_separator != ' ';
        Result r;
        const std::size_t first = t;
        for (; t < f.tokens; ++t) {
            if (t > first && separated) {
                p = skipPadding(p, lineEnd, m_separator);
                if (p < lineEnd && *p == m_separator)
                    ++p;
                else
                    break;
            }
            p = separated ? skipPadding(p, lineEnd, m_separator) : skipBlanks(p, lineEnd);
            if (p == lineEnd && !separated) break;
            const std::size_t c = f.firstColumn + t;
            m_raw[c] = value(c, p, lineEnd, r.overflow);
        }
        r.next = t;
        r.rest = skipBlanks(p, lineEnd);
        return r;
    }

    std::size_t column(const char* at) const {
        return static_cast<std::size_t>(at - m_lineBegin) + 1;
    }

    // For a line's error: the value of a lenient curve on that line that was not a number
    // (two values run together, text with blanks), else empty.
    std::string badValueNote(std::size_t lineNumber) const {
        return m_lastBadLine == lineNumber ? " (" + m_lastBad + ")" : std::string();
    }

private:
    // The value of raw column c at p (advanced past it): a number, or NaN for
    // text, a null token or the header's null value.
    double value(std::size_t c, const char*& p, const char* lineEnd, bool& overflow) {
        const bool separated = m_separator != ' ';
        double v = 0.0;
        auto [end, ec] = fast_float::from_chars(p, lineEnd, v);
        const bool clean = ec == std::errc() &&
                           (end == lineEnd || isBlank(*end) || (separated && *end == m_separator));
        if (clean && !f.textColumn[c]) {
            p = end;
        } else {
            const std::string_view token = tokenAt(c, p, lineEnd);
            if (f.textColumn[c]) {
                v = kNaN;
            } else if (parseNumber(token, v)) {
            } else if (f.las && c != static_cast<std::size_t>(f.depthColumn) &&
                       isNullToken(token, f.nullPolicy)) {
                v = kNaN;
                overflow = !token.empty() && token.find_first_not_of('*') == std::string_view::npos;
            } else if (!f.lenient.empty() && f.lenient[c]) {
                // A curve the reader does not need: this value is unknown, the row is kept.
                BadValues& bad = m_bad[c];
                if (bad.count++ == 0) {
                    bad.firstLine = m_lineNumber;
                    bad.first = std::string(trim(token.substr(0, 40)));
                }
                m_lastBadLine = m_lineNumber;
                m_lastBad = "curve " + f.names[c] + "'s '" +
                            std::string(trim(token.substr(0, 40))) + "' is not a number";
                v = kNaN;
            } else {
                throw ParseError(f.file, m_lineNumber, column(token.data()),
                                 "expected a number for " + (f.las ? "curve " : std::string()) +
                                     f.names[c] + ", found '" + std::string(token.substr(0, 40)) +
                                     "'");
            }
        }
        if (!std::isfinite(v)) return kNaN;
        if (f.las && c != static_cast<std::size_t>(f.depthColumn) &&
            ((f.hasNull && v == f.null) ||
             (f.nullPolicy == NullPolicy::Common && isCommonNullNumber(v))))
            return kNaN;
        return v;
    }

    // The field at p (advanced past it) when it is not a clean number.
    std::string_view tokenAt(std::size_t c, const char*& p, const char* lineEnd) const {
        const bool separated = m_separator != ' ';
        const char* begin = p;
        const char* end = p;
        const bool lenient = !f.lenient.empty() && f.lenient[c];
        // LAS 3.0 quotes a string that holds the delimiter: "SAND, SHALY"; in a curve the
        // log is not read for, 'single quotes' too (lasio's quoted substrings).
        const char quote = p < lineEnd && (*p == '"' || (lenient && *p == '\'')) ? *p : '\0';
        if ((f.textColumn[c] || lenient) && quote != '\0') {
            const void* close =
                std::memchr(p + 1, quote, static_cast<std::size_t>(lineEnd - p - 1));
            if (!close)
                throw ParseError(f.file, m_lineNumber, column(p),
                                 std::string("expected a closing '") + quote +
                                     "' for the text of curve " + f.names[c] +
                                     ", found the end of the line");
            end = static_cast<const char*>(close) + 1;
        } else {
            while (end < lineEnd && !isBlank(*end) && !(separated && *end == m_separator)) ++end;
            // Text may hold blanks where a separator parts the values ("DOLOMITE WI/VUGS").
            if (separated && (f.textColumn[c] || m_separator == '\t'))
                while (end < lineEnd && *end != m_separator) ++end;
        }
        p = end;
        return {begin, static_cast<std::size_t>(end - begin)};
    }

    const RowFormat& f;
    double* m_raw;
    std::vector<BadValues>& m_bad;
    std::size_t m_lastBadLine = 0;  // the line of the last lenient value that was not a number
    std::string m_lastBad;
    char m_separator = ' ';  // of the line being read
    const char* m_lineBegin = nullptr;
    std::size_t m_lineNumber = 0;
};

// The parse of one run: walks its lines and hands each complete row on.
class RunParser {
public:
    RunParser(const RowFormat& format, std::string_view text, bool finalRun, RowSink& sink,
              RowRun& out)
        : f(format),
          m_text(text),
          m_finalRun(finalRun),
          m_sink(sink),
          m_out(out),
          m_raw(format.declared, kNaN),
          m_scanner(format, m_raw.data(), out.bad) {}

    void run(std::size_t firstLine) {
        const char* const base = m_text.data();
        std::size_t pos = 0, lineNumber = firstLine - 1;
        while (pos < m_text.size()) {
            const char* lineBegin = base + pos;
            const void* nl = std::memchr(lineBegin, '\n', m_text.size() - pos);
            const char* lineEnd = nl ? static_cast<const char*>(nl) : base + m_text.size();
            const std::size_t lineStart = pos;
            pos = static_cast<std::size_t>(lineEnd - base) + 1;
            ++lineNumber;
            ++m_out.linesConsumed;
            const char* p = skipBlanks(lineBegin, lineEnd);
            if (p == lineEnd || *p == '#') continue;
            if (*p == '~' && f.las) {
                m_out.stopped = true;
                m_out.stopOffset = lineStart;
                --m_out.linesConsumed;
                break;
            }
            if (f.wrapped)
                wrappedLine(lineBegin, p, lineEnd, lineNumber);
            else
                line(lineBegin, p, lineEnd, lineNumber, pos);
        }
        if (f.wrapped && m_wrappedValues > 0)
            m_out.diagnostics.warn(f.file, m_wrappedLine,
                                   "last depth holds " + std::to_string(m_wrappedValues) + " of " +
                                       std::to_string(f.tokens) +
                                       " wrapped values (truncated file?); skipped");
    }

private:
    void line(const char* lineBegin, const char* p, const char* lineEnd, std::size_t lineNumber,
              std::size_t next) {
        const LineScanner::Result r = m_scanner.scan(lineBegin, p, lineEnd, 0, lineNumber);
        if (r.next == f.tokens && r.rest < lineEnd)
            throw ParseError(f.file, lineNumber, m_scanner.column(r.rest),
                             "expected " + f.layout + ", found more values" +
                                 m_scanner.badValueNote(lineNumber));
        if (r.next < f.tokens) {
            if (r.overflow) {
                // An overflowed field ran into the next ones: they are unknown, not lost.
                m_out.diagnostics.warn(f.file, lineNumber,
                                       "field overflow covers the last " +
                                           std::to_string(f.tokens - r.next + 1) +
                                           " values; read as null");
                for (std::size_t t = r.next; t < f.tokens; ++t) m_raw[f.firstColumn + t] = kNaN;
            } else if (m_finalRun && restIsBlank(m_text, next)) {
                m_out.diagnostics.warn(f.file, lineNumber,
                                       "last line holds " + std::to_string(r.next) + " of " +
                                           std::to_string(f.tokens) +
                                           " values (truncated file?); skipped");
                return;
            } else {
                throw ParseError(f.file, lineNumber, 0,
                                 "expected " + f.layout + ", found " + std::to_string(r.next) +
                                     " values" + m_scanner.badValueNote(lineNumber));
            }
        }
        emit(lineNumber);
    }

    // Wrapped LAS: the values of one depth gather over lines until all are read.
    void wrappedLine(const char* lineBegin, const char* p, const char* lineEnd,
                     std::size_t lineNumber) {
        if (m_wrappedValues == 0) m_wrappedLine = lineNumber;
        const LineScanner::Result r =
            m_scanner.scan(lineBegin, p, lineEnd, m_wrappedValues, lineNumber);
        if (r.rest < lineEnd)
            throw ParseError(f.file, lineNumber, m_scanner.column(r.rest),
                             "expected " + std::to_string(f.tokens) +
                                 " values per depth in wrapped data, found more");
        m_wrappedValues = r.next;
        if (m_wrappedValues < f.tokens) return;
        m_wrappedValues = 0;
        emit(m_wrappedLine);
    }

    void emit(std::size_t lineNumber) {
        for (std::size_t c = 0; c < f.declared; ++c) m_out.nulls[c] += std::isnan(m_raw[c]);
        m_sink.row(m_raw.data(), lineNumber);
    }

    const RowFormat& f;
    std::string_view m_text;
    bool m_finalRun;
    RowSink& m_sink;
    RowRun& m_out;
    std::vector<double> m_raw;
    LineScanner m_scanner;
    std::size_t m_wrappedValues = 0, m_wrappedLine = 0;
};

}  // namespace

void BadValues::add(const BadValues& other, std::size_t linesBefore) {
    if (other.count == 0) return;
    if (count == 0) {
        firstLine = other.firstLine + linesBefore;
        first = other.first;
    }
    count += other.count;
}

void warnBadValues(const RowFormat& format, const std::vector<BadValues>& bad,
                   Diagnostics& diagnostics) {
    for (std::size_t c = 0; c < bad.size() && c < format.names.size(); ++c) {
        const BadValues& b = bad[c];
        if (b.count == 0) continue;
        diagnostics.warn(format.file, b.firstLine,
                         "curve " + format.names[c] + ": " + std::to_string(b.count) +
                             (b.count == 1 ? " value is" : " values are") +
                             " not a number (the first '" + b.first + "'); read as null");
    }
}

void parseRows(const RowFormat& format, std::string_view text, std::size_t firstLine, bool finalRun,
               RowSink& sink, RowRun& out) {
    out.diagnostics = Diagnostics{};
    out.linesConsumed = 0;
    out.stopped = false;
    out.stopOffset = 0;
    out.error = nullptr;
    out.nulls.assign(format.declared, 0);
    out.bad.assign(format.declared, BadValues{});
    try {
        RunParser(format, text, finalRun, sink, out).run(firstLine);
    } catch (...) {
        out.error = std::current_exception();
    }
}

}  // namespace caliper3d::io
