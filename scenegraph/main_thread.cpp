#include "scenegraph/main_thread.h"

#include <cstdio>
#include <cstdlib>
#include <thread>

#include <Inventor/SoDB.h>
#include <Inventor/SoInteraction.h>
#include <Inventor/nodekits/SoNodeKit.h>

#include "scenegraph/coin_messages.h"

namespace caliper3d::scenegraph {

namespace {
std::thread::id g_mainThread;
bool g_initialised = false;
}  // namespace

void initCoin() {
    if (!g_initialised) {
        g_mainThread = std::this_thread::get_id();
        g_initialised = true;
    }
    SoDB::init();
    SoNodeKit::init();
    SoInteraction::init();
    routeCoinMessages();
}

bool onMainThread() {
    return !g_initialised || std::this_thread::get_id() == g_mainThread;
}

void assertMainThread(const char* where) {
#ifndef NDEBUG
    if (!onMainThread()) {
        std::fprintf(stderr, "caliper3d: Coin touched off the main thread in %s\n", where);
        std::abort();
    }
#else
    (void)where;
#endif
}

}  // namespace caliper3d::scenegraph
