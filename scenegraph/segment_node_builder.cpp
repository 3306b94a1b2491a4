#include "scenegraph/segment_node_builder.h"

#include <algorithm>

#include <Inventor/nodes/SoIndexedTriangleStripSet.h>
#include <Inventor/nodes/SoLOD.h>
#include <Inventor/nodes/SoVertexProperty.h>

#include "scenegraph/main_thread.h"

namespace caliper3d::scenegraph {

SoIndexedTriangleStripSet* makeStripSet(const reconstruction::Mesh& mesh) {
    assertMainThread("makeStripSet");
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
    auto* strips = new SoIndexedTriangleStripSet;
    strips->vertexProperty = vp;
    strips->coordIndex.setValues(0, static_cast<int>(mesh.stripIndices.size()),
                                 mesh.stripIndices.data());
    // With vertexProperty bindings *_INDEXED and empty index fields, Coin uses coordIndex.
    return strips;
}

float lodRange(const reconstruction::SegmentMesh& segment, int level) {
    // Full detail only close by; the N-gon levels a few segment lengths away.
    const float size = std::max(segment.radius * 2.0f, 1.0f);
    return level == 0 ? size * 1.5f : size * 6.0f;
}

SoLOD* makeSegmentLod(const reconstruction::SegmentMesh& segment) {
    assertMainThread("makeSegmentLod");
    auto* lod = new SoLOD;
    lod->center.setValue(segment.centre.x, segment.centre.y, segment.centre.z);
    const int levels = static_cast<int>(segment.levels.size());
    for (int i = 0; i + 1 < levels; ++i) lod->range.set1Value(i, lodRange(segment, i));
    if (levels <= 1) lod->range.setNum(0);
    for (const auto& mesh : segment.levels) lod->addChild(makeStripSet(mesh));
    return lod;
}

}  // namespace caliper3d::scenegraph
