#include "app/desktop/well_viewer.h"

#include <cstdlib>

#include <Inventor/events/SoMouseButtonEvent.h>
#include <Inventor/nodes/SoSeparator.h>

#include "scenegraph/colour_legend.h"

namespace caliper3d::app {

WellViewer::WellViewer(QWidget* parent) : SoQtExaminerViewer(parent) {}

WellViewer::~WellViewer() {
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
