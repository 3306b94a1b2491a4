#include "io/stream/mapped_file.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "io/parse_error.h"

namespace caliper3d::io {

MappedFile::MappedFile(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0)
        throw ParseError(path, 0, 0,
                         "cannot open file for reading: " + std::string(std::strerror(errno)));
    struct stat st {};
    if (::fstat(fd, &st) != 0 || st.st_size < 0) {
        const int error = errno;
        ::close(fd);
        throw ParseError(path, 0, 0,
                         "cannot read the file's size: " + std::string(std::strerror(error)));
    }
    m_size = static_cast<std::size_t>(st.st_size);
    if (m_size > 0) {
        void* data = ::mmap(nullptr, m_size, PROT_READ, MAP_PRIVATE, fd, 0);
        if (data == MAP_FAILED) {
            const int error = errno;
            ::close(fd);
            throw ParseError(path, 0, 0,
                             "cannot map the file: " + std::string(std::strerror(error)));
        }
        m_data = data;
#ifdef POSIX_MADV_SEQUENTIAL
        ::posix_madvise(m_data, m_size, POSIX_MADV_SEQUENTIAL);
#endif
    }
    ::close(fd);
}

void MappedFile::release(std::size_t end) const {
    const long page = ::sysconf(_SC_PAGESIZE);
    if (!m_data || page <= 0) return;
    end = std::min(end, m_size) / static_cast<std::size_t>(page) * static_cast<std::size_t>(page);
    // A private read-only file mapping: the pages are dropped, never written back.
    if (end > 0) ::madvise(m_data, end, MADV_DONTNEED);
}

MappedFile::~MappedFile() {
    if (m_data) ::munmap(m_data, m_size);
}

}  // namespace caliper3d::io
