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

#include "scenegraph/main_thread.h"

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
