#include "scenegraph/well_scene.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoDrawStyle.h>
#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoIndexedTriangleStripSet.h>
#include <Inventor/nodes/SoLOD.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoLineSet.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoPointSet.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoShapeHints.h>
#include <Inventor/nodes/SoVertexProperty.h>

#include <algorithm>

#include <glm/geometric.hpp>

#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/section/section_frame.h"
#include "scenegraph/main_thread.h"
#include "scenegraph/segment_node_builder.h"

namespace caliper3d::scenegraph {

namespace {

// Two points at a box's corners, never drawn: it stands among a span's children, which the
// span's SoLOD does not choose while they wait, so that the span's bounds (which frame and cull
// a picture) are those its segments will have.
SoNode* boundsStandIn(const reconstruction::Box3& box) {
    auto* vp = new SoVertexProperty;
    vp->vertex.set1Value(0, box.lo.x, box.lo.y, box.lo.z);
    vp->vertex.set1Value(1, box.hi.x, box.hi.y, box.hi.z);
    auto* points = new SoPointSet;
    points->vertexProperty = vp;
    return points;
}

}  // namespace

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
    m_pathLod = nullptr;
    const std::vector<glm::vec3> line = reconstruction::pathLine(geometry, spacing_m);
    extendPath(line);
    // Seen from afar a line of a point a metre is several points a pixel, each drawn: a
    // coarser copy within a tolerance of it draws the same pixels for a tenth of the points
    // or fewer (a field's overview: docs/benchmarks.md, "The path line's level of detail").
    float error = 0.0f;
    const std::vector<std::size_t> kept =
        reconstruction::simplifiedLine(line, kPathTolerance_m, &error);
    if (kept.size() * 4 > line.size()) return;
    auto* coarseCoords = new SoCoordinate3;
    coarseCoords->point.setNum(static_cast<int>(kept.size()));
    SbVec3f* to = coarseCoords->point.startEditing();
    for (const std::size_t i : kept) (to++)->setValue(line[i].x, line[i].y, line[i].z);
    coarseCoords->point.finishEditing();
    auto* coarseLine = new SoLineSet;
    coarseLine->numVertices.setValue(static_cast<int>(kept.size()));
    auto* coarse = new SoGroup;
    coarse->addChild(coarseCoords);
    coarse->addChild(coarseLine);
    auto* fine = new SoGroup;
    fine->addChild(m_pathCoords);
    fine->addChild(m_pathLine);
    m_pathGroup->removeChild(m_pathLine);
    m_pathGroup->removeChild(m_pathCoords);
    reconstruction::Box3 box;
    for (const glm::vec3& p : line) box.extend(p);
    const glm::vec3 centre = (box.lo + box.hi) / 2.0f;
    m_pathReach = 0.0f;
    for (const glm::vec3& p : line) m_pathReach = std::max(m_pathReach, glm::length(p - centre));
    m_pathError = error;
    m_pathLod = new SoLOD;
    m_pathLod->center.setValue(centre.x, centre.y, centre.z);
    m_pathLod->addChild(fine);
    m_pathLod->addChild(coarse);
    setPathRange();
    m_pathGroup->addChild(m_pathLod);
}

void WellScene::setPathRange() {
    if (!m_pathLod) return;
    // The coarser copy once its distance from the line projects under the pixel tolerance
    // from the line's nearest point.
    const float scale = m_view.focal_px / m_view.pixelTolerance;
    m_pathLod->range.setValue(m_pathError * scale + m_pathReach);
}

void WellScene::extendPath(const std::vector<glm::vec3>& points) {
    assertMainThread("WellScene::extendPath");
    if (m_pathLod) {  // drawn on past a whole path: its line alone again
        m_pathCoords->ref();
        m_pathLine->ref();
        m_pathGroup->removeChild(m_pathLod);
        m_pathGroup->addChild(m_pathCoords);
        m_pathGroup->addChild(m_pathLine);
        m_pathCoords->unrefNoDelete();
        m_pathLine->unrefNoDelete();
        m_pathLod = nullptr;
    }
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
    // Grown once for the stretch (set1Value a point at a time reallocated as it grew).
    const int before = m_pathCoords->point.getNum();
    const int n = before + static_cast<int>(points.size());
    m_pathCoords->point.setNum(n);
    SbVec3f* to = m_pathCoords->point.startEditing() + before;
    for (const glm::vec3& p : points) (to++)->setValue(p.x, p.y, p.z);
    m_pathCoords->point.finishEditing();
    m_pathLine->numVertices.setValue(n);
}

