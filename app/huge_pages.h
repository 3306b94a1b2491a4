#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace caliper3d::app {

// Transparent huge pages for a command that will hold hundreds of megabytes (docs/
// architecture.md, "Huge pages"). Linux gives a process 2 MiB pages only where it asks for
// them (transparent_hugepage "madvise"), and glibc's malloc asks for all of its heap only when
// GLIBC_TUNABLES says glibc.malloc.hugetlb=1, which glibc reads once, as a program starts: so
// the program starts itself again with it. A field of 100 logs or a 4 km log otherwise faults
// its memory in 4 KiB at a time: a fifth of `render`'s load on this machine (docs/benchmarks.md).

// What decides it.
struct HugePageContext {
    std::string setting;   // CALIPER3D_HUGE_PAGES: unset (empty), "always", or anything else: no
    std::string tunables;  // GLIBC_TUNABLES as the program started (empty: none)
    std::string thpMode;   // /sys/kernel/mm/transparent_hugepage/enabled ("always [madvise] never")
    std::uintmax_t inputBytes = 0;  // what the command will read
    std::uintmax_t threshold = 0;   // from how much of it they are asked for
    // The window: it keeps what it loads for as long as it is open, and part of a 2 MiB page
    // freed cannot be given back (the 4 km well held 628 MiB, against 592-609 MiB without,
    // for a load its main thread paces, no faster with them). A window of a field (`files` 2 or
    // more, held lean past its row budget) loads on both cores: it asks as the verbs do.
    bool window = false;
    std::size_t files = 0;  // the command's arguments that are files
};

// A command's own arguments that are files, together, from this much (`batch`: always).
inline constexpr std::uintmax_t kHugePagesFrom_bytes = std::uintmax_t{64} << 20;

// The GLIBC_TUNABLES to start again with, or nothing: the program goes on as it is. Nothing when
// CALIPER3D_HUGE_PAGES says no (any value but "always"; the restart sets it), when the tunables
// already say either way, when the kernel gives huge pages to every process or to none, or
// below the threshold or for the window of one well ("always" asks whatever the input and the
// verb).
std::optional<std::string> hugePageTunables(const HugePageContext& context);

// The context from this process's environment and the kernel's setting.
HugePageContext hugePageContext(std::uintmax_t inputBytes, std::uintmax_t threshold);

// Starts this program again (/proc/self/exe with `argv`, the program's name first) with the
// tunables hugePageTunables gives, CALIPER3D_HUGE_PAGES=1 marking the restart. Returns, having
// changed nothing, when they say no or the restart fails.
void restartWithHugePageMalloc(const HugePageContext& context,
                               const std::vector<std::string>& argv);

// Called first in main: restarts with huge pages when the command's arguments that are files
// come to kHugePagesFrom_bytes or more, the window (`view`) of one file aside.
void preferHugePages(int argc, char** argv);

}  // namespace caliper3d::app
