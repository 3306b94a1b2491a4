#include "scenegraph/render_caching.h"

#include <cstdlib>
#include <string>

#include <Inventor/nodes/SoIndexedTriangleStripSet.h>
#include <Inventor/nodes/SoSeparator.h>

#include "coin_fixture.h"
#include "scenegraph/offscreen_renderer.h"
#include "scenegraph/segment_node_builder.h"

namespace caliper3d::scenegraph {
namespace {

// GL_RENDERER strings as drivers give them.
TEST(RenderCachingTest, SoftwareRasterisersAreToldFromHardwareDrivers) {
    EXPECT_TRUE(isSoftwareRenderer("llvmpipe (LLVM 15.0.6, 256 bits)"));
    EXPECT_TRUE(isSoftwareRenderer("softpipe"));
    EXPECT_TRUE(isSoftwareRenderer("Mesa X11 / swrast"));
    EXPECT_TRUE(isSoftwareRenderer("Microsoft Basic Render Driver (Software)"));
    EXPECT_FALSE(isSoftwareRenderer("NVIDIA H200/PCIe/SSE2"));
    EXPECT_FALSE(isSoftwareRenderer("Mesa Intel(R) UHD Graphics 620 (KBL GT2)"));
    EXPECT_FALSE(isSoftwareRenderer("AMD Radeon RX 6800 XT (navi21, LLVM 15.0.6, DRM 3.49)"));
    EXPECT_FALSE(isSoftwareRenderer(""));
}

// Coin compiles separators' caches by itself (renderCaching AUTO): not on a software rasteriser.
TEST(RenderCachingTest, SeparatorsCacheByThemselvesOnlyOnAHardwareDriver) {
    if (std::getenv("CALIPER3D_RENDER_CACHING"))
        GTEST_SKIP() << "CALIPER3D_RENDER_CACHING is set: the driver does not decide";
    EXPECT_EQ(separatorRenderCaches("llvmpipe (LLVM 15.0.6, 256 bits)"), 0);
    EXPECT_EQ(separatorRenderCaches("Mesa X11 / swrast"), 0);
    EXPECT_EQ(separatorRenderCaches("NVIDIA H200/PCIe/SSE2"), 2);
    EXPECT_EQ(separatorRenderCaches("Mesa Intel(R) UHD Graphics 620 (KBL GT2)"), 2);
}

class RenderCachingSceneTest : public CoinTest {};

// Before any context nothing is cached; once the probe has drawn, a static mesh is cached
// exactly when the driver that drew it is a hardware one (under llvmpipe, as in CI: never).
TEST_F(RenderCachingSceneTest, MeshesAreCachedOnlyOnceAHardwareDriverHasBeenSeen) {
    if (std::getenv("CALIPER3D_RENDER_CACHING"))
        GTEST_SKIP() << "CALIPER3D_RENDER_CACHING is set: the driver does not decide";
    EXPECT_TRUE(notedGlRenderer().empty());
    EXPECT_FALSE(renderCachingWanted());
    auto* before = new SoIndexedTriangleStripSet;
    before->ref();
    EXPECT_EQ(cacheableShape(before), before);
    before->unref();

    probeOffscreenRenderer();
    const std::string renderer = notedGlRenderer();
    ASSERT_FALSE(renderer.empty()) << "no offscreen context was made";
    EXPECT_EQ(renderCachingWanted(), !isSoftwareRenderer(renderer)) << renderer;
    EXPECT_EQ(SoSeparator::getNumRenderCaches(), separatorRenderCaches(renderer)) << renderer;
    auto* shape = new SoIndexedTriangleStripSet;
    shape->ref();
    SoNode* drawn = cacheableShape(shape);
    drawn->ref();
    if (renderCachingWanted()) {
        ASSERT_TRUE(drawn->isOfType(SoSeparator::getClassTypeId())) << renderer;
        EXPECT_EQ(static_cast<SoSeparator*>(drawn)->renderCaching.getValue(), SoSeparator::ON);
    } else {
        EXPECT_EQ(drawn, shape) << renderer;
    }
    drawn->unref();
    shape->unref();
}

}  // namespace
}  // namespace caliper3d::scenegraph
