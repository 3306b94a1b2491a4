#include "app/commands.h"

int main(int argc, char** argv) {
    return caliper3d::app::runCommandLine(argc, argv);
}
