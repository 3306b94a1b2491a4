#include "scenegraph/iv_export.h"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/SoOutput.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/actions/SoWriteAction.h>
#include <Inventor/nodes/SoIndexedTriangleStripSet.h>
#include <Inventor/nodes/SoLOD.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoVertexProperty.h>

#include "reconstruction/well_geometry.h"
#include "scenegraph/main_thread.h"
#include "scenegraph/node_ref.h"
#include "scenegraph/segment_node_builder.h"
#include "scenegraph/well_scene.h"

namespace caliper3d::scenegraph {

namespace {
void* growBuffer(void* buffer, std::size_t size) {
    return std::realloc(buffer, size);
}
}  // namespace

void writeIv(SoNode* scene, const std::string& path, const IvExportOptions& options) {
    assertMainThread("writeIv");
    SoOutput out;
    out.setBinary(options.binary ? TRUE : FALSE);
    if (options.gzip) {
        // Compression must be chosen before openFile(), or Coin ignores it.
        if (!out.setCompression("GZIP", 0.6f))
            throw std::runtime_error(path + ": this Coin build cannot write compressed files");
        if (!out.openFile(path.c_str()))
            throw std::runtime_error(path + ": cannot open file for writing");
        SoWriteAction write(&out);
        write.apply(scene);
        out.closeFile();
        return;
    }
    // Into memory, then one write: Coin writes a binary file a value at a time, each its own
    // stdio call, 5-6 times slower than the text it replaces.
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) throw std::runtime_error(path + ": cannot open file for writing");
    void* start = std::malloc(1u << 20);
    out.setBuffer(start, 1u << 20, &growBuffer);
    SoWriteAction write(&out);
    write.apply(scene);
    void* buffer = nullptr;
    std::size_t size = 0;
    out.getBuffer(buffer, size);
    const bool written = std::fwrite(buffer, 1, size, file) == size;
    std::free(buffer);
    if (std::fclose(file) != 0 || !written)
        throw std::runtime_error(path + ": cannot write the file (disk full?)");
}

std::size_t writeIvFullDetail(const std::vector<const reconstruction::WellGeometry*>& wells,
                              const std::string& path, const IvExportOptions& options) {
    assertMainThread("writeIvFullDetail");
    SoOutput out;
    out.setBinary(options.binary ? TRUE : FALSE);
    // Without compression each segment is written into memory and that memory to the file
    // (Coin writes a value at a time, each its own stdio call, when it writes to a file).
    std::FILE* file = nullptr;
    if (options.gzip) {
        if (!out.setCompression("GZIP", 0.6f))
            throw std::runtime_error(path + ": this Coin build cannot write compressed files");
        if (!out.openFile(path.c_str()))
            throw std::runtime_error(path + ": cannot open file for writing");
    } else {
        file = std::fopen(path.c_str(), "wb");
        if (!file) throw std::runtime_error(path + ": cannot open file for writing");
        out.setBuffer(std::malloc(1u << 20), 1u << 20, &growBuffer);
    }
    bool ok = true;
    auto flush = [&] {
        if (!file) return;
        void* buffer = nullptr;
        std::size_t size = 0;
        out.getBuffer(buffer, size);
        ok = ok && std::fwrite(buffer, 1, size, file) == size;
        out.resetBuffer();
    };
    std::size_t written = 0;
    for (const reconstruction::WellGeometry* geometry : wells) {
        // The well's own nodes (shape hints, material, path) at the top level, so that they
        // apply to the segments written after them.
        WellScene scene;
        scene.setPath(*geometry);
        SoSeparator* root = scene.root();
        for (int i = 0; i < root->getNumChildren(); ++i) {
            if (root->getChild(i)->getName() == SbName("segments")) continue;
            SoWriteAction(&out).apply(root->getChild(i));
        }
        flush();
        for (std::size_t s = 0; s < geometry->segmentCount(); ++s) {
            const NodeRef<SoLOD> lod(makeSegmentLod(geometry->buildSegment(s)));
            SoWriteAction(&out).apply(lod.get());
            flush();
            ++written;
        }
    }
    if (file) {
        void* buffer = nullptr;
        std::size_t size = 0;
        out.getBuffer(buffer, size);
        std::free(buffer);
        ok = std::fclose(file) == 0 && ok;
        if (!ok) throw std::runtime_error(path + ": cannot write the file (disk full?)");
    } else {
        out.closeFile();
    }
    return written;
}

SoNode* readIv(const std::string& path) {
    assertMainThread("readIv");
    SoInput in;
    if (!in.openFile(path.c_str(), TRUE))
        throw std::runtime_error(path + ": cannot open file for reading");
    SoSeparator* root = SoDB::readAll(&in);
    in.closeFile();
    if (!root) throw std::runtime_error(path + ": not a readable Open Inventor file");
    return root;
}

SceneCounts countScene(SoNode* scene) {
    assertMainThread("countScene");
    SceneCounts counts;
    SoSearchAction search;
    search.setInterest(SoSearchAction::ALL);
    search.setSearchingAll(TRUE);  // look below every SoLOD level, not only the active one
    search.setType(SoLOD::getClassTypeId());
    search.apply(scene);
    counts.lods = static_cast<std::size_t>(search.getPaths().getLength());

    search.reset();
    search.setInterest(SoSearchAction::ALL);
    search.setSearchingAll(TRUE);
    search.setType(SoIndexedTriangleStripSet::getClassTypeId());
    search.apply(scene);
    const SoPathList& paths = search.getPaths();
    for (int i = 0; i < paths.getLength(); ++i) {
        auto* strips = static_cast<SoIndexedTriangleStripSet*>(paths[i]->getTail());
        ++counts.stripSets;
        if (auto* vp = static_cast<SoVertexProperty*>(strips->vertexProperty.getValue()))
            counts.vertices += static_cast<std::size_t>(vp->vertex.getNum());
        std::size_t run = 0;
        const int n = strips->coordIndex.getNum();
        const int32_t* idx = strips->coordIndex.getValues(0);
        for (int k = 0; k <= n; ++k) {
            if (k == n || idx[k] < 0) {
                if (run >= 3) counts.triangles += run - 2;
                run = 0;
            } else {
                ++run;
            }
        }
    }
    return counts;
}

}  // namespace caliper3d::scenegraph
