#pragma once

#include <gtest/gtest.h>

#include "scenegraph/main_thread.h"

// Scene-graph tests need Coin initialised, no GL.
class CoinTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() { caliper3d::scenegraph::initCoin(); }
};
