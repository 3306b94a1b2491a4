#include "app/output_names.h"

#include <filesystem>
#include <map>
#include <system_error>

#include "app/input_options.h"

namespace caliper3d::app {

namespace {

void replaceAll(std::string& text, const std::string& token, const std::string& value) {
    for (std::size_t at = text.find(token); at != std::string::npos;
         at = text.find(token, at + value.size()))
        text.replace(at, token.size(), value);
}

bool hasToken(const std::string& spec) {
    for (const char* token : {"{stem}", "{name}", "{index}"})
        if (spec.find(token) != std::string::npos) return true;
    return false;
}

}  // namespace

std::string inputStem(const std::string& input) {
    return std::filesystem::path(input).stem().string();
}

OutputNames::OutputNames(std::string spec, std::string tail)
    : m_spec(std::move(spec)), m_tail(std::move(tail)) {
    std::error_code error;
    m_directory = !m_spec.empty() && m_spec != "-" &&
                  (m_spec.back() == '/' || std::filesystem::is_directory(m_spec, error));
    m_perInput = m_directory || hasToken(m_spec);
}

std::string OutputNames::forInput(const std::string& input, std::size_t index) const {
    if (m_directory) {
        std::string folder = m_spec;
        if (folder.back() != '/') folder += '/';
        return folder + inputStem(input) + m_tail;
    }
    if (!m_perInput) return m_spec;
    std::string out = m_spec;
    replaceAll(out, "{stem}", inputStem(input));
    replaceAll(out, "{name}", std::filesystem::path(input).filename().string());
    replaceAll(out, "{index}", std::to_string(index));
    return out;
}

std::vector<std::string> OutputNames::forInputs(const std::vector<std::string>& inputs,
                                                const std::string& option) const {
    std::vector<std::string> out;
    std::map<std::string, std::size_t> seen;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        out.push_back(forInput(inputs[i], i));
        if (!m_perInput) continue;
        const auto [at, fresh] = seen.emplace(out.back(), i);
        if (!fresh)
            throw UsageError(option + " " + m_spec + ": " + inputs[at->second] + " and " +
                             inputs[i] + " would both write " + out.back() +
                             "; use {index} or {name} in the pattern");
    }
    if (m_perInput)
        for (const std::string& file : out) {
            const std::filesystem::path folder = std::filesystem::path(file).parent_path();
            std::error_code error;
            if (!folder.empty()) std::filesystem::create_directories(folder, error);
            if (error)
                throw UsageError(option + " " + m_spec + ": cannot make the folder " +
                                 folder.string() + ": " + error.message());
        }
    return out;
}

}  // namespace caliper3d::app
