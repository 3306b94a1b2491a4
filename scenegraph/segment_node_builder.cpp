#include "scenegraph/segment_node_builder.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoIndexedTriangleStripSet.h>
#include <Inventor/nodes/SoLOD.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoVertexProperty.h>

#include "scenegraph/main_thread.h"
#include "scenegraph/render_caching.h"

namespace caliper3d::scenegraph {

namespace {

SoVertexProperty* makeVertexProperty(const reconstruction::Mesh& mesh) {
    auto* vp = new SoVertexProperty;
    const int n = static_cast<int>(mesh.positions.size());
    vp->vertex.setNum(n);
    SbVec3f* v = vp->vertex.startEditing();
    for (int i = 0; i < n; ++i)
        v[i].setValue(mesh.positions[i].x, mesh.positions[i].y, mesh.positions[i].z);
    vp->vertex.finishEditing();
    if (mesh.normals.size() == mesh.positions.size()) {
        vp->normal.setNum(n);
        SbVec3f* nv = vp->normal.startEditing();
        for (int i = 0; i < n; ++i)
            nv[i].setValue(mesh.normals[i].x, mesh.normals[i].y, mesh.normals[i].z);
        vp->normal.finishEditing();
        vp->normalBinding = SoVertexProperty::PER_VERTEX_INDEXED;
    }
    if (mesh.colours.size() == mesh.positions.size()) {
        vp->orderedRGBA.setValues(0, n, mesh.colours.data());
        vp->materialBinding = SoVertexProperty::PER_VERTEX_INDEXED;
    }
    return vp;
}

// Strips [begin, end) of `indices` drawn from `vp`'s vertices.
SoIndexedTriangleStripSet* makeStrips(SoVertexProperty* vp,
                                      const std::vector<std::int32_t>& indices, std::size_t begin,
                                      std::size_t end) {
    auto* strips = new SoIndexedTriangleStripSet;
    strips->vertexProperty = vp;
    strips->coordIndex.setValues(0, static_cast<int>(end - begin), indices.data() + begin);
    // With vertexProperty bindings *_INDEXED and empty index fields, Coin uses coordIndex.
    return strips;
}

}  // namespace

SoNode* cacheableShape(SoNode* shape) {
    if (!renderCachingWanted()) return shape;
    auto* separator = new SoSeparator;
    separator->renderCaching = SoSeparator::ON;
    separator->renderCulling = SoSeparator::OFF;  // the span above culls
    separator->addChild(shape);
    return separator;
}

SoIndexedTriangleStripSet* makeStripSet(const reconstruction::Mesh& mesh) {
    assertMainThread("makeStripSet");
    return makeStrips(makeVertexProperty(mesh), mesh.stripIndices, 0, mesh.stripIndices.size());
}

LodView lodViewFor(int viewportHeight_px, float heightAngle_rad, float pixelTolerance) {
    LodView view;
    const float half = std::tan(std::clamp(heightAngle_rad, 0.01f, 3.0f) / 2.0f);
    view.focal_px = static_cast<float>(std::max(viewportHeight_px, 1)) / 2.0f / half;
    view.pixelTolerance = std::max(pixelTolerance, 0.01f);
    return view;
}

std::vector<float> lodSwitchDistances(const reconstruction::SegmentMesh& segment,
                                      const LodView& view) {
    const std::size_t levels = segment.levelError_mm.size();
    std::vector<float> out(levels);
    const float scale = view.focal_px / view.pixelTolerance / 1000.0f;  // mm of error -> m
    float previous = 0.0f;
    for (std::size_t i = 0; i < levels; ++i) {
        const float error_mm =
            i + 1 < levels ? segment.levelError_mm[i + 1] : 2000.0f * segment.maxRadius_m;
        previous = std::max(previous, error_mm * scale + segment.radius);
        out[i] = view.visibility_m > 0.0f ? std::min(previous, view.visibility_m + segment.radius)
                                          : previous;
    }
    return out;
}

int lodLevelAt(const std::vector<float>& switchDistances, float distance) {
    int level = 0;
    while (level < static_cast<int>(switchDistances.size()) &&
           distance >= switchDistances[static_cast<std::size_t>(level)])
        ++level;
    return level;
}

float partSwitchDistance(const reconstruction::DetailPart& part, float partError_mm,
                         const LodView& view) {
    return partError_mm * view.focal_px / view.pixelTolerance / 1000.0f + part.radius;
}

SoNode* makeLevelNode(const reconstruction::SegmentMesh& segment, int level, const LodView& view) {
    assertMainThread("makeLevelNode");
    const reconstruction::Mesh& mesh =
        segment.levels.at(static_cast<std::size_t>(level - segment.firstLevel));
    if (level != 0 || segment.parts.empty()) return cacheableShape(makeStripSet(mesh));
    auto* group = new SoGroup;
    SoVertexProperty* vp = makeVertexProperty(mesh);
    for (const reconstruction::DetailPart& part : segment.parts) {
        auto* lod = new SoLOD;
        lod->center.setValue(part.centre.x, part.centre.y, part.centre.z);
        lod->range.setValue(partSwitchDistance(part, segment.partError_mm, view));
        lod->addChild(
            cacheableShape(makeStrips(vp, mesh.stripIndices, part.stripBegin, part.stripEnd)));
        lod->addChild(cacheableShape(makeStripSet(part.reduced)));
        group->addChild(lod);
    }
    return group;
}

void setPartRanges(SoNode* levelNode, const reconstruction::SegmentMesh& shape,
                   const LodView& view) {
    assertMainThread("setPartRanges");
    if (!levelNode || !levelNode->isOfType(SoGroup::getClassTypeId())) return;
    auto* group = static_cast<SoGroup*>(levelNode);
    const int n = std::min(group->getNumChildren(), static_cast<int>(shape.parts.size()));
    for (int i = 0; i < n; ++i) {
        SoNode* child = group->getChild(i);
        if (!child->isOfType(SoLOD::getClassTypeId())) continue;
        static_cast<SoLOD*>(child)->range.setValue(
            partSwitchDistance(shape.parts[static_cast<std::size_t>(i)], shape.partError_mm, view));
    }
}

SoLOD* makeSegmentLod(const reconstruction::SegmentMesh& segment, const LodView& view) {
    assertMainThread("makeSegmentLod");
    auto* lod = new SoLOD;
    lod->center.setValue(segment.centre.x, segment.centre.y, segment.centre.z);
    const std::vector<float> distances = lodSwitchDistances(segment, view);
    int i = 0;
    for (std::size_t level = static_cast<std::size_t>(segment.firstLevel); level < distances.size();
         ++level)
        lod->range.set1Value(i++, distances[level]);
    if (i == 0) lod->range.setNum(0);
    for (std::size_t l = 0; l < segment.levels.size(); ++l)
        lod->addChild(makeLevelNode(segment, segment.firstLevel + static_cast<int>(l), view));
    lod->addChild(new SoGroup);  // past the last level: nothing (the path line shows the well)
    return lod;
}

}  // namespace caliper3d::scenegraph
