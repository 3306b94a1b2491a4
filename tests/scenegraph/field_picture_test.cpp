// Pictures of a field of wells (scenegraph/picture): every label drawn keeps clear of the
// others. Drawn offscreen (EGL), then the labels are read back from what was drawn.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <Inventor/SbViewVolume.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoSeparator.h>

#include "coin_fixture.h"
#include "reconstruction/section/section_frame.h"
#include "reconstruction/synthetic/synthetic_field.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "reconstruction/well_geometry.h"
#include "reconstruction/well_path.h"
#include "scenegraph/camera_setup.h"
#include "scenegraph/label_style.h"
#include "scenegraph/offscreen_renderer.h"
#include "scenegraph/picture/picture.h"
#include "scenegraph/picture/png_file.h"
#include "scenegraph/picture_scale.h"
#include "scenegraph/render_stats.h"
#include "scenegraph/view_overlay.h"
#include "scenegraph/well_annotations.h"
#include "scenegraph/well_scene.h"
#include "support/drawn_labels.h"

namespace caliper3d::scenegraph {
namespace {

using Geometries = std::vector<std::shared_ptr<const reconstruction::WellGeometry>>;

// A field as `caliper3d synth --field N` lays it out (reconstruction::syntheticFieldWell:
// wellheads 25 m apart on a ring, each well drilled away from its centre), named FIELD-000, ...
// With `padSpacing_m` above 0 the wellheads stand instead on a pad, a grid of slots that far
// apart, four to a row (the wells still drilled outwards as on the ring).
Geometries syntheticField(std::size_t wells, double length_m, double step_m,
                          double padSpacing_m = 0.0) {
    Geometries field;
    for (std::size_t w = 0; w < wells; ++w) {
        const reconstruction::SyntheticFieldWell well =
            reconstruction::syntheticFieldWell(w, wells, length_m, step_m);
        auto table =
            std::make_shared<io::SectionTable>(reconstruction::makeSyntheticWell(well.spec));
        char name[32];
        std::snprintf(name, sizeof name, "FIELD-%03zu", w);
        table->wellName = name;
        reconstruction::GeometryOptions options;
        options.wellheadOffset = {well.north_m, well.east_m, 0.0};
        if (padSpacing_m > 0.0)
            options.wellheadOffset = {double(w / 4) * padSpacing_m, double(w % 4) * padSpacing_m,
                                      0.0};
        field.push_back(std::make_shared<reconstruction::WellGeometry>(table, options));
    }
    // Drawn as render draws them: at the exaggeration chosen for the picture.
    const double factor = chooseExaggeration(field, 0.0, 1.0e300, 768);
    for (auto& well : field)
        well = std::make_shared<reconstruction::WellGeometry>(
            well->restyled(factor, well->options().colouring));
    return field;
}

using test::DrawnLabel;
using test::drawnLabels;

// Where each well's wellhead (MD 0) lands in the picture, through `camera`'s own view volume.
std::vector<glm::vec2> projectedWellheads(const Geometries& field, const SoCamera& camera,
                                          int width, int height) {
    const SbViewVolume volume =
        const_cast<SoCamera&>(camera).getViewVolume(float(width) / float(height));
    std::vector<glm::vec2> heads;
    for (const auto& well : field) {
        const glm::vec3 head(reconstruction::toScene(reconstruction::pathAt(*well, 0.0).position));
        SbVec3f screen;
        volume.projectToScreen(SbVec3f(head.x, head.y, head.z), screen);
        heads.emplace_back(screen[0] * float(width), (1.0f - screen[1]) * float(height));
    }
    return heads;
}

// Pixels of `colour` (within 8 of 255 a channel) that lie in none of `boxes`.
int pixelsOutside(const RenderedImage& image, const float colour[3],
                  const std::vector<ScreenBox>& boxes) {
    int count = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = &image.rgba[(std::size_t(y) * image.width + x) * 4];
            bool close = true;
            for (int c = 0; c < 3; ++c)
                close = close && std::abs(int(p[c]) - int(colour[c] * 255.0f + 0.5f)) <= 8;
            if (!close) continue;
            // A pixel's centre; RenderedImage rows run from the top.
            const float cx = float(x) + 0.5f, cy = float(y) + 0.5f;
            bool inside = false;
            for (const ScreenBox& b : boxes)
                inside = inside || (cx >= b.x0 && cx <= b.x1 && cy >= b.y0 && cy <= b.y1);
            count += inside ? 0 : 1;
        }
    return count;
}

// `picture` drawn again with every well's wall (its segment group) taken out for the
// while: the annotations, overlay and paths as they were.
RenderedImage withoutWalls(const Picture& picture, const std::vector<PictureWell>& wells, int width,
                           int height) {
    struct Hidden {
        SoSeparator* root;
        SoNode* segments;
        int index;
    };
    std::vector<Hidden> hidden;
    for (const PictureWell& well : wells) {
        SoSeparator* root = well.scene->root();
        auto* segments = const_cast<SoSeparator*>(well.scene->segmentGroup());
        segments->ref();
        const int index = root->findChild(segments);
        root->removeChild(index);
        hidden.push_back({root, segments, index});
    }
    OffscreenRenderer renderer;
    RenderedImage bare = renderer.render(picture.root.get(), width, height, kBackgroundColour);
    for (const Hidden& h : hidden) {
        h.root->insertChild(h.segments, h.index);
        h.segments->unref();
    }
    return bare;
}

// How far `p` lies from `box` (0 inside it), pixels.
float distanceToBox(glm::vec2 p, const ScreenBox& box) {
    const glm::vec2 nearest(std::clamp(p.x, box.x0, box.x1), std::clamp(p.y, box.y0, box.y1));
    return glm::length(nearest - p);
}

// Whether `leader` joins a wellhead at `head` to its name in `box`: it starts beside the
// wellhead (outside its 9 px marker, within 16 px), points away from it and ends on the box's
// edge.
bool joins(const ScreenSegment& leader, glm::vec2 head, const ScreenBox& box) {
    const float start = glm::length(leader.a - head);
    return start > 4.5f && start < 16.0f && glm::length(leader.b - head) > start &&
           distanceToBox(leader.b, box) < 1.5f;
}

// `wells` (of `field`) drawn from `view` as render draws them, written to
// $FIELD_PICTURE_DUMP/NAME.png when set; without a root when no offscreen context could be
// made (the failure said).
Picture drawField(const std::vector<PictureWell>& wells, const Geometries& field,
                  ViewDirection view, int width, int height, const std::string& name) {
    PictureRequest request;
    request.width = width;
    request.height = height;
    request.view = view;
    request.unloggedPath = true;
    request.radialExaggeration = field.front()->options().radialExaggeration;
    Picture picture;
    try {
        picture = drawPicture(wells, request);
    } catch (const std::runtime_error& e) {
        ADD_FAILURE() << e.what();
        return picture;
    }
    if (const char* dump = std::getenv("FIELD_PICTURE_DUMP"))
        writePng(picture.image, std::string(dump) + "/" + name + ".png");
    return picture;
}

class FieldPictureTest : public CoinTest {};

TEST_F(FieldPictureTest, NoTwoLabelsOfAFieldOverlapInAnyView) {
    const Geometries field = syntheticField(16, 300.0, 0.5);
    const std::vector<PictureWell> wells = pictureWells(field);
    const int width = 1024, height = 768;
    for (const ViewDirection view :
         {ViewDirection::Iso, ViewDirection::North, ViewDirection::East, ViewDirection::Top}) {
        SCOPED_TRACE("view " + std::to_string(int(view)));
        const Picture picture =
            drawField(wells, field, view, width, height, "view" + std::to_string(int(view)));
        ASSERT_NE(picture.root.get(), nullptr);
        const SoCamera* camera = findCamera(picture.root.get());
        ASSERT_NE(camera, nullptr);
        const std::vector<DrawnLabel> labels =
            drawnLabels(picture.root.get(), *camera, width, height);
        int names = 0, depths = 0;
        for (const DrawnLabel& label : labels) (label.name ? names : depths) += 1;
        // Wells are named where there is room (at least 6 of 16, their wellheads 25 m
        // apart), and the first well's depths are labelled (three from the top, where its
        // upper, vertical part is foreshortened).
        EXPECT_GE(names, 6);
        EXPECT_GE(depths, 3);
        // Every wellhead is in the picture; the caption's last line counts the names left out.
        EXPECT_EQ(picture.names.inView, field.size());
        EXPECT_EQ(picture.names.inView - picture.names.leftOut, std::size_t(names));
        const std::vector<std::string> caption = picture.overlay->caption();
        ASSERT_FALSE(caption.empty());
        if (picture.names.leftOut > 0)
            EXPECT_EQ(caption.back(), std::to_string(picture.names.leftOut) + " of 16 names " +
                                          "left out: no room");
        else
            EXPECT_EQ(caption.back().rfind("radii", 0), 0u) << caption.back();
        const ScreenBox frame{0.0f, 0.0f, float(width), float(height)};
        std::vector<ScreenBox> boxes;
        for (std::size_t i = 0; i < labels.size(); ++i) {
            EXPECT_TRUE(contains(frame, labels[i].box)) << labels[i].text;
            for (std::size_t j = 0; j < i; ++j)
                EXPECT_FALSE(overlaps(labels[i].box, labels[j].box))
                    << "'" << labels[i].text << "' meets '" << labels[j].text << "'";
            for (const ScreenBox& overlay : picture.overlay->occupied(height))
                EXPECT_FALSE(overlaps(labels[i].box, overlay)) << labels[i].text;
            boxes.push_back(labels[i].box);
        }
        // The boxes are what was drawn: no pixel of a label's colour lies outside them (the
        // caption, in the label colour, is the overlay's; the wellheads' markers, 9 px
        // across, are in the name's colour).
        for (const ScreenBox& overlay : picture.overlay->occupied(height)) boxes.push_back(overlay);
        for (const glm::vec2& head : projectedWellheads(field, *camera, width, height))
            boxes.push_back({head.x - 5.5f, head.y - 5.5f, head.x + 5.5f, head.y + 5.5f});
        EXPECT_EQ(pixelsOutside(picture.image, kNameColour, boxes), 0);
        // The label colour, a near white, is also a lit wall's highlight: it is read from the
        // same picture drawn again without the wells' walls.
        EXPECT_EQ(pixelsOutside(withoutWalls(picture, wells, width, height), kLabelColour, boxes),
                  0);
    }
}

TEST_F(FieldPictureTest, AMapNamesEveryWellBesideItsWellhead) {
    const Geometries field = syntheticField(16, 300.0, 0.5);
    const std::vector<PictureWell> wells = pictureWells(field);
    const int width = 1024, height = 768;
    const Picture picture = drawField(wells, field, ViewDirection::Map, width, height, "map");
    ASSERT_NE(picture.root.get(), nullptr);
    const SoCamera* camera = findCamera(picture.root.get());
    ASSERT_NE(camera, nullptr);
    // Looking straight down, north up the picture.
    SbVec3f look, up;
    camera->orientation.getValue().multVec(SbVec3f(0, 0, -1), look);
    camera->orientation.getValue().multVec(SbVec3f(0, 1, 0), up);
    EXPECT_NEAR(look[1], -1.0f, 1e-5f);
    EXPECT_NEAR(up[2], -1.0f, 1e-5f);  // scene z is south
    const std::vector<glm::vec2> heads = projectedWellheads(field, *camera, width, height);
    for (const glm::vec2& head : heads)
        EXPECT_TRUE(head.x > 0.0f && head.x < float(width) && head.y > 0.0f &&
                    head.y < float(height))
            << "every wellhead in the picture";
    // Each wellhead lies where its offset from the first puts it: right of it when east,
    // above it when north (the ring's wells are 10 m or more apart in one of the two).
    for (std::size_t w = 1; w < heads.size(); ++w) {
        const glm::dvec3 offset = field[w]->options().wellheadOffset;
        if (std::abs(offset.y) > 10.0) {
            EXPECT_EQ(heads[w].x > heads[0].x, offset.y > 0.0) << "well " << w << " east";
        }
        if (std::abs(offset.x) > 10.0) {
            EXPECT_EQ(heads[w].y<heads[0].y, offset.x> 0.0) << "well " << w << " north";
        }
    }
    const std::vector<ScreenSegment> leaders =
        test::drawnLeaders(picture.root.get(), *camera, width, height);
    int named = 0;
    for (const DrawnLabel& label : drawnLabels(picture.root.get(), *camera, width, height)) {
        if (!label.name) continue;
        ++named;
        const std::size_t well = std::stoul(label.text.substr(label.text.find('-') + 1));
        ASSERT_LT(well, heads.size()) << label.text;
        // The box's nearest point to the wellhead: beside it, clear of its marker; or apart
        // from it, joined to it by a leader.
        const glm::vec2 head = heads[well];
        const float apart = distanceToBox(head, label.box);
        EXPECT_GE(apart, 4.5f) << label.text;
        if (apart > 30.0f) {
            EXPECT_TRUE(std::any_of(
                leaders.begin(), leaders.end(),
                [&](const ScreenSegment& leader) { return joins(leader, head, label.box); }))
                << label.text << " is " << apart << " px from its wellhead, with no leader";
        }
    }
    EXPECT_GE(named, 14);
}

// A pad: eight wellheads 5 m apart, each well drilled its own way. Seen from above the
// wellheads crowd together, and names enclosed by their neighbours' are placed apart: every
// well is named, each leader runs from its own wellhead to its own name, and no leader meets
// a label, a wellhead's marker or another leader.
TEST_F(FieldPictureTest, APadSeenFromAboveNamesEveryWellWithLeadersThatCrossNothing) {
    const Geometries field = syntheticField(8, 300.0, 0.5, 5.0);
    const std::vector<PictureWell> wells = pictureWells(field);
    const int width = 800, height = 600;
    const Picture picture = drawField(wells, field, ViewDirection::Map, width, height, "pad");
    ASSERT_NE(picture.root.get(), nullptr);
    const SoCamera* camera = findCamera(picture.root.get());
    ASSERT_NE(camera, nullptr);
    const std::vector<glm::vec2> heads = projectedWellheads(field, *camera, width, height);
    // Crowded: no wellhead is a name's length from the next, so eight sides cannot take them all.
    float widest = 0.0f;
    for (std::size_t a = 0; a < heads.size(); ++a)
        for (std::size_t b = 0; b < a; ++b)
            widest = std::max(widest, glm::length(heads[a] - heads[b]));
    EXPECT_LT(widest, 200.0f);
    std::vector<DrawnLabel> names;
    for (const DrawnLabel& label : drawnLabels(picture.root.get(), *camera, width, height))
        if (label.name) names.push_back(label);
    const std::vector<ScreenSegment> leaders =
        test::drawnLeaders(picture.root.get(), *camera, width, height);
    EXPECT_EQ(names.size(), field.size()) << "every well named";
    EXPECT_GE(leaders.size(), 1u) << "the pad needs names placed apart";
    for (std::size_t i = 0; i < names.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            EXPECT_FALSE(overlaps(names[i].box, names[j].box))
                << "'" << names[i].text << "' meets '" << names[j].text << "'";
    for (std::size_t l = 0; l < leaders.size(); ++l) {
        const ScreenSegment& leader = leaders[l];
        // Whose: the name box its far end lies on, and that well's wellhead at its near end.
        std::size_t owner = names.size();
        for (std::size_t i = 0; i < names.size(); ++i)
            if (distanceToBox(leader.b, names[i].box) < 1.5f) owner = i;
        ASSERT_LT(owner, names.size()) << "leader " << l << " ends on no name";
        const std::size_t well =
            std::stoul(names[owner].text.substr(names[owner].text.find('-') + 1));
        ASSERT_LT(well, heads.size());
        EXPECT_TRUE(joins(leader, heads[well], names[owner].box)) << names[owner].text;
        // Clear of the other names (a 1 px tolerance for the projection), the other wellheads'
        // markers and the other leaders.
        for (std::size_t i = 0; i < names.size(); ++i) {
            if (i != owner) {
                EXPECT_FALSE(crosses(leader, names[i].box, -1.0f))
                    << names[owner].text << "'s leader crosses " << names[i].text;
            }
        }
        for (std::size_t h = 0; h < heads.size(); ++h) {
            if (h != well) {
                EXPECT_FALSE(crosses(leader, {heads[h].x - 4.5f, heads[h].y - 4.5f,
                                              heads[h].x + 4.5f, heads[h].y + 4.5f}))
                    << names[owner].text << "'s leader crosses well " << h << "'s marker";
            }
        }
        for (std::size_t k = 0; k < l; ++k)
            EXPECT_FALSE(crosses(leader, leaders[k])) << "leaders " << k << " and " << l;
    }
}

// The wells of `synth --field` never come closer than their wellheads' spacing, however they
// build and turn (as planned wells keep apart), so a picture of the field shows their shapes:
// the exaggeration its spacing allows, 0.5 x 25 m over two radii of at most 0.13 m, is 30.
TEST(SyntheticFieldSpacingTest, NoTwoWellsComeCloserThanTheirWellheadsAndTheFieldIsExaggerated) {
    Geometries field;
    for (std::size_t w = 0; w < 20; ++w) {
        const reconstruction::SyntheticFieldWell well =
            reconstruction::syntheticFieldWell(w, 20, 1000.0, 2.0);
        reconstruction::GeometryOptions options;
        options.wellheadOffset = {well.north_m, well.east_m, 0.0};
        field.push_back(std::make_shared<reconstruction::WellGeometry>(
            std::make_shared<io::SectionTable>(reconstruction::makeSyntheticWell(well.spec)),
            options));
    }
    double closest = 1e300;
    for (std::size_t a = 0; a < field.size(); ++a)
        for (std::size_t b = 0; b < a; ++b)
            closest = std::min(closest, closestApproach_m(*field[a], *field[b], 0.0, 1e300));
    EXPECT_GE(closest, 0.99 * reconstruction::kSyntheticFieldSpacing_m);
    EXPECT_EQ(chooseExaggeration(field, 0.0, 1e300, 800), 30.0);
}

TEST_F(FieldPictureTest, OnlyTheTickedWellOfSeveralCarriesDepthTicks) {
    const Geometries field = syntheticField(4, 200.0, 0.5);
    const std::vector<PictureWell> wells = pictureWells(field);
    PictureRequest request;
    request.width = 640;
    request.height = 480;
    request.view = ViewDirection::North;
    request.tickedWell = 2;
    Picture picture;
    try {
        picture = drawPicture(wells, request);
    } catch (const std::runtime_error& e) {
        FAIL() << e.what();
    }
    SoSearchAction search;
    search.setName("tick_marks");
    search.setInterest(SoSearchAction::ALL);
    search.setSearchingAll(TRUE);
    search.apply(picture.root.get());
    ASSERT_EQ(search.getPaths().getLength(), 1);
    // The marks drawn start on well 2's path, at its first tick (the same depths for every
    // well: they are equally long), and on no other well's.
    auto* marks = static_cast<SoSeparator*>(search.getPaths()[0]->getTail());
    SoCoordinate3* points = nullptr;
    for (int i = 0; i < marks->getNumChildren() && !points; ++i)
        points = dynamic_cast<SoCoordinate3*>(marks->getChild(i));
    ASSERT_NE(points, nullptr);
    const SbVec3f first = points->point[0];
    for (std::size_t w = 0; w < field.size(); ++w) {
        const std::vector<DepthTick> ticks = depthTicks(*field[w], AnnotationView{});
        ASSERT_FALSE(ticks.empty());
        const float apart =
            glm::length(glm::vec3(first[0], first[1], first[2]) - ticks.front().position);
        if (w == 2)
            EXPECT_LT(apart, 1e-3f);
        else
            EXPECT_GT(apart, 20.0f) << "well " << w;
    }
}

TEST_F(FieldPictureTest, AFieldBuiltFromItsCoarsestLevelDrawsEveryPictureTheSame) {
    // `render` of a field builds only each segment's coarsest level up front
    // (reconstruction::kFieldFirstCoarseLevel) and what its camera needs before it draws: the
    // overview and the view down a hole are, pixel for pixel, those of a field built with
    // the finer coarse level too.
    const Geometries field = syntheticField(4, 120.0, 0.1);
    auto built = [&](int firstLevel) {
        std::vector<PictureWell> wells;
        for (const auto& geometry : field) {
            auto scene = std::make_shared<WellScene>();
            scene->buildAll(*geometry, firstLevel);
            wells.push_back({geometry, std::move(scene)});
        }
        return wells;
    };
    PictureRequest overview;
    overview.width = 640;
    overview.height = 400;
    overview.view = ViewDirection::Iso;
    overview.radialExaggeration = field.front()->options().radialExaggeration;
    PictureRequest hole = overview;
    hole.pose = downHolePose(*field.front(), 30.0);
    hole.top_m = 30.0;
    hole.bottom_m = 30.0 + hole.pose->fogVisibility_m;
    hole.tickMarks = false;
    for (const PictureRequest& request : {overview, hole}) {
        SCOPED_TRACE(request.pose ? "down the hole" : "overview");
        const std::vector<PictureWell> finer = built(reconstruction::kFirstCoarseLevel);
        const std::vector<PictureWell> coarsest = built(reconstruction::kFieldFirstCoarseLevel);
        Picture a, b;
        try {
            a = drawPicture(finer, request);
            b = drawPicture(coarsest, request);
        } catch (const std::runtime_error& e) {
            FAIL() << e.what();
        }
        ASSERT_EQ(a.image.rgba.size(), b.image.rgba.size());
        EXPECT_TRUE(a.image.rgba == b.image.rgba);
        // Down the hole the camera needed finer levels, and both built them.
        if (request.pose) {
            EXPECT_GT(b.refinedSegments, 0u);
        }
        // Not two empty pictures: the walls fill a good part of each.
        std::size_t drawn = 0;
        for (std::size_t i = 0; i + 3 < b.image.rgba.size(); i += 4)
            drawn += std::abs(int(b.image.rgba[i]) - int(kBackgroundColour[0] * 255.0f + 0.5f)) > 8
                         ? 1
                         : 0;
        EXPECT_GT(drawn, b.image.rgba.size() / 4 / 50);
    }
}

}  // namespace
}  // namespace caliper3d::scenegraph
