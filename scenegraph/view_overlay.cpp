#include "scenegraph/view_overlay.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

#include <Inventor/SbMatrix.h>
#include <Inventor/SbViewVolume.h>
#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/elements/SoModelMatrixElement.h>
#include <Inventor/elements/SoViewVolumeElement.h>
#include <Inventor/elements/SoViewingMatrixElement.h>
#include <Inventor/elements/SoViewportRegionElement.h>
#include <Inventor/misc/SoState.h>
#include <Inventor/nodes/SoBaseColor.h>
#include <Inventor/nodes/SoCallback.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoDepthBuffer.h>
#include <Inventor/nodes/SoDrawStyle.h>
#include <Inventor/nodes/SoFont.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoLineSet.h>
#include <Inventor/nodes/SoOrthographicCamera.h>
#include <Inventor/nodes/SoText2.h>
#include <Inventor/nodes/SoTranslation.h>

#include "scenegraph/camera_setup.h"
#include "scenegraph/drawn_only.h"
#include "scenegraph/label_style.h"
#include "scenegraph/main_thread.h"

namespace caliper3d::scenegraph {

// A letter at the end of one of the arrow's arms.
struct ArmLetter {
    const SbMatrix* rotation = nullptr;  // the scene camera's, as last drawn
    SbVec3f at;                          // arrow units, scene frame
    SbVec3f foreshortenedAt;             // arrow units, across and up the picture
};

// The rotation part of the scene camera's viewing matrix, as last drawn.
struct ViewOverlay::SceneCamera {
    SbMatrix rotation = SbMatrix::identity();
    ArmLetter north, east;
};

namespace {

// An arm seen at less than this fraction of its length across the picture is end on.
constexpr float kForeshortened = 0.45f;

bool drawing(SoAction* action) {
    return action->isOfType(SoGLRenderAction::getClassTypeId());
}

void keepSceneCamera(void* data, SoAction* action) {
    if (!drawing(action)) return;
    SbMatrix view = SoViewingMatrixElement::get(action->getState());
    view[3][0] = view[3][1] = view[3][2] = 0.0f;  // the rotation only
    *static_cast<SbMatrix*>(data) = view;
}

// Scene units per pixel of the overlay's camera, and its bottom-left corner.
struct Pixels {
    float unit = 1.0f;
    SbVec3f corner;
};
Pixels pixelsOf(SoState* state) {
    const SbViewVolume& volume = SoViewVolumeElement::get(state);
    const SbVec2s size = SoViewportRegionElement::get(state).getViewportSizePixels();
    Pixels p;
    p.unit = volume.getHeight() / static_cast<float>(std::max<short>(size[1], 1));
    p.corner.setValue(-volume.getWidth() / 2.0f, -volume.getHeight() / 2.0f, 0.0f);
    return p;
}

// The arrow: world directions turned as the scene camera sees them, a fixed size in
// pixels, in the corner.
void placeArrow(void* data, SoAction* action) {
    if (!drawing(action)) return;
    SoState* state = action->getState();
    const Pixels p = pixelsOf(state);
    SbMatrix scale, move;
    scale.setScale(ViewOverlay::kArrowLength_px * p.unit);
    move.setTranslate(p.corner +
                      SbVec3f(1.0f, 1.0f, 0.0f) * (ViewOverlay::kArrowCentre_px * p.unit));
    SbMatrix m = *static_cast<const SbMatrix*>(data);
    m.multRight(scale);
    m.multRight(move);
    SoModelMatrixElement::mult(state, nullptr, m);
}

// An arm seen end on (looking north, the north arm points into the picture) would put its
// letter on the arrow's centre, over the other letter: it goes beside the centre instead.
void placeLetter(void* data, SoAction* action) {
    if (!drawing(action)) return;
    const auto& letter = *static_cast<const ArmLetter*>(data);
    SbVec3f seen;
    letter.rotation->multDirMatrix(letter.at, seen);
    const float across = std::hypot(seen[0], seen[1]);
    if (across >= kForeshortened * letter.at.length()) return;
    SbVec3f local;
    letter.rotation->inverse().multDirMatrix(letter.foreshortenedAt, local);
    SoModelMatrixElement::translateBy(action->getState(), nullptr, local - letter.at);
}

// Pixels from the bottom-left corner, for the caption.
void placePixels(void*, SoAction* action) {
    if (!drawing(action)) return;
    SoState* state = action->getState();
    const Pixels p = pixelsOf(state);
    SbMatrix scale, move;
    scale.setScale(p.unit);
    move.setTranslate(p.corner);
    scale.multRight(move);
    SoModelMatrixElement::mult(state, nullptr, scale);
}

SoSeparator* makeLines(const float colour[3], float width,
                       const std::vector<std::vector<SbVec3f>>& strips) {
    auto* group = new SoSeparator;
    auto* style = new SoDrawStyle;
    style->lineWidth = width;
    auto* rgb = new SoBaseColor;
    rgb->rgb.setValue(colour);
    auto* points = new SoCoordinate3;
    auto* lines = new SoLineSet;
    lines->numVertices.setNum(0);  // its default, -1, joins every point into one line
    int n = 0;
    for (const auto& strip : strips) {
        for (const SbVec3f& p : strip) points->point.set1Value(n++, p);
        lines->numVertices.set1Value(lines->numVertices.getNum(), static_cast<int>(strip.size()));
    }
    group->addChild(style);
    group->addChild(rgb);
    group->addChild(points);
    group->addChild(lines);
    return group;
}

// A letter centred on `at` (arrow units).
SoSeparator* letterAt(const char* letter, const SbVec3f& at, const float colour[3]) {
    auto* group = new SoSeparator;
    auto* move = new SoTranslation;
    move->translation = at;
    auto* rgb = new SoBaseColor;
    rgb->rgb.setValue(colour);
    auto* text = new SoText2;
    text->string = letter;
    text->justification = SoText2::CENTER;
    group->addChild(move);
    group->addChild(rgb);
    group->addChild(makeLabelFont(kLabelSize_px));
    group->addChild(text);
    return group;
}

}  // namespace

ViewOverlay::ViewOverlay() : m_camera(std::make_unique<SceneCamera>()) {
    assertMainThread("ViewOverlay");
    auto* content = new SoSeparator;
    auto* keep = new SoCallback;
    keep->setCallback(keepSceneCamera, &m_camera->rotation);
    auto* camera = new SoOrthographicCamera;
    camera->position.setValue(0.0f, 0.0f, 10.0f);
    camera->height = 2.0f;
    camera->nearDistance = 1.0f;
    camera->farDistance = 20.0f;
    auto* over = new SoDepthBuffer;
    over->test = FALSE;
    over->write = FALSE;
    auto* unlit = new SoLightModel;
    unlit->model = SoLightModel::BASE_COLOR;
    content->addChild(keep);
    content->addChild(camera);
    content->addChild(over);
    content->addChild(unlit);

    // Scene frame: x east, y up, z south; the arrow lies in the horizontal plane.
    auto* arrow = new SoSeparator;
    arrow->setName("north_arrow");
    auto* place = new SoCallback;
    place->setCallback(placeArrow, &m_camera->rotation);
    arrow->addChild(place);
    constexpr float kGrey[3] = {0.62f, 0.64f, 0.68f};
    constexpr float kNorth[3] = {0.95f, 0.30f, 0.25f};
    arrow->addChild(makeLines(
        kGrey, 1.5f,
        {{SbVec3f(-0.55f, 0, 0), SbVec3f(0.55f, 0, 0)}, {SbVec3f(0, 0, 0), SbVec3f(0, 0, 0.55f)}}));
    arrow->addChild(
        makeLines(kNorth, 2.5f,
                  {{SbVec3f(0, 0, 0), SbVec3f(0, 0, -1.0f)},
                   {SbVec3f(-0.18f, 0, -0.72f), SbVec3f(0, 0, -1.0f), SbVec3f(0.18f, 0, -0.72f)}}));
    // East named too: looking north, the north arm points into the picture. A letter whose
    // arm is seen end on goes under the centre (N) or above it (E), clear of the other.
    m_camera->north = {&m_camera->rotation, SbVec3f(0.0f, 0.0f, -1.3f), SbVec3f(0.0f, -0.9f, 0.0f)};
    m_camera->east = {&m_camera->rotation, SbVec3f(0.8f, 0.0f, 0.0f), SbVec3f(0.0f, 0.75f, 0.0f)};
    for (auto [letter, arm, colour] :
         {std::tuple{"N", &m_camera->north, kNorth}, std::tuple{"E", &m_camera->east, kGrey}}) {
        SoSeparator* text = letterAt(letter, arm->at, colour);
        auto* beside = new SoCallback;
        beside->setCallback(placeLetter, arm);
        text->insertChild(beside, 0);
        arrow->addChild(text);
    }
    content->addChild(arrow);

    // The caption beside the arrow, outlined in the background colour: legible over a wall
    // (looking down the hole) as over the background, without hiding what lies behind it.
    auto* pixels = new SoSeparator;
    pixels->setName("caption");
    auto* inPixels = new SoCallback;
    inPixels->setCallback(placePixels, nullptr);
    auto* beside = new SoTranslation;
    beside->translation.setValue(kCaptionLeft_px, kArrowCentre_px - 5.0f, 0.0f);
    pixels->addChild(inPixels);
    pixels->addChild(beside);
    pixels->addChild(makeLabelFont(kLabelSize_px));
    m_caption = new SoText2;
    m_caption->string.setNum(0);
    auto* dark = new SoBaseColor;
    dark->rgb.setValue(kBackgroundColour);
    pixels->addChild(dark);
    for (const SbVec3f& offset :
         {SbVec3f(-1, -1, 0), SbVec3f(1, -1, 0), SbVec3f(-1, 1, 0), SbVec3f(1, 1, 0)}) {
        auto* halo = new SoSeparator;
        auto* shift = new SoTranslation;
        shift->translation = offset;
        auto* copy = new SoText2;
        copy->string.connectFrom(&m_caption->string);  // follows setCaption
        halo->addChild(shift);
        halo->addChild(copy);
        pixels->addChild(halo);
    }
    auto* captionColour = new SoBaseColor;
    captionColour->rgb.setValue(kLabelColour);
    pixels->addChild(captionColour);
    pixels->addChild(m_caption);
    content->insertChild(pixels, 4);  // after the camera and depth settings, before the arrow

    m_root = makeRef(makeDrawnOnly(content));
    m_root->setName("view_overlay");
}

ViewOverlay::~ViewOverlay() = default;

void ViewOverlay::setCaption(const std::vector<std::string>& lines) {
    assertMainThread("ViewOverlay::setCaption");
    m_caption->string.setNum(static_cast<int>(lines.size()));
    for (std::size_t i = 0; i < lines.size(); ++i)
        m_caption->string.set1Value(static_cast<int>(i), lines[i].c_str());
}

std::vector<std::string> ViewOverlay::caption() const {
    std::vector<std::string> lines;
    lines.reserve(static_cast<std::size_t>(m_caption->string.getNum()));
    for (int i = 0; i < m_caption->string.getNum(); ++i)
        lines.emplace_back(m_caption->string[i].getString());
    return lines;
}

std::vector<ScreenBox> ViewOverlay::occupied(int height) const {
    const float h = static_cast<float>(height);
    // The arrow's arms and letters lie within its length and a letter of its centre.
    const float reach = kArrowLength_px * 1.3f + kLabelSize_px;
    std::vector<ScreenBox> boxes{{kArrowCentre_px - reach, h - kArrowCentre_px - reach,
                                  kArrowCentre_px + reach, h - kArrowCentre_px + reach}};
    const int lines = m_caption->string.getNum();
    float width = 0.0f;
    for (int i = 0; i < lines; ++i)
        width = std::max(width, boldTextWidth_px(m_caption->string[i].getString(), kLabelSize_px));
    if (lines > 0) {
        // The first line's baseline kArrowCentre_px - 5 up from the bottom, the others below.
        const float baseline = h - (kArrowCentre_px - 5.0f);
        boxes.push_back({kCaptionLeft_px - 1.0f, baseline - kAscent_em * kLabelSize_px - 1.0f,
                         kCaptionLeft_px + width + 1.0f,
                         std::min(h, baseline + static_cast<float>(lines) * kLabelSize_px +
                                         kDescent_em * kLabelSize_px + 1.0f)});
    }
    return boxes;
}

std::string exaggerationCaption(double radialExaggeration) {
    if (std::abs(radialExaggeration - 1.0) < 1e-9) return "radii to scale";
    char text[48];
    std::snprintf(text, sizeof text, "radii x %g", radialExaggeration);
    return text;
}

}  // namespace caliper3d::scenegraph
