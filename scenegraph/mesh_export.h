#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace caliper3d::reconstruction {
class WellGeometry;
struct Mesh;
}  // namespace caliper3d::reconstruction

namespace caliper3d::scenegraph {

// Mesh files for tools outside Inventor, written from plain reconstruction meshes by kept
// libraries: glTF with TinyGLTF, the others with the Open Asset Import Library (assimp), which
// also reads all four back (docs/formats.md, "Mesh exports"). Every format holds the scene
// frame as it is: metres from the first wellhead, x east, y up, z south, which is also glTF's
// own frame (y up, right-handed, metres).
enum class MeshFormat {
    Glb,  // glTF 2.0 binary: a node and a mesh per segment, per-vertex colours
    Ply,  // Stanford polygon file, text, one mesh, per-vertex colours
    Stl,  // stereolithography, one solid, no colours; binary unless text is asked for
    Obj,  // Wavefront OBJ text, a group per segment; colours only as the common "v x y z r g b"
};

// The format a file name asks for by its extension (".glb", ".ply", ".stl", ".obj"), if any.
std::optional<MeshFormat> meshFormatFor(const std::string& path);

// Which pyramid level (reconstruction/mesh/lod_levels.h) a segment is written at: one level
// per segment, since these formats have no level switch.
enum class MeshDetail {
    Shown,  // the finest of the coarse levels the window builds up front (kFirstCoarseLevel)
    Full,   // level 0: every section, with the full spline
};
int meshDetailLevel(MeshDetail detail);

// What a file holds: meshes (one per segment with a wall), vertices and triangles.
struct MeshExportCounts {
    std::size_t meshes = 0;
    std::size_t vertices = 0;
    std::size_t triangles = 0;
};

// The triangles of a mesh's strips as vertex triples, each counter-clockwise seen from the
// side its vertex normals point to (outside the wall): the front face of glTF, PLY, STL and
// OBJ. Strips wind the other way (the scene's SoShapeHints say clockwise). The zero-area
// triangles that join rings of different sizes (a vertex repeated, reconstruction::Mesh) are
// left out: Coin draws nothing for them, and glTF validators and CAD tools flag them.
std::vector<std::uint32_t> stripTriangles(const reconstruction::Mesh& mesh);

// Bytes of memory an export of `triangles` triangles takes at its peak, as measured
// (docs/benchmarks.md, "Mesh exports"): the library's whole file in memory before it writes,
// and for assimp a copy of it, each triangle a face with an index array of its own.
std::size_t meshExportBytes(MeshFormat format, std::size_t triangles);

// The largest .glb: its chunk lengths are 32-bit.
inline constexpr std::size_t kMaxGlbBytes = 0xffffffffu;

// Thrown when an export would need more memory than its limit (MeshFileWriter).
class MeshTooLarge : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A mesh file assembled mesh by mesh and written at once. Each mesh is converted to the
// library's own form when it is added, so the caller can free its mesh (and a well it is done
// with) before building the next; the library needs the whole file before it writes it, so
// memory grows with the file (meshExportBytes). Not tied to any thread; makes no Coin call.
class MeshFileWriter {
public:
    // binary: .stl binary, or text when false (.glb is always binary, .ply and .obj text).
    // memoryLimit_bytes: an export whose meshExportBytes would pass it is refused
    // (MeshTooLarge) rather than left to run the machine out of memory; 0: the machine's
    // physical memory.
    explicit MeshFileWriter(MeshFormat format, bool binary = true,
                            std::size_t memoryLimit_bytes = 0);
    ~MeshFileWriter();
    MeshFileWriter(const MeshFileWriter&) = delete;
    MeshFileWriter& operator=(const MeshFileWriter&) = delete;

    // Starts a well's node: meshes added after it go under it.
    void beginWell(const std::string& name);
    // Adds `mesh` as its own node and mesh, named `name`, under the current well (a well
    // named "well" is started when none was). Its vertices used by no triangle are left out;
    // a mesh without triangles adds nothing. Throws MeshTooLarge past the memory limit, or
    // past kMaxGlbBytes for a .glb.
    void addMesh(const reconstruction::Mesh& mesh, const std::string& name);
    // A well (beginWell) and each of its segments at `detail` (addMesh, "segment N"), built
    // one at a time and freed once added. At full detail the triangles are counted first, and
    // MeshTooLarge thrown before anything is built when they would pass the memory limit.
    void addWell(const reconstruction::WellGeometry& geometry, const std::string& name,
                 MeshDetail detail);
    const MeshExportCounts& counts() const { return m_counts; }

    // Writes everything added and releases it. Throws std::runtime_error naming the file
    // when it cannot be written.
    void write(const std::string& path);

    class Sink;  // the library's form of the file

private:
    void checkMemory(std::size_t triangles) const;

    MeshFormat m_format;
    bool m_binary;
    std::unique_ptr<Sink> m_sink;
    MeshExportCounts m_counts;
    std::size_t m_memoryLimit_bytes = 0;
    bool m_wellStarted = false;
};

}  // namespace caliper3d::scenegraph
