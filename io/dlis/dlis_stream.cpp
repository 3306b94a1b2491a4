#include "io/dlis/dlis_stream.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>
#include <sstream>

#include "io/azimuth_north.h"
#include "io/curve_plan.h"
#include "io/dlis/dlis_reader.h"
#include "io/las_header.h"
#include "io/las_reader.h"
#include "io/layout/las_layout.h"
#include "io/parse_error.h"
#include "io/stream/depth_order.h"
#include "io/stream/row_tally.h"
#include "io/well_location.h"

namespace caliper3d::io {

namespace {

using dlis::Channel;
using dlis::DlisIndex;
using dlis::Frame;
using dlis::LogicalFile;

// "0.1 in" -> 0.1 and "in"; "m" -> 1 and "m". DLIS writes a unit with a scale before it.
std::pair<double, std::string> scaledUnit(const std::string& units) {
    const char* begin = units.c_str();
    char* end = nullptr;
    const double scale = std::strtod(begin, &end);
    if (end != begin && end && *end == ' ' && std::isfinite(scale) && scale > 0.0) {
        std::string rest(end);
        rest.erase(0, rest.find_first_not_of(' '));
        if (!rest.empty()) return {scale, rest};
    }
    return {1.0, units};
}

// The columns one frame offers: a channel each, a one-dimensional array an element each.
struct FrameColumns {
    std::vector<LasItem> items;          // as ~C items, for the plan
    std::vector<std::size_t> channelOf;  // per column: position in Frame::channels
    std::vector<std::size_t> elementOf;  // per column: element of that channel
    std::vector<double> scale;           // per column: the unit's scale
    std::vector<std::string> notRead;    // arrays of more dimensions, listed only
};

FrameColumns frameColumns(const LogicalFile& file, const Frame& frame) {
    FrameColumns out;
    for (std::size_t k = 0; k < frame.channels.size(); ++k) {
        const Channel& ch = file.channels[frame.channels[k]];
        const auto [scale, unit] = scaledUnit(ch.units);
        const std::size_t n = ch.elements();
        const bool oneDimension = ch.dimension.size() == 1 && n >= 1 && n <= kMaxArms;
        const bool number = dlis::repCodeSize(ch.repCode) > 0 || ch.repCode == dlis::kUVARI ||
                            ch.repCode == dlis::kORIGIN;
        if (!oneDimension || !number) {
            out.notRead.push_back(ch.name.id);
            continue;
        }
        for (std::size_t e = 0; e < n; ++e) {
            const std::string mnemonic =
                n == 1 ? ch.name.id : ch.name.id + "[" + std::to_string(e + 1) + "]";
            out.items.push_back({mnemonic, unit, "", ch.longName, 0});
            out.channelOf.push_back(k);
            out.elementOf.push_back(e);
            out.scale.push_back(scale);
        }
    }
    return out;
}

std::string joined(const std::vector<dlis::Value>& values) {
    dlis::Attribute a;
    a.values = values;
    std::string text;
    for (std::size_t i = 0; i < values.size(); ++i) text += (i ? ", " : "") + a.text(i);
    return text;
}

// The header a LAS file would carry: the origin as ~Well items, the parameters as ~P.
LasHeader headerOf(const LogicalFile& file, const std::string& name,
                   const std::vector<LasItem>& curves, Diagnostics* diagnostics) {
    LasHeader h;
    h.file = name;
    h.curves = curves;
    auto well = [&](const char* mnemonic, const std::string& value) {
        if (!value.empty()) h.well.push_back({mnemonic, "", value, "", 0});
    };
    well("WELL", file.wellName);
    well("UWI", file.wellId);
    well("FLD", file.fieldName);
    well("COMP", file.company);
    well("SRVC", file.producer);
    well("DATE", file.creationTime);
    for (const dlis::Parameter& p : file.parameters) {
        const auto [scale, unit] = scaledUnit(p.units);
        LasItem item{p.name.id, unit, "", p.longName, 0};
        if (p.values.size() == 1) {
            dlis::Attribute a;
            a.values = p.values;
            const double v = a.number();
            if (std::isfinite(v) && scale != 1.0) {
                std::ostringstream text;
                text.precision(10);
                text << v * scale;
                item.value = text.str();
            } else {
                item.value = a.text();
            }
        } else if (p.values.size() > 1 && diagnostics &&
                   (p.name.id == "BS" || p.name.id.rfind("CS", 0) == 0 || p.name.id == "MDEC")) {
            diagnostics->warn(name, 0,
                              "parameter " + p.name.id + " holds " +
                                  std::to_string(p.values.size()) + " values (" + joined(p.values) +
                                  "); not used as one value");
        }
        h.parameters.push_back(std::move(item));
    }
    return h;
}

std::string dimensionText(const Channel& ch) {
    std::string text;
    for (std::size_t i = 0; i < ch.dimension.size(); ++i)
        text += (i ? "x" : "") + std::to_string(ch.dimension[i]);
    return text;
}

// What `info` prints about the file beyond the curves read.
std::vector<std::string> describeIndex(const DlisIndex& index, std::size_t chosenFile,
                                       std::size_t chosenFrame) {
    std::vector<std::string> lines;
    std::string label = "DLIS " + index.version + " " + index.structure;
    if (!index.storageSetId.empty()) label += ", storage set '" + index.storageSetId + "'";
    if (index.sulOffset) label += ", label after " + std::to_string(index.sulOffset) + " bytes";
    if (!index.hasSul) label = "DLIS, no storage unit label";
    if (index.tapeImage) label += ", tape image";
    lines.push_back(label);
    for (std::size_t i = 0; i < index.files.size(); ++i) {
        const LogicalFile& f = index.files[i];
        std::string head = "logical file " + std::to_string(i + 1) +
                           (i == chosenFile ? " (read)" : "") + ": '" + f.id + "'";
        if (!f.wellName.empty()) head += ", well '" + f.wellName + "'";
        if (!f.fieldName.empty()) head += ", field '" + f.fieldName + "'";
        if (!f.company.empty()) head += ", company '" + f.company + "'";
        if (!f.producer.empty()) head += ", by " + f.producer;
        if (!f.product.empty()) head += " " + f.product;
        if (!f.creationTime.empty()) head += ", created " + f.creationTime;
        lines.push_back(head);
        for (std::size_t j = 0; j < f.frames.size(); ++j) {
            const Frame& fr = f.frames[j];
            std::string line = "  frame " + fr.name.id +
                               (i == chosenFile && j == chosenFrame ? " (read)" : "") + ": " +
                               std::to_string(fr.records) + " frame records, " +
                               std::to_string(fr.channels.size()) + " channels";
            if (!fr.indexType.empty()) line += ", index " + fr.indexType;
            if (!fr.direction.empty()) line += " " + fr.direction;
            lines.push_back(line);
            if (i != chosenFile) continue;
            for (std::size_t k : fr.channels) {
                const Channel& ch = f.channels[k];
                lines.push_back("    " + ch.name.id + "  " + (ch.units.empty() ? "-" : ch.units) +
                                "  " + dlis::repCodeName(ch.repCode) + "  " + dimensionText(ch) +
                                (ch.longName.empty() ? "" : "  " + ch.longName));
            }
        }
        if (i != chosenFile) continue;
        for (const dlis::Parameter& p : f.parameters)
            lines.push_back("  parameter " + p.name.id + " = " +
                            (p.values.empty() ? std::string("(no value)") : joined(p.values)) +
                            (p.units.empty() ? "" : " " + p.units) +
                            (p.longName.empty() ? "" : "  (" + p.longName + ")"));
        if (f.encryptedRecords)
            lines.push_back("  " + std::to_string(f.encryptedRecords) +
                            " encrypted records (not read)");
    }
    return lines;
}

// The plan of one frame; nullopt when it names no caliper curve or cannot be read.
struct FrameChoice {
    std::size_t file = 0, frame = 0;
    FrameColumns columns;
    LasHeader header;
};

std::optional<FrameChoice> bestFrame(const DlisIndex& index, std::size_t file,
                                     const std::string& name, const ReadOptions& options) {
    std::optional<FrameChoice> best;
    int bestArms = 0;
    const LogicalFile& f = index.files[file];
    for (std::size_t j = 0; j < f.frames.size(); ++j) {
        if (f.frames[j].channels.empty()) continue;
        FrameChoice c{file, j, frameColumns(f, f.frames[j]), {}};
        if (c.columns.items.empty()) continue;
        c.header = headerOf(f, name, c.columns.items, nullptr);
        LogInfo scratch;
        int arms = 0;
        try {
            arms = lasLayout(c.header, name, options, scratch).plan.armCount;
        } catch (const std::exception&) {
            arms = 0;
        }
        if (!best || arms > bestArms ||
            (arms == bestArms && f.frames[j].records > f.frames[best->frame].records)) {
            bestArms = arms;
            best = std::move(c);
        }
    }
    return best;
}

class DlisStreamer {
public:
    DlisStreamer(std::string_view bytes, std::string name, const ReadOptions& options,
                 const ChunkConsumer& consumer, const StreamOptions& stream,
                 const std::function<void(std::size_t)>& release)
        : m_bytes(bytes),
          m_name(std::move(name)),
          m_options(options),
          m_consumer(consumer),
          m_stream(stream),
          m_release(release) {
        m_info.file = m_name;
    }

