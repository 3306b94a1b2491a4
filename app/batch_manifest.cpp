#include "app/batch_manifest.h"

#include <algorithm>
#include <stdexcept>

#include "app/output_names.h"

namespace caliper3d::app {

std::string rowOutput(const ManifestRow& row, const std::string& verb, const std::string& folder) {
    if (verb == "info") return "";
    const std::string extension = verb == "report" ? ".csv" : verb == "render" ? ".png" : ".iv";
    std::string given = row.output.empty() ? folder : row.output;
    if (given.empty())
        throw std::invalid_argument("no output: give the row an output or batch -o DIR/");
    const bool isFolder = given.back() == '/' || (row.output.empty() && !folder.empty());
    if (isFolder) {
        std::string out = given;
        if (out.back() != '/') out += '/';
        return out + inputStem(row.file) + extension;
    }
    const std::size_t writers = static_cast<std::size_t>(std::count_if(
        row.verbs.begin(), row.verbs.end(), [](const std::string& v) { return v != "info"; }));
    if (writers > 1)
        throw std::invalid_argument("output '" + row.output +
                                    "' names one file for several verbs: give a folder (out/)");
    return given;
}

std::vector<std::string> verbArguments(const ManifestRow& row, const std::string& verb,
                                       const std::string& output, const std::string& summary) {
    std::vector<std::string> args = {row.file};
    auto option = [&args](const char* name, const std::string& value) {
        if (value.empty()) return;
        args.emplace_back(name);
        args.push_back(value);
    };
    if (verb != "info") option("-o", output);
    for (const WellOption& well : wellOptions()) {
        const auto cell = row.wellOptions.find(well.name);
        if (cell != row.wellOptions.end() && takes(verb, well.group))
            option((std::string("--") + well.name).c_str(), cell->second);
    }
    args.insert(args.end(), row.options.begin(), row.options.end());
    option("--summary", summary);
    return args;
}

}  // namespace caliper3d::app