void WellScene::growTo(int depth) {
    while (m_depth < depth) {
        m_spans.emplace_back();
        SoSeparator* oldRoot =
            m_depth > 0 ? m_spans[static_cast<std::size_t>(m_depth) - 1][0].separator : nullptr;
        if (oldRoot) oldRoot->ref();
        m_segments->removeAllChildren();
        ++m_depth;
        const std::size_t root = ensureSpan(m_depth, 0);
        if (oldRoot) {
            m_spans[static_cast<std::size_t>(m_depth) - 1][root].children->addChild(oldRoot);
            oldRoot->unref();
        }
    }
}

std::size_t WellScene::ensureSpan(int depth, std::size_t index) {
    auto& level = m_spans[static_cast<std::size_t>(depth) - 1];
    if (index < level.size()) return index;
    // Spans of a depth are made in order, as the segments arrive.
    while (level.size() <= index) {
        Span span;
        span.separator = new SoSeparator;
        span.separator->setName("span");
        // Culled against the view by its cached bounding box (all of its SoLOD's children).
        span.separator->renderCulling = SoSeparator::ON;
        span.lod = new SoLOD;
        span.children = new SoGroup;
        span.lod->addChild(span.children);
        span.separator->addChild(span.lod);
        const std::size_t made = level.size();
        m_spanOfLod[span.lod] = {depth, made};
        SoSeparator* separator = span.separator;
        level.push_back(span);
        if (depth == m_depth) {
            m_segments->addChild(separator);
        } else {
            const std::size_t parent = ensureSpan(depth + 1, made / reconstruction::kLodTreeFanOut);
            m_spans[static_cast<std::size_t>(depth)][parent].children->addChild(separator);
        }
    }
    return index;
}

void WellScene::addSegment(const reconstruction::SegmentMesh& segment) {
    assertMainThread("WellScene::addSegment");
    addRecord();
    m_fullTriangles += segment.fullDetailTriangles;
    makeSegmentNode(m_records.size() - 1, segment);
}

void WellScene::addRecord() {
    growTo(reconstruction::lodTreeDepth(m_records.size() + 1));
    ensureSpan(1, m_records.size() / reconstruction::kLodTreeFanOut);
    m_records.emplace_back();
}

void WellScene::makeSegmentNode(std::size_t index, const reconstruction::SegmentMesh& segment) {
    Record& record = m_records[index];
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
    m_spans[0][index / reconstruction::kLodTreeFanOut].children->addChild(record.lod);
    m_segmentOfLod[record.lod] = index;
}

void WellScene::makeSegmentNodes(std::size_t index) {
    Span& span = m_spans[0][index];
    if (span.segmentsMade) return;
    const std::size_t first = index * reconstruction::kLodTreeFanOut;
    const std::size_t end = std::min(first + reconstruction::kLodTreeFanOut, m_records.size());
    span.children->removeAllChildren();  // the bounds' stand-in
    for (std::size_t s = first; s < end; ++s)
        if (!m_records[s].lod) makeSegmentNode(s, m_waiting(s));
    span.segmentsMade = true;
    setSpanRanges(span);
    m_boundsStale = true;
}

void WellScene::buildAll(const reconstruction::WellGeometry& geometry, int firstLevel) {
    attachAll(geometry, reconstruction::buildCoarseMeshes(geometry, firstLevel));
}

void WellScene::attachAll(const reconstruction::WellGeometry& geometry,
                          const reconstruction::CoarseMeshes& meshes) {
    setPath(geometry);
    for (const reconstruction::SegmentMesh& mesh : meshes.segments) addSegment(mesh);
    for (const reconstruction::SpanMesh& span : meshes.spans) addSpan(span);
    cacheBounds();
}

void WellScene::attachAll(const reconstruction::WellGeometry& geometry,
                          const std::vector<reconstruction::SpanMesh>& spans,
                          WaitingSegments segments) {
    assertMainThread("WellScene::attachAll");
    setPath(geometry);
    m_waiting = std::move(segments.build);
    for (std::size_t s = 0; s < segments.count; ++s) addRecord();
    m_fullTriangles += segments.fullDetailTriangles;
    if (!m_spans.empty())
        for (Span& span : m_spans[0]) span.segmentsMade = false;
    for (const reconstruction::SpanMesh& span : spans) addSpan(span);
    for (std::size_t i = 0; !m_spans.empty() && i < m_spans[0].size(); ++i) {
        Span& span = m_spans[0][i];
        // A span without a merged mesh shows its segments from every distance.
        if (!span.merged) {
            makeSegmentNodes(i);
            continue;
        }
        if (segments.boxes.size() != segments.count) continue;
        reconstruction::Box3 box;
        const std::size_t first = i * reconstruction::kLodTreeFanOut;
        for (std::size_t s = first;
             s < std::min(first + reconstruction::kLodTreeFanOut, segments.count); ++s)
            box.extend(segments.boxes[s]);
        if (!box.empty()) span.children->addChild(boundsStandIn(box));
    }
    cacheBounds();
}

