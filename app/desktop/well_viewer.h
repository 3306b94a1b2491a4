#pragma once

#include <chrono>
#include <functional>
#include <optional>

#include <QTimer>

#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>
#include <Inventor/SbVec2s.h>

#include "reconstruction/mesh/wall_colouring.h"
#include "scenegraph/colour_legend.h"

class SoSceneManager;
class SoSeparator;

namespace caliper3d::app {

// The examiner viewer of the window, with the legend of the wall's colours drawn over the
// scene as a superimposition (SoQtViewer's own overlay: it is not part of the scene graph,
// so it adds nothing to "view all" nor to a picked path).
class WellViewer : public SoQtExaminerViewer {
public:
    explicit WellViewer(QWidget* parent);
    ~WellViewer() override;
    WellViewer(const WellViewer&) = delete;
    WellViewer& operator=(const WellViewer&) = delete;

    // Shows `legend` (replacing the one shown); null hides it.
    void setLegend(const reconstruction::ColourLegend* legend);
    // The legend's overlay, null when none is shown (tests).
    SoSeparator* legendNode() const { return m_legend; }
    // The legend's panel in the view's pixels (from its top-left corner), as drawn: what the
    // wells' labels keep clear of. Nothing when no legend is shown.
    std::optional<scenegraph::ScreenBox> legendPanel() const;
    // Called with the pixel (Coin's: origin at the bottom left) of a left click that did not
    // drag: a drag turns the camera, a click picks.
    void onClick(std::function<void(const SbVec2s& pixel)> callback) {
        m_onClick = std::move(callback);
    }
    // While `interval` is above zero, the frames a change of the scene asks for come at most one
    // an interval, the first at once and the last of them always (a field's load changes the scene
    // for every well it draws, and each frame took the cores the load reads with:
    // docs/architecture.md, "Frames while a field loads"). Frames asked for within kInputFree of
    // the user's own input (a turn, a zoom, a click) or while the camera spins are drawn at once;
    // so is render().
    void limitFrames(std::chrono::milliseconds interval);
    std::chrono::milliseconds frameLimit() const { return m_frameInterval; }
    // Frames the scene's changes drew since the viewer was made (tests).
    int framesDrawn() const { return m_framesDrawn; }

protected:
    SbBool processSoEvent(const SoEvent* event) override;
    void sizeChanged(const SbVec2s& size) override;

private:
    using Clock = std::chrono::steady_clock;
    static constexpr std::chrono::milliseconds kInputFree{500};
    static void sceneChanged(void* self, SoSceneManager* manager);
    void frameWhenDue();

    static constexpr int kClickSlop_px = 3;  // a press and release this close is a click
    // In the lower half of the view: the wells' names are at its top.
    static constexpr scenegraph::LegendBar kLegendBar = scenegraph::kLowerLegendBar;
    SoSeparator* m_legend = nullptr;  // referenced while shown
    std::optional<reconstruction::ColourLegend> m_shownLegend;
    short m_legendHeight = 0;  // the view's height the legend was laid out for
    std::function<void(const SbVec2s&)> m_onClick;
    SbVec2s m_pressedAt{-1000, -1000};
    std::chrono::milliseconds m_frameInterval{0};
    Clock::time_point m_lastFrame{}, m_lastInput{};
    QTimer m_laterFrame;  // single shot: the frame held back
    int m_framesDrawn = 0;
};

}  // namespace caliper3d::app
