#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace caliper3d::io {

// A file's bytes mapped read-only into memory (POSIX mmap): a binary format read by
// offset (DLIS) costs no copy, and the kernel pages it in and out as it is read. Boost's
// mapped_file would do the same but needs a library the build does not otherwise link.
// Throws ParseError naming the file when it cannot be opened or mapped.
class MappedFile {
public:
    explicit MappedFile(const std::string& path);
    ~MappedFile();
    MappedFile(const MappedFile&) = delete;
    MappedFile& operator=(const MappedFile&) = delete;

    std::string_view bytes() const { return {static_cast<const char*>(m_data), m_size}; }
    // Gives back the pages of bytes [0, end) read so far: they leave the resident set and are
    // read again from the file if touched again (a reader that has done with them keeps its
    // memory to what it parsed).
    void release(std::size_t end) const;

private:
    void* m_data = nullptr;
    std::size_t m_size = 0;
};

}  // namespace caliper3d::io
