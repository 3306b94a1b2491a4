#pragma once

#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>

#include "reconstruction/mesh/wall_colouring.h"

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

private:
    SoSeparator* m_legend = nullptr;  // referenced while shown
};

}  // namespace caliper3d::app
