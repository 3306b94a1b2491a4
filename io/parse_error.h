#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace caliper3d::io {

// A reading failure that says where (file, line, column) and what was expected.
// Line and column are 1-based; 0 means "not applicable".
class ParseError : public std::runtime_error {
public:
    ParseError(std::string file, std::size_t line, std::size_t column, const std::string& what)
        : std::runtime_error(format(file, line, column, what)),
          m_file(std::move(file)),
          m_line(line),
          m_column(column),
          m_message(what) {}

    const std::string& file() const { return m_file; }
    std::size_t line() const { return m_line; }
    std::size_t column() const { return m_column; }
    const std::string& message() const { return m_message; }  // what() without file, line, column

private:
    static std::string format(const std::string& file, std::size_t line, std::size_t column,
                              const std::string& what) {
        std::string s = file;
        if (line > 0) s += ":" + std::to_string(line);
        if (column > 0) s += ":" + std::to_string(column);
        return s + ": " + what;
    }

    std::string m_file;
    std::size_t m_line;
    std::size_t m_column;
    std::string m_message;
};

}  // namespace caliper3d::io
