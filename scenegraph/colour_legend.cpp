#include "scenegraph/colour_legend.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <Inventor/SbMatrix.h>
#include <Inventor/actions/SoAction.h>
#include <Inventor/elements/SoModelMatrixElement.h>
#include <Inventor/elements/SoViewportRegionElement.h>
#include <Inventor/misc/SoState.h>
#include <Inventor/nodes/SoAnnotation.h>
#include <Inventor/nodes/SoBaseColor.h>
#include <Inventor/nodes/SoCallback.h>
#include <Inventor/nodes/SoFont.h>
#include <Inventor/nodes/SoIndexedTriangleStripSet.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoOrthographicCamera.h>
#include <Inventor/nodes/SoPickStyle.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoText2.h>
#include <Inventor/nodes/SoTranslation.h>

#include "reconstruction/mesh/mesh.h"
#include "scenegraph/label_style.h"
#include "scenegraph/main_thread.h"
#include "scenegraph/segment_node_builder.h"

namespace caliper3d::scenegraph {

namespace {

using reconstruction::ColourMapKind;

// Layout: up, the overlay camera's frame (the viewport is [-1, 1] whatever its aspect,
// LEAVE_ALONE); across, pixels from the right edge (inPixelsFromRight), text growing
// leftwards from its anchor (RIGHT).
constexpr float kBarLeft_px = -32.0f, kBarRight_px = -19.0f;
constexpr float kTextRight_px = -37.0f, kTitleRight_px = -10.0f;
constexpr float kPanelMargin_px = 10.0f;  // left of the longest line
constexpr float kFontSize_px = 13.0f;
constexpr int kBarSteps = 32;

// x in pixels from the viewport's right edge (negative leftwards), y as the camera's.
void inPixelsFromRight(void*, SoAction* action) {
    SoState* state = action->getState();
    if (!state->isElementEnabled(SoModelMatrixElement::getClassStackIndex()) ||
        !state->isElementEnabled(SoViewportRegionElement::getClassStackIndex()))
        return;
    const short width = SoViewportRegionElement::get(state).getViewportSizePixels()[0];
    SbMatrix scale, move;
    scale.setScale(SbVec3f(2.0f / static_cast<float>(std::max<short>(width, 1)), 1.0f, 1.0f));
    move.setTranslate(SbVec3f(1.0f, 0.0f, 0.0f));
    scale.multRight(move);
    SoModelMatrixElement::mult(state, nullptr, scale);
}

std::string withUnit(const std::string& text, const std::string& unit) {
    return unit.empty() ? text : text + " " + unit;
}

void addText(SoSeparator* parent, float x, float y, const std::string& text,
             SoText2::Justification justification = SoText2::RIGHT) {
    auto* group = new SoSeparator;
    auto* at = new SoTranslation;
    at->translation.setValue(x, y, 0.0f);
    auto* label = new SoText2;
    label->string = text.c_str();
    label->justification = justification;
    group->addChild(at);
    group->addChild(label);
    parent->addChild(group);
}

// A quad strip from bottom to top; `colours` one per row of two vertices.
SoIndexedTriangleStripSet* makeBar(float left, float right, const std::vector<float>& ys,
                                   const std::vector<std::uint32_t>& colours) {
    reconstruction::Mesh mesh;
    for (std::size_t i = 0; i < ys.size(); ++i) {
        mesh.positions.emplace_back(left, ys[i], 0.0f);
        mesh.positions.emplace_back(right, ys[i], 0.0f);
        mesh.colours.push_back(colours[i]);
        mesh.colours.push_back(colours[i]);
    }
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
        mesh.stripIndices.push_back(static_cast<std::int32_t>(i));
    mesh.stripIndices.push_back(-1);
    return makeStripSet(mesh);
}

std::uint32_t mapColour(const reconstruction::ColourLegend& legend, double t) {
    return legend.kind == ColourMapKind::Diverging ? reconstruction::divergingColour(t)
                                                   : reconstruction::sequentialColour(t);
}

}  // namespace

std::string legendNumber(double value) {
    if (!std::isfinite(value)) return "no value";
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    std::string s(text);
    if (s == "-0") s = "0";
    return s;
}

LegendText legendText(const reconstruction::ColourLegend& legend) {
    LegendText out;
    out.title = legend.unit.empty() ? legend.title : legend.title + " (" + legend.unit + ")";
    if (legend.kind == ColourMapKind::Categorical) {
        for (const auto& category : legend.categories) out.labels.push_back(category.first);
    } else {
        const double centre =
            legend.kind == ColourMapKind::Diverging ? 0.0 : (legend.lo + legend.hi) / 2.0;
        out.labels = {withUnit(legendNumber(legend.hi), legend.unit),
                      legend.kind == ColourMapKind::Diverging
                          ? "0 (" +
                                (!legend.centre.empty() ? legend.centre
                                 : legend.note.empty()  ? std::string("bit")
                                                        : std::string("gauge")) +
                                ")"
                          : withUnit(legendNumber(centre), legend.unit),
                      withUnit(legendNumber(legend.lo), legend.unit)};
        if (!legend.range.empty()) out.footer.push_back("range: " + legend.range);
    }
    if (!legend.note.empty()) out.footer.push_back(legend.note);
    if (legend.noValue) {
        std::string line = "dark grey: ";
        for (const char c :
             legend.noValueText.empty() ? std::string("no value") : legend.noValueText) {
            if (c != '\n') {
                line += c;
                continue;
            }
            out.footer.push_back(line);
            line.clear();
        }
        out.footer.push_back(line);
    }
    out.footer.emplace_back("gaps: no data");
    return out;
}

namespace {
// Up, the text is laid out in pixels from the bar (its bar is placed in fractions of the
// picture's height): in a tall view its lines are as close as in a short one.
constexpr float kTitleAbove_px = 19.0f;  // the title's baseline above the bar's top
constexpr float kPanelAbove_px = 37.0f;  // the panel's top above the bar's top
constexpr float kLine_px = 17.0f;        // one note line below the last
constexpr float kPanelBelow_px = 12.0f;  // the panel's bottom below the last note
constexpr float kLabelDrop_px = 5.0f;    // a label's baseline below the mark it names
constexpr float kMinBar_px = 60.0f;      // the bar is never shortened below this
// The panel ends this far inside the picture's top and bottom edges (the picture's height
// is 2).
constexpr float kPanelEdge = 0.99f;
// A note line is wrapped at a space to no more characters than the title has (within these
// bounds), so that a long range or note does not widen the panel over the scene (and a
// narrow view's caption and depth labels).
constexpr std::size_t kFooterMinChars = 20, kFooterMaxChars = 30;

// The legend's frame up the picture for one height: the bar's ends, the panel's, and the
// size of a pixel in the overlay camera's units.
struct Frame {
    float barTop = 0.0f, barBottom = 0.0f, panelTop = 0.0f, panelBottom = 0.0f, px = 0.0f;
    float noteY(std::size_t i) const { return barBottom - kLine_px * px * float(i + 1); }
};

// `line` cut at spaces into lines of at most `most` characters (a longer word stays whole).
std::vector<std::string> wrapped(const std::string& line, std::size_t most) {
    std::vector<std::string> lines;
    std::string current;
    std::size_t at = 0;
    while (at < line.size()) {
        const std::size_t space = line.find(' ', at);
        const std::size_t end = space == std::string::npos ? line.size() : space;
        const std::string word = line.substr(at, end - at);
        if (!current.empty() && current.size() + 1 + word.size() > most) {
            lines.push_back(current);
            current.clear();
        }
        current += current.empty() ? word : " " + word;
        at = end + 1;
    }
    lines.push_back(current);
    return lines;
}

// The legend's text as drawn: its notes wrapped.
LegendText laidOut(const reconstruction::ColourLegend& legend) {
    LegendText text = legendText(legend);
    std::vector<std::string> footer;
    for (const std::string& line : text.footer)
        for (std::string& part :
             wrapped(line, std::clamp(text.title.size(), kFooterMinChars, kFooterMaxChars)))
            footer.push_back(std::move(part));
    text.footer = std::move(footer);
    return text;
}

// `bar` in a picture `height` pixels tall: no longer than its most, then raised until the
// panel's last note ends inside the picture, and shortened when that would take its title
// out at the top.
Frame frameOf(const LegendText& text, LegendBar bar, int height) {
    Frame f;
    f.px = 2.0f / static_cast<float>(std::max(height, 1));
    if (bar.maxLength_px > 0.0f) bar.top = std::min(bar.top, bar.bottom + bar.maxLength_px * f.px);
    const float below_px = kLine_px * static_cast<float>(text.footer.size()) + kPanelBelow_px;
    const float raise = -kPanelEdge - (bar.bottom - below_px * f.px);
    if (raise > 0.0f) {
        bar.top = std::min(bar.top + raise, kPanelEdge - kPanelAbove_px * f.px);
        bar.bottom = std::min(bar.bottom + raise, bar.top - kMinBar_px * f.px);
    }
    f.barTop = bar.top;
    f.barBottom = bar.bottom;
    f.panelTop = bar.top + kPanelAbove_px * f.px;
    f.panelBottom = bar.bottom - below_px * f.px;
    return f;
}
}  // namespace

ScreenBox legendPanel_px(const reconstruction::ColourLegend& legend, int width, int height,
                         LegendBar bar) {
    const float w = static_cast<float>(width), h = static_cast<float>(height);
    const auto down = [h](float up) { return (1.0f - up) / 2.0f * h; };
    const Frame f = frameOf(laidOut(legend), bar, height);
    return {w - legendWidth_px(legend), down(f.panelTop), w, down(f.panelBottom)};
}

float legendWidth_px(const reconstruction::ColourLegend& legend) {
    const LegendText text = laidOut(legend);
    float width = textWidth_px(text.title, kFontSize_px) - kTitleRight_px;
    for (const std::string& line : text.footer)
        width = std::max(width, textWidth_px(line, kFontSize_px) - kTitleRight_px);
    for (const std::string& label : text.labels)
        width = std::max(width, textWidth_px(label, kFontSize_px) - kTextRight_px);
    return std::ceil(width + kPanelMargin_px);
}

SoSeparator* makeColourLegend(const reconstruction::ColourLegend& legend, int height,
                              LegendBar bar) {
    assertMainThread("makeColourLegend");
    const LegendText text = laidOut(legend);
    const Frame f = frameOf(text, bar, height);
    const float kBarTop = f.barTop, kBarBottom = f.barBottom;
    auto* root = new SoAnnotation;
    root->setName("colour_legend");
    auto* camera = new SoOrthographicCamera;
    camera->viewportMapping = SoCamera::LEAVE_ALONE;
    camera->position.setValue(0.0f, 0.0f, 1.0f);
    camera->height = 2.0f;
    camera->nearDistance = 0.5f;
    camera->farDistance = 1.5f;
    auto* pick = new SoPickStyle;
    pick->style = SoPickStyle::UNPICKABLE;  // picking a section never hits the legend
    auto* unlit = new SoLightModel;
    unlit->model = SoLightModel::BASE_COLOR;
    auto* font = new SoFont;
    font->name = "Sans";
    font->size = kFontSize_px;
    root->addChild(camera);
    root->addChild(pick);
    root->addChild(unlit);
    root->addChild(font);

    auto* pixels = new SoCallback;
    pixels->setCallback(inPixelsFromRight, nullptr);
    root->addChild(pixels);

    // A panel behind the legend so it reads over the wall, as wide as its longest line.
    root->addChild(makeBar(-legendWidth_px(legend), 0.0f, {f.panelBottom, f.panelTop},
                           {0x262B36FFu, 0x262B36FFu}));

    std::vector<float> ys;
    std::vector<std::uint32_t> colours;
    const int steps = legend.kind == ColourMapKind::Categorical
                          ? static_cast<int>(legend.categories.size())
                          : kBarSteps;
    const float step = (kBarTop - kBarBottom) / static_cast<float>(std::max(steps, 1));
    if (legend.kind == ColourMapKind::Categorical) {
        // One swatch a class, top to bottom in the legend's order.
        for (int i = 0; i < steps; ++i) {
            const float top = kBarTop - step * static_cast<float>(i);
            const std::uint32_t c = legend.categories[static_cast<std::size_t>(i)].second;
            root->addChild(makeBar(kBarLeft_px, kBarRight_px, {top - step * 0.85f, top}, {c, c}));
        }
    } else {
        for (int i = 0; i <= steps; ++i) {
            const double t = static_cast<double>(i) / steps;
            ys.push_back(kBarBottom + step * static_cast<float>(i));
            colours.push_back(mapColour(legend, t));
        }
        root->addChild(makeBar(kBarLeft_px, kBarRight_px, ys, colours));
    }

    auto* ink = new SoBaseColor;
    ink->rgb.setValue(0.92f, 0.93f, 0.95f);
    root->addChild(ink);
    addText(root, kTitleRight_px, kBarTop + kTitleAbove_px * f.px, text.title);
    const float drop = kLabelDrop_px * f.px;
    if (legend.kind == ColourMapKind::Categorical) {
        for (std::size_t i = 0; i < text.labels.size(); ++i) {
            const float top = kBarTop - step * static_cast<float>(i);
            addText(root, kTextRight_px, top - step * 0.425f - drop, text.labels[i]);
        }
    } else {
        const float ysOf[3] = {kBarTop, (kBarTop + kBarBottom) / 2.0f, kBarBottom};
        for (std::size_t i = 0; i < 3; ++i)
            addText(root, kTextRight_px, ysOf[i] - drop, text.labels[i]);
    }
    for (std::size_t i = 0; i < text.footer.size(); ++i)
        addText(root, kTitleRight_px, f.noteY(i), text.footer[i]);
    return root;
}

}  // namespace caliper3d::scenegraph
