#include "scenegraph/well_scene.h"

#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoDrawStyle.h>
#include <Inventor/nodes/SoLOD.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoLineSet.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoShapeHints.h>

#include "reconstruction/section/section_frame.h"
#include "scenegraph/main_thread.h"
#include "scenegraph/segment_node_builder.h"

namespace caliper3d::scenegraph {

WellScene::WellScene() : m_root(new SoSeparator) {
    assertMainThread("WellScene");
    m_root->setName("caliper3d_well");
    auto* hints = new SoShapeHints;
    hints->vertexOrdering = SoShapeHints::CLOCKWISE;
    hints->shapeType = SoShapeHints::UNKNOWN_SHAPE_TYPE;  // two-sided lighting
    m_root->addChild(hints);
    auto* material = new SoMaterial;
    material->diffuseColor.setValue(0.72f, 0.72f, 0.72f);
    material->specularColor.setValue(0.25f, 0.25f, 0.25f);
    material->shininess = 0.3f;
    m_root->addChild(material);
    m_pathGroup = new SoSeparator;
    m_pathGroup->setName("path");
    m_root->addChild(m_pathGroup);
    m_segments = new SoSeparator;
    m_segments->setName("segments");
    m_root->addChild(m_segments);
}

void WellScene::setPath(const reconstruction::WellGeometry& geometry, double spacing_m) {
    assertMainThread("WellScene::setPath");
    m_pathGroup->removeAllChildren();
    const auto& depth = geometry.table().depth_m;
    auto* coords = new SoCoordinate3;
    int n = 0;
    double next = depth.front();
    for (std::size_t row = 0; row < depth.size(); ++row) {
        if (depth[row] < next && row + 1 != depth.size()) continue;
        const glm::dvec3 p = reconstruction::toScene(geometry.centre(row));
        coords->point.set1Value(n++, static_cast<float>(p.x), static_cast<float>(p.y),
                                static_cast<float>(p.z));
        next = depth[row] + spacing_m;
    }
    auto* style = new SoDrawStyle;
    style->lineWidth = 2.0f;
    auto* light = new SoLightModel;
    light->model = SoLightModel::BASE_COLOR;
    auto* colour = new SoMaterial;
    colour->diffuseColor.setValue(0.2f, 0.55f, 0.9f);
    auto* line = new SoLineSet;
    line->numVertices.setValue(n);
    m_pathGroup->addChild(style);
    m_pathGroup->addChild(light);
    m_pathGroup->addChild(colour);
    m_pathGroup->addChild(coords);
    m_pathGroup->addChild(line);
}

void WellScene::addSegment(const reconstruction::SegmentMesh& segment) {
    assertMainThread("WellScene::addSegment");
    m_segments->addChild(makeSegmentLod(segment));
    ++m_segmentCount;
    if (!segment.levels.empty()) m_fullTriangles += segment.levels.front().triangleCount();
}

void WellScene::buildAll(const reconstruction::WellGeometry& geometry) {
    setPath(geometry);
    for (std::size_t s = 0; s < geometry.segmentCount(); ++s) addSegment(geometry.buildSegment(s));
}

}  // namespace caliper3d::scenegraph