void WellScene::cacheBounds() {
    assertMainThread("WellScene::cacheBounds");
    m_boundsStale = false;
    SoGetBoundingBoxAction bounds{SbViewportRegion()};
    bounds.apply(m_segments);
}

void WellScene::addSpan(const reconstruction::SpanMesh& mesh) {
    assertMainThread("WellScene::addSpan");
    if (mesh.depth < 1 || mesh.depth > m_depth) return;
    auto& level = m_spans[static_cast<std::size_t>(mesh.depth) - 1];
    if (mesh.index >= level.size() || mesh.lastSegment >= m_records.size()) return;
    Span& span = level[mesh.index];
    if (span.merged) {  // a new look: the old merged mesh and empty level go
        span.lod->removeChild(2);
        span.lod->removeChild(1);
    }
    span.centre = mesh.centre;
    span.radius = mesh.radius;
    span.error_mm = mesh.error_mm;
    span.maxRadius_m = mesh.maxRadius_m;
    span.firstSegment = mesh.firstSegment;
    span.lastSegment = mesh.lastSegment;
    span.firstRow = mesh.firstRow;
    span.lastRow = mesh.lastRow;
    span.lod->center.setValue(mesh.centre.x, mesh.centre.y, mesh.centre.z);
    span.lod->addChild(cacheableShape(makeStripSet(mesh.mesh)));
    span.lod->addChild(new SoGroup);  // past it: nothing (the path line shows the well)
    if (!span.merged) ++m_mergedSpans;
    span.merged = true;
    setSpanRanges(span);
}

std::pair<float, float> WellScene::spanSwitchDistances(const Span& span) const {
    const float scale = m_view.focal_px / m_view.pixelTolerance / 1000.0f;  // mm of error -> m
    float merged = span.error_mm * scale + span.radius;
    float empty = std::max(merged, 2000.0f * span.maxRadius_m * scale + span.radius);
    if (m_view.visibility_m > 0.0f) {
        merged = std::min(merged, m_view.visibility_m + span.radius);
        empty = std::min(empty, m_view.visibility_m + span.radius);
    }
    return {merged, empty};
}

void WellScene::setSpanRanges(Span& span) const {
    if (!span.merged) {
        span.lod->range.setNum(0);
        return;
    }
    const auto [merged, empty] = spanSwitchDistances(span);
    span.lod->range.setNum(2);
    span.lod->range.set1Value(0, span.segmentsMade ? merged : 0.0f);
    span.lod->range.set1Value(1, empty);
}

std::optional<std::size_t> WellScene::segmentOfLod(const SoNode* node) const {
    const auto it = m_segmentOfLod.find(node);
    if (it == m_segmentOfLod.end()) return std::nullopt;
    return it->second;
}

std::optional<WellScene::SpanRows> WellScene::spanOfLod(const SoNode* node) const {
    const auto it = m_spanOfLod.find(node);
    if (it == m_spanOfLod.end()) return std::nullopt;
    const Span& span = m_spans[static_cast<std::size_t>(it->second.first) - 1][it->second.second];
    if (!span.merged) return std::nullopt;
    return SpanRows{it->second.first, span.firstSegment, span.lastSegment, span.firstRow,
                    span.lastRow};
}

PlannedWell planWaitingWell(const std::shared_ptr<const reconstruction::WellGeometry>& drawn,
                            const std::shared_ptr<const reconstruction::CoarsePlan>& plan,
                            const std::shared_ptr<const std::vector<std::size_t>>& wholeRows,
                            int threads) {
    PlannedWell out;
    out.spans = reconstruction::buildPlannedSpans(*drawn, *plan, wholeRows.get(), threads);
    out.waiting.count = plan->segments.size();
    out.waiting.boxes.reserve(plan->segments.size());
    for (const reconstruction::SegmentPlan& segment : plan->segments) {
        out.waiting.fullDetailTriangles += segment.fullDetailTriangles;
        out.waiting.boxes.push_back(
            reconstruction::plannedSegmentBox(*drawn, segment, wholeRows.get()));
    }
    out.waiting.build = [drawn, plan, wholeRows](std::size_t s) {
        return reconstruction::finishSegmentLevels(*drawn, plan->segments[s], wholeRows.get());
    };
    return out;
}

void WellScene::buildAllLevels(const reconstruction::WellGeometry& geometry) {
    setPath(geometry);
    for (std::size_t s = 0; s < geometry.segmentCount(); ++s) addSegment(geometry.buildSegment(s));
}