    LogInfo run() {
        const DlisIndex index = dlis::indexDlis(m_bytes, m_name, &m_info.diagnostics);
        if (m_release) m_release(m_bytes.size());  // read again from the start for the frames
        const FrameChoice choice = choose(index);
        const LogicalFile& file = index.files[choice.file];
        const Frame& frame = file.frames[choice.frame];
        const LogLayout layout = lasLayout(choice.header, m_name, m_options, m_info);
        m_info.north =
            readAzimuthNorth(&choice.header, layout.columns, layout.plan, &m_info.diagnostics);
        m_info.format = "DLIS (RP66 " + index.version + "), logical file " +
                        std::to_string(choice.file + 1) + " of " +
                        std::to_string(index.files.size()) + ", frame " + frame.name.id;
        m_info.details = describeIndex(index, choice.file, choice.frame);
        for (const std::string& array : choice.columns.notRead)
            m_info.diagnostics.warn(m_name, 0,
                                    "channel " + array +
                                        " is an array of more than one dimension (an image) or of "
                                        "text; listed, not read");
        for (std::size_t j = 0; j < file.frames.size(); ++j)
            if (j != choice.frame && file.frames[j].records > 0)
                m_info.diagnostics.warn(m_name, 0,
                                        "frame " + file.frames[j].name.id +
                                            " of the same logical file is not read "
                                            "(one frame per log)");
        if (index.files.size() > 1 && m_options.logicalFile == 0)
            m_info.diagnostics.warn(
                m_name, 0,
                std::to_string(index.files.size()) + " logical files (runs); reading " +
                    std::to_string(choice.file + 1) + " (--file picks another)");
        readRows(index, choice, layout);
        return finish(layout);
    }

private:
    FrameChoice choose(const DlisIndex& index) {
        if (m_options.logicalFile > 0) {
            const std::size_t wanted = static_cast<std::size_t>(m_options.logicalFile);
            if (wanted > index.files.size())
                throw ParseError(m_name, 0, 0,
                                 "expected --file from 1 to " + std::to_string(index.files.size()) +
                                     " (the logical files of this DLIS), found " +
                                     std::to_string(wanted));
            if (auto c = bestFrame(index, wanted - 1, m_name, m_options)) return std::move(*c);
            throw ParseError(
                m_name, 0, 0,
                "logical file " + std::to_string(wanted) + " holds no frame that can be read");
        }
        std::optional<FrameChoice> first;
        for (std::size_t i = 0; i < index.files.size(); ++i) {
            auto c = bestFrame(index, i, m_name, m_options);
            if (!c) continue;
            LogInfo scratch;
            int arms = 0;
            try {
                arms = lasLayout(c->header, m_name, m_options, scratch).plan.armCount;
            } catch (const std::exception&) {
            }
            if (arms > 0) return std::move(*c);
            if (!first) first = std::move(c);
        }
        if (first) return std::move(*first);
        throw ParseError(m_name, 0, 0,
                         "expected a frame of numeric channels, found none in " +
                             std::to_string(index.files.size()) +
                             " logical files (arrays of more than one dimension and text "
                             "channels are not read as curves)");
    }

