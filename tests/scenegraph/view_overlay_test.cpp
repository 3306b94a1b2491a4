#include <gtest/gtest.h>

#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoCube.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoText2.h>

#include "coin_fixture.h"
#include "scenegraph/node_ref.h"
#include "scenegraph/view_overlay.h"

namespace caliper3d::scenegraph {
namespace {

TEST(ViewOverlayTest, CaptionStatesTheExaggeration) {
    EXPECT_EQ(exaggerationCaption(300.0), "radii x 300");
    EXPECT_EQ(exaggerationCaption(2.5), "radii x 2.5");
    EXPECT_EQ(exaggerationCaption(1.0), "radii to scale");
}

class ViewOverlayNodesTest : public CoinTest {};

TEST_F(ViewOverlayNodesTest, CaptionLinesAreItsText) {
    ViewOverlay overlay;
    overlay.setCaption({"eye at MD 60.00 m", "radii x 20"});
    SoSearchAction byName;
    byName.setName("caption");
    byName.setSearchingAll(TRUE);
    byName.apply(overlay.root());
    ASSERT_NE(byName.getPath(), nullptr);
    SoSearchAction text;
    text.setType(SoText2::getClassTypeId());
    text.setSearchingAll(TRUE);
    text.apply(byName.getPath()->getTail());
    ASSERT_NE(text.getPath(), nullptr);
    const auto* caption = static_cast<SoText2*>(text.getPath()->getTail());
    ASSERT_EQ(caption->string.getNum(), 2);
    EXPECT_STREQ(caption->string[1].getString(), "radii x 20");
}

TEST_F(ViewOverlayNodesTest, TakesNoPartInTheSceneBox) {
    // It draws in pixels at a corner: framing a scene with it must not see it.
    ViewOverlay overlay;
    overlay.setCaption({"radii x 20"});
    auto root = makeRef(new SoSeparator);
    root->addChild(new SoCube);  // 2 x 2 x 2 at the origin
    root->addChild(overlay.root());
    SoGetBoundingBoxAction box(SbViewportRegion(640, 480));
    box.apply(root.get());
    EXPECT_EQ(box.getBoundingBox().getMin(), SbVec3f(-1.0f, -1.0f, -1.0f));
    EXPECT_EQ(box.getBoundingBox().getMax(), SbVec3f(1.0f, 1.0f, 1.0f));
}

}  // namespace
}  // namespace caliper3d::scenegraph
