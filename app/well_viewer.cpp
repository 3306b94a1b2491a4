#include "app/well_viewer.h"

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
    if (legend) {
        m_legend = scenegraph::makeColourLegend(*legend);
        m_legend->ref();
        addSuperimposition(m_legend);
    }
    scheduleRedraw();
}

}  // namespace caliper3d::app
