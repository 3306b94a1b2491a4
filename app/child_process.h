#pragma once

#include <string>
#include <vector>

#include <sys/types.h>

namespace caliper3d::app {

// This program's own executable (/proc/self/exe), to run verbs in child processes.
std::string ownExecutable();

// Starts `program` with `args` (argv[1...]), its standard output and error written to the
// files `stdoutPath` and `stderrPath`, standard input from /dev/null. Throws
// std::runtime_error when it cannot be started.
pid_t startChild(const std::string& program, const std::vector<std::string>& args,
                 const std::string& stdoutPath, const std::string& stderrPath);

// How a child ended, from waitpid's status: "" for exit status 0, else "exit status N" or
// "stopped by signal N (NAME)".
std::string describeEnd(int waitStatus);

}  // namespace caliper3d::app
