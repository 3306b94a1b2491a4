#include "scenegraph/well_scene.h"

#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoDrawStyle.h>
#include <Inventor/nodes/SoIndexedTriangleStripSet.h>
#include <Inventor/nodes/SoLOD.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoLineSet.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoShapeHints.h>

#include <algorithm>
#include <thread>

#include <glm/geometric.hpp>

#include "reconstruction/mesh/lod_levels.h"
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
    m_pathCoords = nullptr;
    extendPath(reconstruction::pathLine(geometry, spacing_m));
}

void WellScene::extendPath(const std::vector<glm::vec3>& points) {
    assertMainThread("WellScene::extendPath");
    if (!m_pathCoords) {
        auto* style = new SoDrawStyle;
        style->lineWidth = 2.0f;
        auto* light = new SoLightModel;
        light->model = SoLightModel::BASE_COLOR;
        auto* colour = new SoMaterial;
        colour->diffuseColor.setValue(0.2f, 0.55f, 0.9f);
        m_pathCoords = new SoCoordinate3;
        m_pathCoords->point.setNum(0);
        m_pathLine = new SoLineSet;
        m_pathGroup->addChild(style);
        m_pathGroup->addChild(light);
        m_pathGroup->addChild(colour);
        m_pathGroup->addChild(m_pathCoords);
        m_pathGroup->addChild(m_pathLine);
    }
    int n = m_pathCoords->point.getNum();
    for (const glm::vec3& p : points) m_pathCoords->point.set1Value(n++, p.x, p.y, p.z);
    m_pathLine->numVertices.setValue(n);
}

void WellScene::addSegment(const reconstruction::SegmentMesh& segment) {
    assertMainThread("WellScene::addSegment");
    Record record;
    record.lod = makeSegmentLod(segment, m_view);
    record.centre = segment.centre;
    record.heldFrom = segment.firstLevel;
    record.coarseFrom = segment.firstLevel;
    // What the switch distances read, not the meshes (they are in the nodes now).
    record.shape.radius = segment.radius;
    record.shape.maxRadius_m = segment.maxRadius_m;
    record.shape.levelError_mm = segment.levelError_mm;
    keepPartShapes(record, segment);
    record.switchDistances = lodSwitchDistances(segment, m_view);
    m_segments->addChild(record.lod);
    m_fullTriangles += segment.fullDetailTriangles;
    m_records.push_back(std::move(record));
}

void WellScene::buildAll(const reconstruction::WellGeometry& geometry) {
    setPath(geometry);
    // Meshes on two threads (they read the immutable geometry only), nodes on this one, in
    // order. Every coarse mesh is held at once: a few MB for a 4 km well.
    const std::size_t count = geometry.segmentCount();
    std::vector<reconstruction::SegmentMesh> meshes(count);
    auto build = [&geometry, &meshes, count](std::size_t from) {
        for (std::size_t s = from; s < count; s += 2)
            meshes[s] = reconstruction::buildCoarseSegment(geometry, s);
    };
    std::thread helper(build, 1);
    build(0);
    helper.join();
    for (const reconstruction::SegmentMesh& mesh : meshes) addSegment(mesh);
}

void WellScene::buildAllLevels(const reconstruction::WellGeometry& geometry) {
    setPath(geometry);
    for (std::size_t s = 0; s < geometry.segmentCount(); ++s) addSegment(geometry.buildSegment(s));
}

void WellScene::setRanges(Record& record) {
    SoMFFloat& range = record.lod->range;
    const int first = record.heldFrom;
    const int count = static_cast<int>(record.switchDistances.size()) - first;
    range.setNum(std::max(count, 0));
    for (int i = 0; i < count; ++i)
        range.set1Value(
            i,
            record.switchDistances[static_cast<std::size_t>(first) + static_cast<std::size_t>(i)]);
}

void WellScene::keepPartShapes(Record& record, const reconstruction::SegmentMesh& segment) {
    if (segment.firstLevel != 0) return;
    record.shape.parts.clear();
    for (const auto& part : segment.parts) {
        reconstruction::DetailPart shape;  // where it is, not its meshes
        shape.centre = part.centre;
        shape.radius = part.radius;
        record.shape.parts.push_back(shape);
    }
    record.shape.partError_mm = segment.partError_mm;
}

void WellScene::setLodView(const LodView& view) {
    assertMainThread("WellScene::setLodView");
    m_view = view;
    for (Record& record : m_records) {
        record.switchDistances = lodSwitchDistances(record.shape, m_view);
        setRanges(record);
        if (record.heldFrom == 0) setPartRanges(record.lod->getChild(0), record.shape, m_view);
    }
}

std::vector<DetailRequest> WellScene::wantedDetail(const glm::vec3& eye) {
    ++m_tick;
    std::vector<DetailRequest> out;
    for (std::size_t s = 0; s < m_records.size(); ++s) {
        Record& record = m_records[s];
        const float distance = glm::length(record.centre - eye);
        const int level = lodLevelAt(record.switchDistances, distance);
        if (level < record.coarseFrom) record.lastWanted = m_tick;
        if (level < record.heldFrom) out.push_back({s, level, record.heldFrom, distance});
    }
    std::sort(out.begin(), out.end(), [](const DetailRequest& a, const DetailRequest& b) {
        return a.distance < b.distance;
    });
    return out;
}

void WellScene::attachFinerLevels(const reconstruction::SegmentMesh& finer) {
    assertMainThread("WellScene::attachFinerLevels");
    if (finer.index >= m_records.size()) return;
    Record& record = m_records[finer.index];
    // Only the levels it lacks, finest first, in front of those it holds.
    const int count =
        std::min(static_cast<int>(finer.levels.size()), record.heldFrom - finer.firstLevel);
    if (count <= 0) return;
    for (int i = count - 1; i >= 0; --i) {
        const int level = finer.firstLevel + i;
        record.lod->insertChild(makeLevelNode(finer, level, m_view), 0);
        std::size_t triangles = finer.levels[static_cast<std::size_t>(i)].triangleCount();
        if (level == 0)
            for (const auto& part : finer.parts) triangles += part.reduced.triangleCount();
        record.fineTriangles += triangles;
        m_fineTriangles += triangles;
    }
    keepPartShapes(record, finer);
    record.heldFrom = finer.firstLevel;
    record.lastWanted = m_tick;
    setRanges(record);
}

std::size_t WellScene::evictFineLevels(std::size_t budgetTriangles) {
    assertMainThread("WellScene::evictFineLevels");
    if (m_fineTriangles <= budgetTriangles) return 0;
    std::vector<std::size_t> held;
    for (std::size_t s = 0; s < m_records.size(); ++s)
        if (m_records[s].heldFrom < m_records[s].coarseFrom && m_records[s].lastWanted < m_tick)
            held.push_back(s);
    std::sort(held.begin(), held.end(), [&](std::size_t a, std::size_t b) {
        return m_records[a].lastWanted < m_records[b].lastWanted;
    });
    std::size_t dropped = 0;
    for (std::size_t s : held) {
        if (m_fineTriangles <= budgetTriangles) break;
        Record& record = m_records[s];
        for (int i = record.heldFrom; i < record.coarseFrom; ++i) record.lod->removeChild(0);
        m_fineTriangles -= record.fineTriangles;
        record.fineTriangles = 0;
        record.heldFrom = record.coarseFrom;
        setRanges(record);
        ++dropped;
    }
    return dropped;
}

}  // namespace caliper3d::scenegraph
