#pragma once

#include <functional>
#include <string>
#include <vector>

#include <sys/types.h>

namespace caliper3d::app {

// Runs `body` in a child process, a fork of this one (the same program, its libraries already
// loaded: no exec, no dynamic loading again), its standard output and error written to the
// files `stdoutPath` and `stderrPath`, standard input from /dev/null; the child's exit status
// is what `body` returns. Call it only while this process has one thread: a fork copies the
// calling thread alone. Throws std::runtime_error when no child can be made.
pid_t forkChild(const std::function<int()>& body, const std::string& stdoutPath,
                const std::string& stderrPath);

// How a child ended, from waitpid's status: "" for exit status 0, else "exit status N" or
// "stopped by signal N (NAME)".
std::string describeEnd(int waitStatus);

}  // namespace caliper3d::app