    void readRows(const DlisIndex& index, const FrameChoice& choice, const LogLayout& layout) {
        const LogicalFile& file = index.files[choice.file];
        const Frame& frame = file.frames[choice.frame];
        const FrameColumns& cols = choice.columns;
        // Every channel with a column is decoded; the rest are skipped by their size.
        std::vector<std::size_t> wanted;
        for (std::size_t k : cols.channelOf)
            if (wanted.empty() || wanted.back() != k) wanted.push_back(k);
        const dlis::FrameRead read = dlis::frameRead(file, frame, wanted);
        // Where each column's value lies in the decoded values.
        std::vector<std::size_t> at(cols.items.size());
        {
            std::size_t offset = 0, w = 0;
            for (std::size_t c = 0; c < cols.items.size(); ++c) {
                while (wanted[w] != cols.channelOf[c]) {
                    offset += file.channels[frame.channels[wanted[w]]].elements();
                    ++w;
                }
                at[c] = offset + cols.elementOf[c];
            }
        }
        const CurvePlan& plan = layout.plan;
        m_nulls.assign(cols.items.size(), 0);
        DepthOrdering order(plan.emptyTable(layout.columns), m_options.depthOrder, m_name,
                            plan.depthScale, m_stream.chunkRows);
        SectionTable rows = plan.emptyTable(layout.columns);
        std::vector<std::size_t> ordinals;
        std::vector<double> raw(cols.items.size());
        const DepthOrdering::Emit emit = [this](const SectionTable& t) { deliver(t); };
        const bool common = m_options.nullPolicy == NullPolicy::Common;
        std::size_t ordinal = 0;
        if (m_stream.onStart) m_stream.onStart(m_info, frame.records);
        auto flush = [&] {
            try {
                order.add(rows, ordinals, emit);
            } catch (const ParseError& e) {
                if (e.line() == 0) throw;
                throw ParseError(m_name, 0, 0,
                                 "frame record " + std::to_string(e.line()) + " of " +
                                     frame.name.id + ": " + e.message());
            }
            order.emitReady(emit);
            rows.clearRows();
            ordinals.clear();
        };
        dlis::readFrames(
            m_bytes, m_name, index, choice.file, choice.frame, read,
            [&](std::uint32_t number, const double* values, std::size_t offset) {
                ++ordinal;
                for (std::size_t c = 0; c < raw.size(); ++c) {
                    double v = values[at[c]];
                    if (std::isnan(v) || (common && isCommonNullNumber(v))) {
                        v = std::numeric_limits<double>::quiet_NaN();
                        ++m_nulls[c];
                    } else {
                        v *= cols.scale[c];
                    }
                    raw[c] = v;
                }
                try {
                    plan.checkAngles(raw.data(), m_name, 0);
                } catch (const ParseError& e) {
                    throw ParseError(m_name, 0, 0,
                                     "byte " + std::to_string(offset) + " (frame " +
                                         std::to_string(number) + "): " + e.message());
                }
                plan.mapRow(raw.data(), rows);
                ordinals.push_back(ordinal);
                if (rows.rowCount() >= m_stream.chunkRows) {
                    flush();
                    if (m_release) m_release(offset);
                    if (cancelled()) return false;
                }
                return true;
            },
            &m_info.diagnostics);
        if (rows.rowCount()) flush();
        const std::size_t before = m_info.diagnostics.warnings.size();
        order.finish(
            !m_info.cancelled, emit, [this] { return !cancelled(); }, m_info.diagnostics);
        // The depth ordering counts rows as lines; in DLIS they are frame records.
        for (std::size_t i = before; i < m_info.diagnostics.warnings.size(); ++i) {
            Warning& w = m_info.diagnostics.warnings[i];
            if (w.line == 0) continue;
            w.message = "from frame record " + std::to_string(w.line) + " of " + frame.name.id +
                        ": " + w.message;
            w.line = 0;
        }
    }

