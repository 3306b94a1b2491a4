#include "scenegraph/iv_export.h"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <utility>

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/SoOutput.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/actions/SoWriteAction.h>
#include <Inventor/nodes/SoIndexedTriangleStripSet.h>
#include <Inventor/nodes/SoLOD.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoVertexProperty.h>

#include "io/atomic_output.h"
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

// An Open Inventor file being written, node after node, into a temporary beside it that
// close() renames over it (io::AtomicOutput: a failed or killed export leaves the previous
// file). With gzip, through Coin's own file; otherwise into memory, flushed to the file after
// each node: Coin writes a file a value at a time, each its own stdio call, 5-6 times slower
// than the text it replaces (25 times for binary). The buffer and the file are released, and
// the temporary removed, however the writing ends.
class IvFileWriter {
public:
    IvFileWriter(const std::string& path, const IvExportOptions& options)
        : m_path(path), m_output(path) {
        m_out.setBinary(options.binary ? TRUE : FALSE);
        if (options.gzip) {
            // Compression must be chosen before openFile(), or Coin ignores it.
            if (!m_out.setCompression("GZIP", 0.6f))
                throw std::runtime_error(path + ": this Coin build cannot write compressed files");
            if (!m_out.openFile(m_output.path().c_str()))
                throw std::runtime_error(path + ": cannot open file for writing");
            m_coinFile = true;
            return;
        }
        m_file = std::fopen(m_output.path().c_str(), "wb");
        if (!m_file) throw std::runtime_error(path + ": cannot open file for writing");
        m_out.setBuffer(std::malloc(1u << 20), 1u << 20, &growBuffer);
    }
    ~IvFileWriter() {
        if (m_file) {
            std::free(buffer().first);
            std::fclose(m_file);
        }
        if (m_coinFile) m_out.closeFile();  // before m_output removes the file
    }
    IvFileWriter(const IvFileWriter&) = delete;
    IvFileWriter& operator=(const IvFileWriter&) = delete;

    void write(SoNode* node) {
        SoWriteAction(&m_out).apply(node);
        if (!m_file) return;
        const auto [data, size] = buffer();
        m_ok = m_ok && std::fwrite(data, 1, size, m_file) == size;
        m_out.resetBuffer();
    }

    // Throws std::runtime_error naming the file when it could not be written.
    void close() {
        if (m_coinFile) {
            m_out.closeFile();
            m_coinFile = false;
        } else {
            std::free(buffer().first);
            const bool closed = std::fclose(m_file) == 0;
            m_file = nullptr;
            if (!closed || !m_ok)
                throw std::runtime_error(m_path + ": cannot write the file (disk full?)");
        }
        m_output.commit();
    }

private:
    std::pair<void*, std::size_t> buffer() {
        void* data = nullptr;
        std::size_t size = 0;
        m_out.getBuffer(data, size);
        return {data, size};
    }

    std::string m_path;
    io::AtomicOutput m_output;  // declared before the file and SoOutput: they close first
    SoOutput m_out;
    std::FILE* m_file = nullptr;
    bool m_coinFile = false;  // m_out has a file open (gzip)
    bool m_ok = true;
};

}  // namespace

void writeIv(SoNode* scene, const std::string& path, const IvExportOptions& options) {
    assertMainThread("writeIv");
    IvFileWriter file(path, options);
    file.write(scene);
    file.close();
}

std::size_t writeIvFullDetail(const std::vector<const reconstruction::WellGeometry*>& wells,
                              const std::string& path, const IvExportOptions& options) {
    assertMainThread("writeIvFullDetail");
    IvFileWriter file(path, options);
    std::size_t written = 0;
    for (const reconstruction::WellGeometry* geometry : wells) {
        // The well's own nodes (shape hints, material, path) at the top level, so that they
        // apply to the segments written after them.
        WellScene scene;
        scene.setPath(*geometry);
        SoSeparator* root = scene.root();
        for (int i = 0; i < root->getNumChildren(); ++i)
            if (root->getChild(i)->getName() != SbName("segments")) file.write(root->getChild(i));
        for (std::size_t s = 0; s < geometry->segmentCount(); ++s) {
            const NodeRef<SoLOD> lod(makeSegmentLod(geometry->buildSegment(s)));
            file.write(lod.get());
            ++written;
        }
    }
    file.close();
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
