#include "io/parked_rows.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

#include <unistd.h>

namespace caliper3d::io {

namespace {

// The columns of `t` in the order they are parked: depth, radii, the optional curves (empty
// when absent), the extra curves.
template <typename Table, typename Visit>
void forEachColumn(Table& t, Visit visit) {
    visit(t.depth_m);
    visit(t.radius_mm);
    visit(t.p1az_deg);
    visit(t.devi_deg);
    visit(t.hazi_deg);
    visit(t.rb_deg);
    visit(t.bitSize_mm);
    for (auto& extra : t.extraCurves) visit(extra.values);
}

std::string why(const char* what) {
    return std::string("caliper3d: cannot ") + what +
           " a scratch file in the temporary folder: " + std::strerror(errno);
}

}  // namespace

void ParkedRows::Closer::operator()(std::FILE* file) const {
    std::fclose(file);
}

ParkedRows::ParkedRows(const SectionTable& table)
    : m_rows(table.rowCount()), m_arms(table.armCount) {
    // std::tmpfile, not a named file: nothing is left behind by a program that is stopped.
    m_file.reset(std::tmpfile());
    if (!m_file) throw std::runtime_error(why("make"));
    forEachColumn(table, [this](const std::vector<double>& column) {
        m_lengths.push_back(column.size());
        if (column.empty()) return;
        if (std::fwrite(column.data(), sizeof(double), column.size(), m_file.get()) !=
            column.size())
            throw std::runtime_error(why("write"));
        m_bytes += column.size() * sizeof(double);
    });
    if (std::fflush(m_file.get()) != 0) throw std::runtime_error(why("write"));
}

ParkedRows::~ParkedRows() = default;

SectionTable ParkedRows::read(const SectionTable& shape) const {
    SectionTable out = shape.rows(0, 0);
    std::size_t column = 0;
    bool fits = shape.armCount == m_arms;
    forEachColumn(shape, [&](const std::vector<double>& c) {
        const std::size_t parked = column < m_lengths.size() ? m_lengths[column] : 0;
        fits = fits && column < m_lengths.size() && c.empty() == (parked == 0);
        ++column;
    });
    if (!fits || column != m_lengths.size())
        throw std::runtime_error("caliper3d: rows parked for " + shape.source +
                                 " do not match its curves");
    const int fd = fileno(m_file.get());
    off_t offset = 0;
    column = 0;
    forEachColumn(out, [&](std::vector<double>& c) {
        const std::size_t values = m_lengths[column++];
        c.resize(values);
        auto* bytes = reinterpret_cast<char*>(c.data());  // doubles, read back as written
        std::size_t left = values * sizeof(double);
        while (left > 0) {
            const ssize_t got = ::pread(fd, bytes, left, offset);
            if (got < 0 && errno == EINTR) continue;
            if (got <= 0) throw std::runtime_error(why("read back"));
            bytes += got;
            offset += got;
            left -= static_cast<std::size_t>(got);
        }
    });
    return out;
}

}  // namespace caliper3d::io