    bool cancelled() {
        if (m_stream.cancel && m_stream.cancel->load(std::memory_order_relaxed))
            m_info.cancelled = true;
        return m_info.cancelled;
    }

    void deliver(const SectionTable& chunk) {
        if (chunk.rowCount() == 0) return;
        m_tally.add(chunk, m_info);
        m_consumer(chunk);
    }

    LogInfo finish(const LogLayout& layout) {
        for (std::size_t c = 0; c < m_info.curves.size() && c < m_nulls.size(); ++c)
            m_info.curves[c].nulls = m_nulls[c];
        m_info.arms = layout.plan.armCount;
        m_tally.finish(m_info);
        if (m_info.rows == 0 && !m_info.cancelled)
            throw ParseError(
                m_name, 0, 0,
                "expected frames of data in the frame read, found none (" + m_info.format + ")");
        return std::move(m_info);
    }

    std::string_view m_bytes;
    std::string m_name;
    const ReadOptions& m_options;
    const ChunkConsumer& m_consumer;
    const StreamOptions& m_stream;
    const std::function<void(std::size_t)>& m_release;
    LogInfo m_info;
    RowTally m_tally;
    std::vector<std::size_t> m_nulls;
};

}  // namespace

WellLocation readDlisWellLocation(std::string_view bytes, const std::string& name,
                                  Diagnostics* diagnostics) {
    const DlisIndex index = dlis::indexDlis(bytes, name, nullptr);
    WellLocation first;
    for (std::size_t i = 0; i < index.files.size(); ++i) {
        const LasHeader h = headerOf(index.files[i], name, {}, nullptr);
        WellLocation location = readWellLocation(h, name, i == 0 ? diagnostics : nullptr);
        if (i == 0) first = location;
        if (location.hasProjected() || std::isfinite(location.latitude_deg)) return location;
    }
    return first;
}

LogInfo streamDlis(std::string_view bytes, const std::string& name, const ReadOptions& options,
                   const ChunkConsumer& consumer, const StreamOptions& stream,
                   const std::function<void(std::size_t end)>& release) {
    return DlisStreamer(bytes, name, options, consumer, stream, release).run();
}

}  // namespace caliper3d::io
