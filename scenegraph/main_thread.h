#pragma once

namespace caliper3d::scenegraph {

// Coin on Debian is built without thread safety: the scene graph and sensor
// queues may be touched by the main thread only. initCoin() records which
// thread that is; assertMainThread() aborts in debug builds when called from
// any other thread.
void initCoin();
bool onMainThread();
void assertMainThread(const char* where);

}  // namespace caliper3d::scenegraph
