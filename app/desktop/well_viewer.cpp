#include "app/desktop/well_viewer.h"

#include <cstdlib>

#include <Inventor/SoSceneManager.h>
#include <Inventor/events/SoMouseButtonEvent.h>
#include <Inventor/nodes/SoSeparator.h>

#include "scenegraph/colour_legend.h"

namespace caliper3d::app {

WellViewer::WellViewer(QWidget* parent) : SoQtExaminerViewer(parent) {
    // The scene manager asks for a frame when the scene changes: through frameWhenDue, which
    // may hold it back (limitFrames), in place of the render area's own callback that draws
    // at once.
    getSceneManager()->setRenderCallback(&WellViewer::sceneChanged, this);
    m_laterFrame.setSingleShot(true);
    QObject::connect(&m_laterFrame, &QTimer::timeout, [this] { frameWhenDue(); });
}

void WellViewer::limitFrames(std::chrono::milliseconds interval) {
    // The first frame a limit sees is drawn at once (a field's first picture).
    if (m_frameInterval.count() <= 0) m_lastFrame = {};
    m_frameInterval = interval;
    // A frame held back comes now: no limit is left to wait for.
    if (interval.count() <= 0 && m_laterFrame.isActive()) {
        m_laterFrame.stop();
        frameWhenDue();
    }
}

void WellViewer::sceneChanged(void* self, SoSceneManager* /*manager*/) {
    static_cast<WellViewer*>(self)->frameWhenDue();
}

void WellViewer::frameWhenDue() {
    const Clock::time_point now = Clock::now();
    const auto since = now - m_lastFrame;
    if (m_frameInterval.count() > 0 && since < m_frameInterval && now - m_lastInput > kInputFree &&
        !isAnimating()) {
        if (!m_laterFrame.isActive())
            m_laterFrame.start(
                std::chrono::ceil<std::chrono::milliseconds>(m_frameInterval - since));
        return;
    }
    m_laterFrame.stop();
    m_lastFrame = now;
    ++m_framesDrawn;
    render();
}

WellViewer::~WellViewer() {
    // No frame asked of this viewer once it is going (its timer goes first).
    getSceneManager()->setRenderCallback(nullptr, nullptr);
    setLegend(nullptr);
}

void WellViewer::setLegend(const reconstruction::ColourLegend* legend) {
    if (m_legend) {
        removeSuperimposition(m_legend);
        m_legend->unref();
        m_legend = nullptr;
    }
    m_shownLegend.reset();
    if (legend) {
        m_legendHeight = getViewportRegion().getViewportSizePixels()[1];
        m_legend = scenegraph::makeColourLegend(*legend, m_legendHeight, kLegendBar);
        m_legend->ref();
        addSuperimposition(m_legend);
        m_shownLegend = *legend;
    }
    scheduleRedraw();
}

std::optional<scenegraph::ScreenBox> WellViewer::legendPanel() const {
    if (!m_shownLegend) return std::nullopt;
    const SbVec2s size = getViewportRegion().getViewportSizePixels();
    return scenegraph::legendPanel_px(*m_shownLegend, size[0], size[1], kLegendBar);
}

// The legend's text is laid out in pixels up the view: made again for a new height.
void WellViewer::sizeChanged(const SbVec2s& size) {
    SoQtExaminerViewer::sizeChanged(size);
    if (m_shownLegend && getViewportRegion().getViewportSizePixels()[1] != m_legendHeight) {
        const reconstruction::ColourLegend legend = *m_shownLegend;
        setLegend(&legend);
    }
}

SbBool WellViewer::processSoEvent(const SoEvent* event) {
    m_lastInput = Clock::now();
    if (m_onClick && event->isOfType(SoMouseButtonEvent::getClassTypeId())) {
        const auto* button = static_cast<const SoMouseButtonEvent*>(event);
        if (button->getButton() == SoMouseButtonEvent::BUTTON1) {
            const SbVec2s at = event->getPosition();
            if (button->getState() == SoButtonEvent::DOWN) {
                m_pressedAt = at;
            } else if (std::abs(at[0] - m_pressedAt[0]) <= kClickSlop_px &&
                       std::abs(at[1] - m_pressedAt[1]) <= kClickSlop_px) {
                m_pressedAt = SbVec2s(-1000, -1000);
                const SbBool handled = SoQtExaminerViewer::processSoEvent(event);
                m_onClick(at);
                return handled;
            }
        }
    }
    return SoQtExaminerViewer::processSoEvent(event);
}

}  // namespace caliper3d::app
