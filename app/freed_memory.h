#pragma once

namespace caliper3d::app {

// How the program's memory is allocated, set once in main before any thread starts (docs/
// architecture.md, "Freed memory kept for reuse"). A field's wells are each read, placed and
// planned on short-lived threads, and each frees about 100 MB (a well of 1 km at 2.5 mm) for
// the next. glibc's malloc by default gives threads arenas of their own and hands large blocks
// back to the kernel as they are freed, so each next well faulted in (and the kernel zeroed)
// fresh pages: on this VM a 4 KiB fault costs about 11 us, and 100 wells took 68-261 thousand.
// One arena, with blocks up to 256 MiB kept in it and its top kept: the next well reuses what
// the last one freed (9.5-19 thousand faults). The window hands the memory back once its load
// and analyses end (WellSession::giveBackFreedMemory, malloc_trim). glibc only; elsewhere
// nothing.
void keepFreedMemoryForReuse();

}  // namespace caliper3d::app
