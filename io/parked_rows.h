#pragma once

#include <cstddef>
#include <cstdio>
#include <memory>
#include <vector>

#include "io/section_table.h"

namespace caliper3d::io {

// A table's rows parked, as they are in memory, in an unnamed scratch file of the system's
// temporary folder (std::tmpfile: gone when closed, or when the program ends however it ends),
// to be read back whole later at the speed of a copy instead of parsed again from the log. A
// field held lean (app/scene_assembly.cpp) keeps only a sample of each well's rows while it
// plans the picture, then needs every row of each well once more, one well at a time, to build
// its meshes. What is parked lives in the page cache, which the system may write out and take
// back, not in this process's memory. Reading back may happen on any thread, one at a time or
// together (positioned reads).
class ParkedRows {
public:
    // Writes the rows of `table`. Throws std::runtime_error saying why when no scratch file can
    // be made or written (a full disk): the caller reads the log again instead.
    explicit ParkedRows(const SectionTable& table);
    ~ParkedRows();
    ParkedRows(const ParkedRows&) = delete;
    ParkedRows& operator=(const ParkedRows&) = delete;

    std::size_t rowCount() const { return m_rows; }
    std::size_t bytes() const { return m_bytes; }

    // The table parked: `shape`'s source, name, units, casing, north and curves (a table of the
    // same log, such as a sample of its rows: its optional curves present where the parked
    // table's are) with the rows as written. Throws std::runtime_error when `shape` does not
    // match what was parked or the file cannot be read back.
    SectionTable read(const SectionTable& shape) const;

private:
    struct Closer {
        void operator()(std::FILE* file) const;
    };
    std::unique_ptr<std::FILE, Closer> m_file;
    std::size_t m_rows = 0;
    int m_arms = 0;
    std::size_t m_bytes = 0;
    std::vector<std::size_t> m_lengths;  // values of each column, in the order written
};

}  // namespace caliper3d::io
