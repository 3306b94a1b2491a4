#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace caliper3d::io {

// Where the text of a log comes from: a file read in blocks, or text in memory.
class TextSource {
public:
    virtual ~TextSource() = default;
    // Copies up to n bytes; 0 at the end.
    virtual std::size_t read(char* to, std::size_t n) = 0;
    // Total size in bytes (for estimates only).
    virtual std::size_t size() const = 0;
};

// A file opened for sequential reading. Throws ParseError naming the file when
// it cannot be opened or read.
class FileSource : public TextSource {
public:
    explicit FileSource(const std::string& path);
    ~FileSource() override;
    FileSource(const FileSource&) = delete;
    FileSource& operator=(const FileSource&) = delete;
    std::size_t read(char* to, std::size_t n) override;
    std::size_t size() const override { return m_size; }

private:
    std::string m_path;
    int m_fd = -1;
    std::size_t m_size = 0;
};

class MemorySource : public TextSource {
public:
    explicit MemorySource(std::string_view text) : m_text(text) {}
    std::size_t read(char* to, std::size_t n) override;
    std::size_t size() const override { return m_text.size(); }

private:
    std::string_view m_text;
    std::size_t m_pos = 0;
};

// Hands out runs of whole lines, a block at a time, so the text is never held
// whole; the last run may end in an unterminated line. A line longer than a
// block grows the block.
class BlockReader {
public:
    BlockReader(TextSource& source, std::size_t blockBytes);
    ~BlockReader();
    BlockReader(const BlockReader&) = delete;
    BlockReader& operator=(const BlockReader&) = delete;
    // The next run; valid until the following call.
    std::string_view next();
    bool done() const { return m_eof && m_begin == m_end; }

private:
    TextSource& m_source;
    std::vector<char> m_buffer;
    std::size_t m_begin = 0, m_end = 0;
    bool m_eof = false;
};

}  // namespace caliper3d::io
