#include "app/freed_memory.h"

#include <cstdlib>  // (defines __GLIBC__ where glibc is the C library)

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace caliper3d::app {

void keepFreedMemoryForReuse() {
#ifdef __GLIBC__
    mallopt(M_ARENA_MAX, 1);
    mallopt(M_MMAP_THRESHOLD, 256 << 20);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}

}  // namespace caliper3d::app
