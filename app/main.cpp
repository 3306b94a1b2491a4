#include "app/commands.h"
#include "app/freed_memory.h"
#include "app/huge_pages.h"

int main(int argc, char** argv) {
    caliper3d::app::preferHugePages(argc, argv);
    caliper3d::app::keepFreedMemoryForReuse();
    return caliper3d::app::runCommandLine(argc, argv);
}
