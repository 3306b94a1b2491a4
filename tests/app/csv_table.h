#pragma once
// The CSV files the report verb writes, read back by the command tests: a header line of
// names, then rows of comma-separated fields (no quoting: the report writes none).
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <istream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace caliper3d::test {

// A CSV file as rows of named fields.
struct Csv {
    std::vector<std::string> names;
    std::vector<std::map<std::string, std::string>> rows;
    double number(std::size_t row, const std::string& name) const {
        const std::string& text = rows.at(row).at(name);
        return text.empty() ? std::nan("") : std::stod(text);
    }
};

inline std::vector<std::string> splitCsvLine(const std::string& line) {
    std::vector<std::string> out;
    std::stringstream in(line);
    std::string field;
    while (std::getline(in, field, ',')) out.push_back(field);
    if (!line.empty() && line.back() == ',') out.emplace_back();
    return out;
}

// Every row must hold one field per name (a failed expectation otherwise).
inline Csv parseCsv(std::istream& in) {
    Csv csv;
    std::string line;
    if (!std::getline(in, line)) return csv;
    csv.names = splitCsvLine(line);
    while (std::getline(in, line)) {
        const std::vector<std::string> fields = splitCsvLine(line);
        EXPECT_EQ(fields.size(), csv.names.size()) << line;
        std::map<std::string, std::string> row;
        for (std::size_t k = 0; k < fields.size() && k < csv.names.size(); ++k)
            row[csv.names[k]] = fields[k];
        csv.rows.push_back(std::move(row));
    }
    return csv;
}

inline Csv readCsv(const std::filesystem::path& path) {
    std::ifstream in(path);
    return parseCsv(in);
}

}  // namespace caliper3d::test
