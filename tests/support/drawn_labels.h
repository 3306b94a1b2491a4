#pragma once

// The labels a scene draws, read back from its nodes: what the field picture and the window
// tests check for overlaps. Header only: it needs Coin, which test_support does not link.
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/vec2.hpp>

#include <Inventor/SbViewVolume.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoText2.h>
#include <Inventor/nodes/SoTranslation.h>

#include "scenegraph/camera_setup.h"
#include "scenegraph/label_placement.h"
#include "scenegraph/label_style.h"

namespace caliper3d::test {

// A label as drawn: its text, whether it names a well, and the pixels it covers.
struct DrawnLabel {
    std::string text;
    bool name = false;
    scenegraph::ScreenBox box;
};

// The labels under `root`, read from the nodes drawn (each a separator named "well_name" or
// "depth_label": an SoTranslation to the left end of its baseline first, its SoText2 last)
// and placed in a view of `width` x `height` pixels through `camera`'s own view volume, as
// Coin maps it to the view. Hidden labels count too: callers search what is shown.
inline std::vector<DrawnLabel> drawnLabels(SoNode* root, const SoCamera& camera, int width,
                                           int height) {
    const float aspect = float(width) / float(height);
    const SbViewVolume volume = scenegraph::shownViewVolume(camera, aspect);  // as Coin draws it
    std::vector<DrawnLabel> labels;
    for (const char* kind : {"well_name", "depth_label"}) {
        SoSearchAction search;
        search.setName(kind);
        search.setInterest(SoSearchAction::ALL);
        search.setSearchingAll(TRUE);
        search.apply(root);
        const SoPathList& paths = search.getPaths();
        for (int i = 0; i < paths.getLength(); ++i) {
            auto* group = static_cast<SoSeparator*>(paths[i]->getTail());
            auto* move = dynamic_cast<SoTranslation*>(group->getChild(0));
            auto* text = dynamic_cast<SoText2*>(group->getChild(group->getNumChildren() - 1));
            if (!move || !text) {
                ADD_FAILURE() << kind << " " << i << " is not a translated text";
                continue;
            }
            SbVec3f screen;
            volume.projectToScreen(move->translation.getValue(), screen);
            const glm::vec2 baseline(screen[0] * float(width), (1.0f - screen[1]) * float(height));
            DrawnLabel label;
            label.text = text->string[0].getString();
            label.name = std::string(kind) == "well_name";
            label.box = scenegraph::labelBox(
                baseline, label.text,
                label.name ? scenegraph::kNameSize_px : scenegraph::kLabelSize_px);
            labels.push_back(label);
        }
    }
    return labels;
}

// The leaders drawn from wells to their names placed apart (separators named "name_leader",
// their SoCoordinate3 holding the two ends), in pixels as drawnLabels places the labels.
inline std::vector<scenegraph::ScreenSegment> drawnLeaders(SoNode* root, const SoCamera& camera,
                                                           int width, int height) {
    const SbViewVolume volume = scenegraph::shownViewVolume(camera, float(width) / float(height));
    SoSearchAction search;
    search.setName("name_leader");
    search.setInterest(SoSearchAction::ALL);
    search.setSearchingAll(TRUE);
    search.apply(root);
    std::vector<scenegraph::ScreenSegment> leaders;
    const SoPathList& paths = search.getPaths();
    for (int i = 0; i < paths.getLength(); ++i) {
        auto* group = static_cast<SoSeparator*>(paths[i]->getTail());
        SoCoordinate3* ends = nullptr;
        for (int c = 0; c < group->getNumChildren() && !ends; ++c)
            ends = dynamic_cast<SoCoordinate3*>(group->getChild(c));
        if (!ends || ends->point.getNum() != 2) {
            ADD_FAILURE() << "leader " << i << " is not a line of two points";
            continue;
        }
        glm::vec2 pixel[2];
        for (int e = 0; e < 2; ++e) {
            SbVec3f screen;
            volume.projectToScreen(ends->point[e], screen);
            pixel[e] = glm::vec2(screen[0] * float(width), (1.0f - screen[1]) * float(height));
        }
        leaders.push_back({pixel[0], pixel[1]});
    }
    return leaders;
}

}  // namespace caliper3d::test
