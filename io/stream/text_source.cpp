#include "io/stream/text_source.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "io/parse_error.h"

namespace caliper3d::io {

FileSource::FileSource(const std::string& path) : m_path(path) {
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

FileSource::~FileSource() {
    ::close(m_fd);
}

std::size_t FileSource::read(char* to, std::size_t n) {
    for (;;) {
        const ssize_t got = ::read(m_fd, to, n);
        if (got >= 0) return static_cast<std::size_t>(got);
        if (errno != EINTR)
            throw ParseError(m_path, 0, 0, "read failed: " + std::string(std::strerror(errno)));
    }
}

std::size_t MemorySource::read(char* to, std::size_t n) {
    n = std::min(n, m_text.size() - m_pos);
    std::memcpy(to, m_text.data() + m_pos, n);
    m_pos += n;
    return n;
}

namespace {

// Each reading thread keeps the block of its last file for the next. A field is a hundred
// logs read one after another on the same threads: a fresh block per file (allocated, zeroed,
// faulted in) cost a tenth of the whole read of 100 logs of 1.5 MB (docs/benchmarks.md).
// A block grown past this for a very long line is let go.
constexpr std::size_t kKeptBlockBytes = 16u << 20;
thread_local std::vector<char> t_keptBlock;

}  // namespace

// No bigger than the text (a small file or a fuzzer's input needs no 8 MiB block).
BlockReader::BlockReader(TextSource& source, std::size_t blockBytes)
    : m_source(source), m_buffer(std::move(t_keptBlock)) {
    t_keptBlock = {};
    m_buffer.resize(std::max<std::size_t>(std::min(blockBytes, source.size() + 1), 4096));
}

BlockReader::~BlockReader() {
    if (m_buffer.capacity() <= kKeptBlockBytes) t_keptBlock = std::move(m_buffer);
}

std::string_view BlockReader::next() {
    std::memmove(m_buffer.data(), m_buffer.data() + m_begin, m_end - m_begin);
    m_end -= m_begin;
    m_begin = 0;
    for (;;) {
        while (!m_eof && m_end < m_buffer.size()) {
            const std::size_t got = m_source.read(m_buffer.data() + m_end, m_buffer.size() - m_end);
            if (got == 0) m_eof = true;
            m_end += got;
        }
        if (m_eof) {
            m_begin = m_end;
            return {m_buffer.data(), m_end};
        }
        const void* nl = memrchr(m_buffer.data(), '\n', m_end);
        if (nl != nullptr) {
            m_begin = static_cast<std::size_t>(static_cast<const char*>(nl) - m_buffer.data()) + 1;
            return {m_buffer.data(), m_begin};
        }
        m_buffer.resize(m_buffer.size() * 2);  // a line longer than a block
    }
}

}  // namespace caliper3d::io
