#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace caliper3d::app {

// Where a verb that writes writes, from its -o (docs/user-guide.md, "Batch and cluster"):
// - "DIR/" (a trailing slash, or an existing folder): one file per input, DIR/STEM + `tail`
//   (STEM: the input's file name less its extension; `tail` e.g. ".csv", "-zones.csv");
// - a pattern holding {stem}, {name} (the input's file name) or {index} (its place among the
//   inputs, from 0): one file per input, the pattern filled in;
// - anything else: one file for every input (export and render draw them in one scene).
class OutputNames {
public:
    OutputNames(std::string spec, std::string tail);
    const std::string& spec() const { return m_spec; }
    bool perInput() const { return m_perInput; }
    // The output for input `index` (the spec itself when not per input).
    std::string forInput(const std::string& input, std::size_t index) const;
    // Every input's output; throws UsageError (naming `option`) when two inputs would write
    // the same file. Creates the folders they go in.
    std::vector<std::string> forInputs(const std::vector<std::string>& inputs,
                                       const std::string& option) const;

private:
    std::string m_spec;
    std::string m_tail;
    bool m_directory = false;
    bool m_perInput = false;
};

// The input's file name less its last extension ("logs/A-1.las" -> "A-1").
std::string inputStem(const std::string& input);

}  // namespace caliper3d::app
