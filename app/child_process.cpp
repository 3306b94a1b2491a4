#include "app/child_process.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <stdexcept>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

namespace caliper3d::app {

namespace {

// Points descriptor `target` at `path`; false when it cannot be opened.
bool redirect(int target, const char* path, int flags) {
    const int fd = open(path, flags, 0644);
    if (fd < 0) return false;
    const bool ok = dup2(fd, target) >= 0;
    close(fd);
    return ok;
}

}  // namespace

pid_t forkChild(const std::function<int()>& body, const std::string& stdoutPath,
                const std::string& stderrPath) {
    // Text buffered here would otherwise be printed again by the child.
    std::cout.flush();
    std::fflush(nullptr);
    const pid_t pid = fork();
    if (pid < 0)
        throw std::runtime_error(std::string("cannot start a process: ") + strerror(errno));
    if (pid > 0) return pid;
    const int writing = O_WRONLY | O_CREAT | O_TRUNC;
    if (!redirect(STDIN_FILENO, "/dev/null", O_RDONLY) ||
        !redirect(STDOUT_FILENO, stdoutPath.c_str(), writing) ||
        !redirect(STDERR_FILENO, stderrPath.c_str(), writing))
        _exit(127);
    const int status = body();
    std::cout.flush();
    std::fflush(nullptr);
    // _exit: the parent's exit handlers and static objects are the parent's to run.
    _exit(status);
}

std::string describeEnd(int waitStatus) {
    if (WIFEXITED(waitStatus)) {
        const int code = WEXITSTATUS(waitStatus);
        return code == 0 ? "" : "exit status " + std::to_string(code);
    }
    if (WIFSIGNALED(waitStatus)) {
        const int signal = WTERMSIG(waitStatus);
        const char* name = strsignal(signal);
        return "stopped by signal " + std::to_string(signal) + " (" + (name ? name : "?") + ")";
    }
    return "ended abnormally";
}

}  // namespace caliper3d::app
