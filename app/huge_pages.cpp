#include "app/huge_pages.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace caliper3d::app {

namespace {

constexpr const char* kHugeHeap = "glibc.malloc.hugetlb=1";

std::string environment(const char* name) {
    const char* value = std::getenv(name);
    return value ? value : "";
}

}  // namespace

std::optional<std::string> hugePageTunables(const HugePageContext& context) {
    const bool always = context.setting == "always";
    if (!context.setting.empty() && !always) return std::nullopt;
    const bool oneWellWindow = context.window && context.files < 2;
    if (!always && (oneWellWindow || context.inputBytes < context.threshold)) return std::nullopt;
    if (context.tunables.find("glibc.malloc.hugetlb") != std::string::npos) return std::nullopt;
    if (context.thpMode.find("[madvise]") == std::string::npos) return std::nullopt;
    return context.tunables.empty() ? std::string(kHugeHeap) : context.tunables + ":" + kHugeHeap;
}

HugePageContext hugePageContext(std::uintmax_t inputBytes, std::uintmax_t threshold) {
    HugePageContext context;
    context.setting = environment("CALIPER3D_HUGE_PAGES");
    context.tunables = environment("GLIBC_TUNABLES");
    context.inputBytes = inputBytes;
    context.threshold = threshold;
    std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
    std::stringstream text;
    text << mode.rdbuf();
    context.thpMode = text.str();
    return context;
}

void restartWithHugePageMalloc(const HugePageContext& context,
                               const std::vector<std::string>& argv) {
    const std::optional<std::string> tunables = hugePageTunables(context);
    if (!tunables || argv.empty()) return;
    char path[4096];
    const ssize_t size = readlink("/proc/self/exe", path, sizeof path - 1);
    if (size <= 0) return;
    path[size] = '\0';
    const char* given = std::getenv("GLIBC_TUNABLES");
    const std::string before = given ? given : "";
    const char* marked = std::getenv("CALIPER3D_HUGE_PAGES");
    const std::string setting = marked ? marked : "";
    setenv("GLIBC_TUNABLES", tunables->c_str(), 1);
    setenv("CALIPER3D_HUGE_PAGES", "1", 1);
    std::vector<std::string> all = argv;
    std::vector<char*> pointers;
    pointers.reserve(all.size() + 1);
    for (std::string& arg : all) pointers.push_back(arg.data());
    pointers.push_back(nullptr);
    std::cout.flush();
    std::fflush(nullptr);
    execv(path, pointers.data());
    // No restart: go on as we are, with the environment as it was.
    if (given)
        setenv("GLIBC_TUNABLES", before.c_str(), 1);
    else
        unsetenv("GLIBC_TUNABLES");
    if (marked)
        setenv("CALIPER3D_HUGE_PAGES", setting.c_str(), 1);
    else
        unsetenv("CALIPER3D_HUGE_PAGES");
}

void preferHugePages(int argc, char** argv) {
    std::uintmax_t bytes = 0;
    std::size_t files = 0;
    for (int i = 1; i < argc; ++i) {
        std::error_code error;
        if (std::filesystem::is_regular_file(argv[i], error)) {
            bytes += std::filesystem::file_size(argv[i], error);
            ++files;
        }
    }
    // hugePageTunables decides: one small file read at start-up, the rule in one place.
    HugePageContext context = hugePageContext(bytes, kHugePagesFrom_bytes);
    context.window = argc > 1 && std::string(argv[1]) == "view";
    context.files = files;
    restartWithHugePageMalloc(context, std::vector<std::string>(argv, argv + argc));
}

}  // namespace caliper3d::app
