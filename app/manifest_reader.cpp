// The manifest's reading (CSV and JSON), apart from the rest of the batch so that it builds
// without Qt: the fuzz target links it alone (tests/fuzz/fuzz_batch_manifest.cpp).
#include "app/batch_manifest.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "io/parse_error.h"

namespace caliper3d::app {

namespace {

namespace fs = std::filesystem;

bool isColumn(const std::string& name) {
    const std::vector<std::string>& columns = manifestColumns();
    return std::find(columns.begin(), columns.end(), name) != columns.end();
}

std::string trim(const std::string& text) {
    const auto first = text.find_first_not_of(" \t\r");
    if (first == std::string::npos) return "";
    return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string> words(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string word; in >> word;) out.push_back(word);
    return out;
}

// One CSV line: fields split at commas outside double quotes ("" inside is one quote).
std::vector<std::string> csvFields(const std::string& line, const std::string& file,
                                   std::size_t lineNumber) {
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char c = line[i];
        if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
            fields.back() += '"';
            ++i;
        } else if (c == '"') {
            quoted = !quoted;
        } else if (c == ',' && !quoted) {
            fields.emplace_back();
        } else {
            fields.back() += c;
        }
    }
    if (quoted) throw io::ParseError(file, lineNumber, 0, "a double quote is not closed");
    for (std::string& field : fields) field = trim(field);
    return fields;
}

// A path of the manifest, relative to the manifest's folder.
std::string resolved(const std::string& path, const fs::path& folder) {
    if (path.empty() || fs::path(path).is_absolute() || folder.empty()) return path;
    std::string out = (folder / path).lexically_normal().string();
    if (path.back() == '/' && out.back() != '/') out += '/';
    return out;
}

// Fills `row` from its named fields; sets its problem where they cannot run.
void fillRow(ManifestRow& row, const std::map<std::string, std::string>& field,
             const fs::path& folder) {
    auto get = [&field](const char* name) {
        const auto it = field.find(name);
        return it == field.end() ? std::string() : it->second;
    };
    row.file = resolved(get("file"), folder);
    row.verbs = words(get("verb"));
    if (row.verbs.empty()) row.verbs = {"report"};
    row.output = resolved(get("output"), folder);
    for (const WellOption& option : wellOptions()) {
        if (option.column.empty()) continue;
        std::string cell = get(option.column.c_str());
        if (option.value == OptionValue::Path) cell = resolved(cell, folder);
        if (!cell.empty()) row.wellOptions[option.name] = cell;
    }
    row.options = words(get("options"));
    if (row.file.empty()) row.problem = "no file given";
    for (const std::string& verb : row.verbs)
        if (std::find(batchVerbs().begin(), batchVerbs().end(), verb) == batchVerbs().end()) {
            row.problem = "unknown verb '" + verb + "' (a row runs info, report, render or export)";
            break;
        }
}

Manifest readCsvManifest(const std::string& path, std::istream& in) {
    Manifest manifest{path, {}};
    const fs::path folder = fs::path(path).parent_path();
    std::vector<std::string> header;
    std::string text;
    for (std::size_t lineNumber = 1; std::getline(in, text); ++lineNumber) {
        const std::string line = trim(text);
        if (line.empty() || line.front() == '#') continue;
        std::vector<std::string> fields = csvFields(line, path, lineNumber);
        if (header.empty()) {
            for (std::string& name : fields) {
                std::transform(name.begin(), name.end(), name.begin(), ::tolower);
                if (!isColumn(name))
                    throw io::ParseError(path, lineNumber, 0, "unknown column '" + name + "'");
            }
            if (std::find(fields.begin(), fields.end(), "file") == fields.end())
                throw io::ParseError(path, lineNumber, 0, "the header has no 'file' column");
            header = fields;
            continue;
        }
        ManifestRow row;
        row.index = manifest.rows.size();
        row.line = lineNumber;
        std::map<std::string, std::string> named;
        for (std::size_t k = 0; k < fields.size() && k < header.size(); ++k)
            named[header[k]] = fields[k];
        fillRow(row, named, folder);
        if (fields.size() > header.size())
            row.problem = std::to_string(fields.size()) + " fields for " +
                          std::to_string(header.size()) + " columns (quote a field with commas)";
        manifest.rows.push_back(std::move(row));
    }
    if (header.empty()) throw io::ParseError(path, 0, 0, "no header row (file,verb,...)");
    return manifest;
}

// A JSON value as the manifest's text: strings as they are, numbers as written, arrays
// joined (by commas for an option whose value is a comma list, a wellhead or curve names;
// by spaces for verbs and options).
std::string jsonText(const std::string& key, const nlohmann::json& value) {
    if (value.is_string()) return value.get<std::string>();
    if (value.is_array()) {
        std::string out;
        const auto option = std::find_if(wellOptions().begin(), wellOptions().end(),
                                         [&key](const WellOption& o) { return o.column == key; });
        const char* separator =
            option != wellOptions().end() && option->value == OptionValue::CommaList ? "," : " ";
        for (const nlohmann::json& item : value)
            out += (out.empty() ? "" : separator) + jsonText(key, item);
        return out;
    }
    if (value.is_null()) return "";
    return value.dump();
}

Manifest readJsonManifest(const std::string& path, std::istream& in) {
    nlohmann::json document;
    try {
        document = nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {
        // Not only syntax: a number too large for a double is out_of_range (found by
        // fuzz_batch_manifest).
        throw io::ParseError(path, 0, 0, std::string("not JSON: ") + e.what());
    }
    if (document.is_object() && document.contains("wells")) document = document["wells"];
    if (!document.is_array())
        throw io::ParseError(path, 0, 0, "expected an array of wells, or {\"wells\": [...]}");
    Manifest manifest{path, {}};
    const fs::path folder = fs::path(path).parent_path();
    for (const nlohmann::json& item : document) {
        ManifestRow row;
        row.index = manifest.rows.size();
        std::map<std::string, std::string> named;
        if (!item.is_object()) {
            row.problem = "expected an object with a \"file\"";
        } else {
            for (const auto& [key, value] : item.items()) {
                if (!isColumn(key)) throw io::ParseError(path, 0, 0, "unknown key '" + key + "'");
                named[key] = jsonText(key, value);
            }
            fillRow(row, named, folder);
        }
        manifest.rows.push_back(std::move(row));
    }
    return manifest;
}

}  // namespace

const std::vector<std::string>& manifestColumns() {
    static const std::vector<std::string> kColumns = [] {
        std::vector<std::string> columns = {"file", "verb", "output"};
        for (const WellOption& option : wellOptions())
            if (!option.column.empty()) columns.push_back(option.column);
        columns.emplace_back("options");
        return columns;
    }();
    return kColumns;
}

const std::vector<std::string>& batchVerbs() {
    static const std::vector<std::string> kVerbs = {"info", "report", "render", "export"};
    return kVerbs;
}

Manifest readManifest(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw io::ParseError(path, 0, 0, "cannot open the manifest");
    return parseManifest(path, in);
}

Manifest parseManifest(const std::string& path, std::istream& in) {
    const std::string extension = fs::path(path).extension().string();
    if (extension == ".json" || extension == ".JSON") return readJsonManifest(path, in);
    return readCsvManifest(path, in);
}

}  // namespace caliper3d::app
