#pragma once

#include <array>
#include <cstdio>
#include <string>

#include <sys/wait.h>

namespace caliper3d::test {

struct CommandRun {
    int status = -1;
    std::string output;  // stdout, and stderr too unless kept apart
};

// Runs the caliper3d binary with `arguments` through the shell.
inline CommandRun runCaliper3d(const std::string& arguments, bool withStderr = true) {
    CommandRun r;
    const std::string command =
        std::string(CALIPER3D_BINARY) + " " + arguments + (withStderr ? " 2>&1" : " 2>/dev/null");
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buffer{};
    while (std::fgets(buffer.data(), buffer.size(), pipe)) r.output += buffer.data();
    const int raw = pclose(pipe);
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    return r;
}

// Runs the binary with `arguments` (and `environment`, e.g. "env -u DISPLAY")
// and keeps only its standard error.
inline CommandRun runCaliper3dStderr(const std::string& arguments,
                                     const std::string& environment = "") {
    CommandRun r;
    const std::string command = (environment.empty() ? "" : environment + " ") +
                                std::string(CALIPER3D_BINARY) + " " + arguments +
                                " 2>&1 1>/dev/null";
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buffer{};
    while (std::fgets(buffer.data(), buffer.size(), pipe)) r.output += buffer.data();
    const int raw = pclose(pipe);
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    return r;
}

}  // namespace caliper3d::test
