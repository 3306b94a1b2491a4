#include "app/commands.h"
#include "app/huge_pages.h"

int main(int argc, char** argv) {
    caliper3d::app::preferHugePages(argc, argv);
    return caliper3d::app::runCommandLine(argc, argv);
}