void WellScene::setRanges(Record& record) {
    if (!record.lod) return;  // waiting: made with the view's ranges
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
    setPathRange();
    for (Record& record : m_records) {
        if (!record.lod) continue;  // made with the view's ranges when near
        record.switchDistances = lodSwitchDistances(record.shape, m_view);
        setRanges(record);
        if (record.heldFrom == 0) setPartRanges(record.lod->getChild(0), record.shape, m_view);
    }
    for (auto& level : m_spans)
        for (Span& span : level) setSpanRanges(span);
}

void WellScene::collectWanted(int depth, std::size_t index, const glm::vec3& eye,
                              std::vector<DetailRequest>& out) {
    const Span& span = m_spans[static_cast<std::size_t>(depth) - 1][index];
    // A span drawing its merged mesh, or nothing, draws none of its segments.
    if (span.merged && glm::length(span.centre - eye) >= spanSwitchDistances(span).first) return;
    const std::size_t first = index * reconstruction::kLodTreeFanOut;
    if (depth > 1) {
        const std::size_t children = m_spans[static_cast<std::size_t>(depth) - 2].size();
        for (std::size_t c = first; c < std::min(first + reconstruction::kLodTreeFanOut, children);
             ++c)
            collectWanted(depth - 1, c, eye, out);
        return;
    }
    for (std::size_t s = first;
         s < std::min(first + reconstruction::kLodTreeFanOut, m_records.size()); ++s) {
        Record& record = m_records[s];
        const float distance = glm::length(record.centre - eye);
        const int level = lodLevelAt(record.switchDistances, distance);
        if (level < record.coarseFrom) record.lastWanted = m_tick;
        if (level < record.heldFrom) out.push_back({s, level, record.heldFrom, distance});
    }
}

void WellScene::makeNodesNear(int depth, std::size_t index, const glm::vec3& eye) {
    const Span& span = m_spans[static_cast<std::size_t>(depth) - 1][index];
    if (span.merged && glm::length(span.centre - eye) >= spanSwitchDistances(span).first) return;
    if (depth == 1) {
        makeSegmentNodes(index);
        return;
    }
    const std::size_t first = index * reconstruction::kLodTreeFanOut;
    const std::size_t children = m_spans[static_cast<std::size_t>(depth) - 2].size();
    for (std::size_t c = first; c < std::min(first + reconstruction::kLodTreeFanOut, children); ++c)
        makeNodesNear(depth - 1, c, eye);
}

void WellScene::makeSegmentNodesNear(const glm::vec3& eye) {
    assertMainThread("WellScene::makeSegmentNodesNear");
    if (m_depth > 0) makeNodesNear(m_depth, 0, eye);
    if (m_boundsStale) cacheBounds();
}

std::vector<DetailRequest> WellScene::wantedDetail(const glm::vec3& eye) {
    makeSegmentNodesNear(eye);
    ++m_tick;
    std::vector<DetailRequest> out;
    if (m_depth > 0) collectWanted(m_depth, 0, eye, out);
    std::sort(out.begin(), out.end(), [](const DetailRequest& a, const DetailRequest& b) {
        return a.distance < b.distance;
    });
    return out;
}

void WellScene::attachFinerLevels(const reconstruction::SegmentMesh& finer) {
    assertMainThread("WellScene::attachFinerLevels");
    if (finer.index >= m_records.size()) return;
    makeSegmentNodes(finer.index / reconstruction::kLodTreeFanOut);
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

std::vector<WellScene::IdleDetail> WellScene::idleDetail() const {
    std::vector<IdleDetail> out;
    for (std::size_t s = 0; s < m_records.size(); ++s) {
        const Record& record = m_records[s];
        if (record.heldFrom < record.coarseFrom && record.lastWanted < m_tick)
            out.push_back({s, m_tick - record.lastWanted, record.fineTriangles});
    }
    return out;
}

void WellScene::dropFineLevels(std::size_t segment) {
    assertMainThread("WellScene::dropFineLevels");
    if (segment >= m_records.size()) return;
    Record& record = m_records[segment];
    for (int i = record.heldFrom; i < record.coarseFrom; ++i) record.lod->removeChild(0);
    m_fineTriangles -= record.fineTriangles;
    record.fineTriangles = 0;
    record.heldFrom = record.coarseFrom;
    setRanges(record);
}

std::size_t WellScene::evictFineLevels(std::size_t budgetTriangles) {
    assertMainThread("WellScene::evictFineLevels");
    if (m_fineTriangles <= budgetTriangles) return 0;
    std::vector<IdleDetail> idle = idleDetail();
    std::sort(idle.begin(), idle.end(),
              [](const IdleDetail& a, const IdleDetail& b) { return a.idleFor > b.idleFor; });
    std::size_t dropped = 0;
    for (const IdleDetail& d : idle) {
        if (m_fineTriangles <= budgetTriangles) break;
        dropFineLevels(d.segment);
        ++dropped;
    }
    return dropped;
}

}  // namespace caliper3d::scenegraph
