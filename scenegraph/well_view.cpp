#include "scenegraph/well_view.h"

#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoSwitch.h>

#include "scenegraph/main_thread.h"
#include "scenegraph/pick_markers.h"
#include "scenegraph/well_annotations.h"
#include "scenegraph/well_scene.h"

namespace caliper3d::scenegraph {

WellView::WellView(SoGroup* parent, int firstCoarseLevel)
    : m_parent(parent),
      m_shown(makeRef(new SoSwitch)),
      m_scene(std::make_unique<WellScene>()),
      m_firstCoarseLevel(firstCoarseLevel) {
    assertMainThread("WellView");
    m_shown->whichChild = SO_SWITCH_ALL;
    m_shown->addChild(m_scene->root());
    m_parent->addChild(m_shown.get());
}

WellView::~WellView() {
    assertMainThread("WellView");
    const int at = m_parent->findChild(m_shown.get());
    if (at >= 0) m_parent->removeChild(at);
}

void WellView::setVisible(bool visible) {
    m_shown->whichChild = visible ? SO_SWITCH_ALL : SO_SWITCH_NONE;
}

bool WellView::visible() const {
    return m_shown->whichChild.getValue() != SO_SWITCH_NONE;
}

void WellView::annotate(const reconstruction::WellGeometry& geometry, double radialExaggeration) {
    assertMainThread("WellView");
    show(makeWholeWellAnnotations(geometry, radialExaggeration, m_depthTicks), geometry,
         radialExaggeration);
}

void WellView::annotate(const reconstruction::WellGeometry& geometry, const AnnotationView& view,
                        const WellLabels& labels) {
    assertMainThread("WellView");
    show(makeWholeWellAnnotations(geometry, view, labels), geometry, view.radialExaggeration);
}

void WellView::show(SoSeparator* annotations, const reconstruction::WellGeometry& geometry,
                    double radialExaggeration) {
    if (!m_picks.empty())
        annotations->addChild(makePickMarkers(geometry, m_picks, radialExaggeration));
    if (m_annotations)
        m_shown->replaceChild(m_annotations, annotations);
    else
        m_shown->addChild(annotations);
    m_annotations = annotations;
}

void WellView::replaceScene(std::unique_ptr<WellScene> scene,
                            const reconstruction::WellGeometry& geometry,
                            double radialExaggeration) {
    m_shown->replaceChild(m_scene->root(), scene->root());
    m_scene = std::move(scene);
    annotate(geometry, radialExaggeration);  // the tick marks stand off the wall as now drawn
}

void WellView::rebuild(const reconstruction::WellGeometry& geometry, double radialExaggeration) {
    assertMainThread("WellView");
    auto scene = std::make_unique<WellScene>();
    scene->buildAll(geometry, m_firstCoarseLevel);
    replaceScene(std::move(scene), geometry, radialExaggeration);
}

void WellView::rebuild(const reconstruction::WellGeometry& geometry,
                       const reconstruction::CoarseMeshes& meshes, double radialExaggeration) {
    assertMainThread("WellView");
    auto scene = std::make_unique<WellScene>();
    scene->attachAll(geometry, meshes);
    replaceScene(std::move(scene), geometry, radialExaggeration);
}

void WellView::rebuild(const reconstruction::WellGeometry& geometry, PlannedWell planned,
                       double radialExaggeration) {
    assertMainThread("WellView");
    auto scene = std::make_unique<WellScene>();
    scene->attachAll(geometry, planned.spans, std::move(planned.waiting));
    replaceScene(std::move(scene), geometry, radialExaggeration);
}

}  // namespace caliper3d::scenegraph
