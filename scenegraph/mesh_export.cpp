#include "scenegraph/mesh_export.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

#include <assimp/material.h>
#include <assimp/scene.h>
#include <tiny_gltf.h>
#include <assimp/Exporter.hpp>
#include <glm/vec3.hpp>

#include "io/atomic_output.h"
#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/mesh/mesh.h"
#include "reconstruction/well_geometry.h"

namespace caliper3d::scenegraph {

// One mesh as a file holds it: the triangles (three indices each, into `vertices`) and which
// of the mesh's vertices are written, in the mesh's order.
struct MeshTriangles {
    std::vector<std::uint32_t> triangles;
    std::vector<std::uint32_t> vertices;
};

class MeshFileWriter::Sink {
public:
    virtual ~Sink() = default;
    virtual void beginWell(const std::string& name) = 0;
    virtual void add(const reconstruction::Mesh& mesh, const MeshTriangles& written,
                     const std::string& name) = 0;
    // Writes the file at `path`; errors name `shownAs` (the file the user asked for, which
    // `path`, a temporary beside it, replaces once written).
    virtual void write(const std::string& path, const std::string& shownAs) = 0;
};

namespace {

constexpr double kMiB = 1024.0 * 1024.0;

bool endsWith(const std::string& text, const std::string& tail) {
    return text.size() > tail.size() &&
           text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

std::size_t physicalMemory() {
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long pageSize = sysconf(_SC_PAGESIZE);
    if (pages <= 0 || pageSize <= 0) return 0;
    return static_cast<std::size_t>(pages) * static_cast<std::size_t>(pageSize);
}

float channel(std::uint32_t rgba, int shift) {
    return static_cast<float>((rgba >> shift) & 0xffu) / 255.0f;
}

// glTF's COLOR_0 is linear, multiplied into linear lighting and encoded as sRGB on the way to
// the screen; the scene's colours are sRGB values that Coin puts on the screen as they are.
// Converted, a glTF viewer shows the colours the window shows. (IEC 61966-2-1.)
float linearFromSrgb(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

// glTF through TinyGLTF: one buffer that every mesh's arrays are appended to, a node and a
// mesh per segment. (assimp's glTF writer regrows its buffer to the exact size at every
// array, so 4000 segments took 755 s for a 34 MB file.)
class GltfSink : public MeshFileWriter::Sink {
public:
    GltfSink() {
        m_model.asset.version = "2.0";
        m_model.asset.generator = "caliper3d";
        m_model.buffers.emplace_back();
        tinygltf::Material wall;
        wall.name = "wall";
        // White, so that the vertex colours are the colours seen; the hole is seen from
        // inside as well as from outside.
        wall.pbrMetallicRoughness.baseColorFactor = {1.0, 1.0, 1.0, 1.0};
        wall.pbrMetallicRoughness.metallicFactor = 0.0;
        wall.pbrMetallicRoughness.roughnessFactor = 0.8;
        wall.doubleSided = true;
        m_model.materials.push_back(wall);
        tinygltf::Node root;
        root.name = "caliper3d";
        m_model.nodes.push_back(root);
        tinygltf::Scene scene;
        scene.nodes.push_back(0);
        m_model.scenes.push_back(scene);
        m_model.defaultScene = 0;
    }

    void beginWell(const std::string& name) override {
        tinygltf::Node well;
        well.name = name;
        m_well = static_cast<int>(m_model.nodes.size());
        m_model.nodes.push_back(well);
        m_model.nodes[0].children.push_back(m_well);
    }

    void add(const reconstruction::Mesh& mesh, const MeshTriangles& written,
             const std::string& name) override {
        const std::size_t n = written.vertices.size();
        tinygltf::Primitive primitive;
        primitive.material = 0;
        primitive.mode = TINYGLTF_MODE_TRIANGLES;

        std::vector<float> values(3 * n);
        std::vector<double> lo(3, std::numeric_limits<double>::infinity());
        std::vector<double> hi(3, -std::numeric_limits<double>::infinity());
        for (std::size_t i = 0; i < n; ++i)
            for (int k = 0; k < 3; ++k) {
                const float v = mesh.positions[written.vertices[i]][k];
                values[3 * i + static_cast<std::size_t>(k)] = v;
                const auto axis = static_cast<std::size_t>(k);
                lo[axis] = std::min(lo[axis], static_cast<double>(v));
                hi[axis] = std::max(hi[axis], static_cast<double>(v));
            }
        // glTF requires the bounds of every position accessor.
        const int position =
            append(values.data(), values.size() * sizeof(float), n, TINYGLTF_COMPONENT_TYPE_FLOAT,
                   TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER);
        m_model.accessors[static_cast<std::size_t>(position)].minValues = lo;
        m_model.accessors[static_cast<std::size_t>(position)].maxValues = hi;
        primitive.attributes["POSITION"] = position;

        if (mesh.normals.size() == mesh.positions.size()) {
            for (std::size_t i = 0; i < n; ++i)
                for (int k = 0; k < 3; ++k)
                    values[3 * i + static_cast<std::size_t>(k)] =
                        mesh.normals[written.vertices[i]][k];
            primitive.attributes["NORMAL"] = append(
                values.data(), values.size() * sizeof(float), n, TINYGLTF_COMPONENT_TYPE_FLOAT,
                TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER);
        }

        if (mesh.colours.size() == mesh.positions.size()) {
            // Linear values in 16 bits: 8 would band the darker colours once linear.
            std::vector<std::uint16_t> colours(4 * n);
            for (std::size_t i = 0; i < n; ++i) {
                const std::uint32_t c = mesh.colours[written.vertices[i]];  // 0xRRGGBBAA
                const float rgba[4] = {linearFromSrgb(channel(c, 24)),
                                       linearFromSrgb(channel(c, 16)),
                                       linearFromSrgb(channel(c, 8)), channel(c, 0)};
                for (std::size_t k = 0; k < 4; ++k)
                    colours[4 * i + k] =
                        static_cast<std::uint16_t>(std::lround(rgba[k] * 65535.0f));
            }
            const int colour = append(colours.data(), colours.size() * sizeof(std::uint16_t), n,
                                      TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_VEC4,
                                      TINYGLTF_TARGET_ARRAY_BUFFER);
            m_model.accessors[static_cast<std::size_t>(colour)].normalized = true;
            primitive.attributes["COLOR_0"] = colour;
        }

        const std::size_t indices = written.triangles.size();
        if (n <= std::numeric_limits<std::uint16_t>::max()) {
            const std::vector<std::uint16_t> shortIndices(written.triangles.begin(),
                                                          written.triangles.end());
            primitive.indices = append(shortIndices.data(), indices * sizeof(std::uint16_t),
                                       indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                                       TINYGLTF_TYPE_SCALAR, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        } else {
            primitive.indices = append(written.triangles.data(), indices * sizeof(std::uint32_t),
                                       indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                                       TINYGLTF_TYPE_SCALAR, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        }

        tinygltf::Mesh out;
        out.name = name;
        out.primitives.push_back(std::move(primitive));
        tinygltf::Node node;
        node.name = name;
        node.mesh = static_cast<int>(m_model.meshes.size());
        m_model.meshes.push_back(std::move(out));
        m_model.nodes[static_cast<std::size_t>(m_well)].children.push_back(
            static_cast<int>(m_model.nodes.size()));
        m_model.nodes.push_back(std::move(node));
    }

    void write(const std::string& path, const std::string& shownAs) override {
        // The writer copies the buffer into the file's binary chunk: without the room the
        // buffer grew into, the peak is twice the buffer, not three times.
        m_model.buffers.front().data.shrink_to_fit();
        std::ofstream file(path, std::ios::binary);
        if (!file) throw std::runtime_error(shownAs + ": cannot open file for writing");
        // Through a stream the library opens nothing itself, and its stream's state tells
        // whether every byte was written (the library does not check).
        tinygltf::TinyGLTF gltf;
        const bool serialised = gltf.WriteGltfSceneToStream(&m_model, file, false, true);
        file.close();
        if (!serialised || !file)
            throw std::runtime_error(shownAs + ": cannot write the file (disk full?)");
    }

private:
    // Appends `bytes` to the buffer (4-byte aligned, as every accessor needs) as a buffer view
    // and an accessor of `count` elements; returns the accessor.
    int append(const void* data, std::size_t bytes, std::size_t count, int componentType, int type,
               int target) {
        std::vector<unsigned char>& buffer = m_model.buffers.front().data;
        const std::size_t offset = (buffer.size() + 3) & ~std::size_t{3};
        if (offset + bytes > kMaxGlbBytes - kJsonMargin_bytes) {
            char text[160];
            std::snprintf(text, sizeof text,
                          "a .glb holds at most 4 GiB, and this one passes %.0f MiB",
                          static_cast<double>(offset + bytes) / kMiB);
            throw MeshTooLarge(text);
        }
        buffer.resize(offset + bytes);
        std::memcpy(buffer.data() + offset, data, bytes);
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = offset;
        view.byteLength = bytes;
        view.target = target;
        m_model.bufferViews.push_back(view);
        tinygltf::Accessor accessor;
        accessor.bufferView = static_cast<int>(m_model.bufferViews.size()) - 1;
        accessor.componentType = componentType;
        accessor.count = count;
        accessor.type = type;
        m_model.accessors.push_back(accessor);
        return static_cast<int>(m_model.accessors.size()) - 1;
    }

    // Room left in a .glb for its JSON chunk (about 150 bytes per array).
    static constexpr std::size_t kJsonMargin_bytes = std::size_t{64} << 20;

    tinygltf::Model m_model;
    int m_well = -1;
};

// PLY, STL and OBJ through assimp, which wants the whole scene as its own arrays: an aiMesh
// per segment, each triangle an aiFace.
class AssimpSink : public MeshFileWriter::Sink {
public:
    AssimpSink(MeshFormat format, bool binary) : m_format(format), m_binary(binary) {}

    void beginWell(const std::string& name) override { m_wells.push_back({name, {}}); }

    void add(const reconstruction::Mesh& mesh, const MeshTriangles& written,
             const std::string& name) override {
        const auto n = static_cast<unsigned int>(written.vertices.size());
        auto out = std::make_unique<aiMesh>();
        out->mName = aiString(name);
        out->mMaterialIndex = 0;
        out->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
        out->mNumVertices = n;
        out->mVertices = new aiVector3D[n];
        const bool normals = mesh.normals.size() == mesh.positions.size();
        const bool colours = mesh.colours.size() == mesh.positions.size();
        if (normals) out->mNormals = new aiVector3D[n];
        if (colours) out->mColors[0] = new aiColor4D[n];
        for (unsigned int i = 0; i < n; ++i) {
            const std::uint32_t v = written.vertices[i];
            const glm::vec3& p = mesh.positions[v];
            out->mVertices[i] = aiVector3D(p.x, p.y, p.z);
            if (normals) {
                const glm::vec3& normal = mesh.normals[v];
                out->mNormals[i] = aiVector3D(normal.x, normal.y, normal.z);
            }
            if (colours) {
                const std::uint32_t c = mesh.colours[v];  // 0xRRGGBBAA
                out->mColors[0][i] =
                    aiColor4D(channel(c, 24), channel(c, 16), channel(c, 8), channel(c, 0));
            }
        }
        const std::size_t faces = written.triangles.size() / 3;
        out->mNumFaces = static_cast<unsigned int>(faces);
        out->mFaces = new aiFace[faces];
        for (std::size_t f = 0; f < faces; ++f) {
            aiFace& face = out->mFaces[f];
            face.mNumIndices = 3;
            face.mIndices = new unsigned int[3];
            std::copy_n(written.triangles.begin() + static_cast<std::ptrdiff_t>(3 * f), 3,
                        face.mIndices);
        }
        auto node = std::make_unique<aiNode>(name);
        node->mNumMeshes = 1;
        node->mMeshes = new unsigned int[1]{static_cast<unsigned int>(m_meshes.size())};
        m_wells.back().segments.push_back(std::move(node));
        m_meshes.push_back(std::move(out));
    }

    void write(const std::string& path, const std::string& shownAs) override {
        aiScene scene;  // owns, and frees, everything handed to it below
        scene.mRootNode = new aiNode("caliper3d");
        scene.mNumMaterials = 1;
        scene.mMaterials = new aiMaterial* [1] { wallMaterial() };
        scene.mNumMeshes = static_cast<unsigned int>(m_meshes.size());
        scene.mMeshes = new aiMesh*[m_meshes.size()];
        for (std::size_t i = 0; i < m_meshes.size(); ++i) scene.mMeshes[i] = m_meshes[i].release();
        m_meshes.clear();
        aiNode* root = scene.mRootNode;
        root->mNumChildren = static_cast<unsigned int>(m_wells.size());
        root->mChildren = new aiNode*[m_wells.size()];
        for (std::size_t w = 0; w < m_wells.size(); ++w) {
            Well& well = m_wells[w];
            auto* node = new aiNode(well.name);
            node->mParent = root;
            root->mChildren[w] = node;
            node->mNumChildren = static_cast<unsigned int>(well.segments.size());
            node->mChildren = new aiNode*[well.segments.size()];
            for (std::size_t s = 0; s < well.segments.size(); ++s) {
                node->mChildren[s] = well.segments[s].release();
                node->mChildren[s]->mParent = node;
            }
        }
        m_wells.clear();

        Assimp::Exporter exporter;
        if (exporter.Export(&scene, exporterId(), path.c_str()) != AI_SUCCESS)
            throw std::runtime_error(shownAs + ": cannot write the file (" +
                                     exporter.GetErrorString() + ")");
    }

private:
    struct Well {
        std::string name;
        std::vector<std::unique_ptr<aiNode>> segments;
    };

    const char* exporterId() const {
        switch (m_format) {
            case MeshFormat::Ply:
                // Text only: the library's binary PLY writer (5.2.5, Debian 12) declares the
                // colours uchar and writes them as floats, a file no reader takes (assimp issue
                // #3827, fixed upstream in 2024).
                return "ply";
            case MeshFormat::Stl:
                return m_binary ? "stlb" : "stl";
            case MeshFormat::Obj:
                // Without a material file beside it: the material says only "two-sided".
                return "objnomtl";
            case MeshFormat::Glb:
                break;
        }
        return "";
    }

    static aiMaterial* wallMaterial() {
        auto* material = new aiMaterial;
        const aiString name("wall");
        material->AddProperty(&name, AI_MATKEY_NAME);
        const aiColor4D white(1.0f, 1.0f, 1.0f, 1.0f);
        material->AddProperty(&white, 1, AI_MATKEY_COLOR_DIFFUSE);
        const int twoSided = 1;
        material->AddProperty(&twoSided, 1, AI_MATKEY_TWOSIDED);
        return material;
    }

    MeshFormat m_format;
    bool m_binary;
    std::vector<std::unique_ptr<aiMesh>> m_meshes;
    std::vector<Well> m_wells;
};

std::unique_ptr<MeshFileWriter::Sink> makeSink(MeshFormat format, bool binary) {
    if (format == MeshFormat::Glb) return std::make_unique<GltfSink>();
    return std::make_unique<AssimpSink>(format, binary);
}

}  // namespace

std::optional<MeshFormat> meshFormatFor(const std::string& path) {
    if (endsWith(path, ".glb")) return MeshFormat::Glb;
    if (endsWith(path, ".ply")) return MeshFormat::Ply;
    if (endsWith(path, ".stl")) return MeshFormat::Stl;
    if (endsWith(path, ".obj")) return MeshFormat::Obj;
    return std::nullopt;
}

int meshDetailLevel(MeshDetail detail) {
    return detail == MeshDetail::Full ? 0 : reconstruction::kFirstCoarseLevel;
}

std::vector<std::uint32_t> stripTriangles(const reconstruction::Mesh& mesh) {
    std::vector<std::uint32_t> out;
    const std::vector<std::int32_t>& strips = mesh.stripIndices;
    std::size_t start = 0;  // of the current strip
    for (std::size_t k = 0; k <= strips.size(); ++k) {
        if (k < strips.size() && strips[k] >= 0) continue;
        // Triangle i of a strip is (v_i, v_i+1, v_i+2), every other one turned to keep the
        // strip's winding; each is written reversed.
        for (std::size_t i = start; i + 2 < k; ++i) {
            const auto a = static_cast<std::uint32_t>(strips[i]);
            const auto b = static_cast<std::uint32_t>(strips[i + 1]);
            const auto c = static_cast<std::uint32_t>(strips[i + 2]);
            if (a == b || b == c || a == c) continue;
            if ((i - start) % 2 == 0) {
                out.insert(out.end(), {a, c, b});
            } else {
                out.insert(out.end(), {a, b, c});
            }
        }
        start = k + 1;
    }
    return out;
}

std::size_t meshExportBytes(MeshFormat format, std::size_t triangles) {
    // Peak memory over the well's own, per triangle, of full-detail exports of the 100 m
    // synthetic well (3.84 M triangles; docs/benchmarks.md, "Mesh exports"), rounded up: the
    // .glb buffer and its copy into the file's chunk (44 bytes); assimp's scene, its copy of
    // it, and for PLY and OBJ the whole text in memory (STL 270, PLY 307, OBJ 500).
    switch (format) {
        case MeshFormat::Glb:
            return triangles * 60;
        case MeshFormat::Stl:
            return triangles * 300;
        case MeshFormat::Ply:
            return triangles * 330;
        case MeshFormat::Obj:
            return triangles * 550;
    }
    return 0;
}

MeshFileWriter::MeshFileWriter(MeshFormat format, bool binary, std::size_t memoryLimit_bytes)
    : m_format(format),
      m_binary(binary),
      m_sink(makeSink(format, binary)),
      m_memoryLimit_bytes(memoryLimit_bytes > 0 ? memoryLimit_bytes : physicalMemory()) {}

MeshFileWriter::~MeshFileWriter() = default;

void MeshFileWriter::checkMemory(std::size_t triangles) const {
    const std::size_t bytes = meshExportBytes(m_format, triangles);
    if (m_memoryLimit_bytes == 0 || bytes <= m_memoryLimit_bytes) return;
    char text[256];
    std::snprintf(text, sizeof text,
                  "%zu triangles need about %.0f MiB to write (the mesh library holds the whole "
                  "file before it writes it), more than the %.0f MiB allowed",
                  triangles, static_cast<double>(bytes) / kMiB,
                  static_cast<double>(m_memoryLimit_bytes) / kMiB);
    throw MeshTooLarge(text);
}

void MeshFileWriter::beginWell(const std::string& name) {
    m_sink->beginWell(name);
    m_wellStarted = true;
}

void MeshFileWriter::addMesh(const reconstruction::Mesh& mesh, const std::string& name) {
    MeshTriangles written;
    written.triangles = stripTriangles(mesh);
    if (written.triangles.empty()) return;
    checkMemory(m_counts.triangles + written.triangles.size() / 3);
    // Vertices in the order of the mesh, those no triangle uses left out.
    constexpr std::uint32_t kUnused = ~0u;
    std::vector<std::uint32_t> remap(mesh.positions.size(), kUnused);
    for (std::uint32_t v : written.triangles) remap[v] = 0;
    for (std::size_t v = 0; v < remap.size(); ++v) {
        if (remap[v] == kUnused) continue;
        remap[v] = static_cast<std::uint32_t>(written.vertices.size());
        written.vertices.push_back(static_cast<std::uint32_t>(v));
    }
    for (std::uint32_t& v : written.triangles) v = remap[v];

    if (!m_wellStarted) beginWell("well");
    m_sink->add(mesh, written, name);
    ++m_counts.meshes;
    m_counts.vertices += written.vertices.size();
    m_counts.triangles += written.triangles.size() / 3;
}

void MeshFileWriter::addWell(const reconstruction::WellGeometry& geometry, const std::string& name,
                             MeshDetail detail) {
    const int level = meshDetailLevel(detail);
    if (detail == MeshDetail::Full) {
        // Level 0 joins every pair of measured neighbouring rows with the full spline.
        const auto points =
            static_cast<std::size_t>(reconstruction::lodPyramid(geometry.options()).front().points);
        std::size_t pairs = 0;
        const std::size_t rows = geometry.table().rowCount();
        for (std::size_t r = 0; r + 1 < rows; ++r)
            pairs += geometry.measured(r) && geometry.measured(r + 1) ? 1 : 0;
        checkMemory(m_counts.triangles + 2 * points * pairs);
    }
    beginWell(name);
    for (std::size_t s = 0; s < geometry.segmentCount(); ++s) {
        const reconstruction::SegmentMesh segment =
            reconstruction::buildSegmentLevels(geometry, s, level, level + 1);
        if (!segment.levels.empty())
            addMesh(segment.levels.front(), "segment " + std::to_string(s));
    }
}

void MeshFileWriter::write(const std::string& path) {
    std::unique_ptr<Sink> sink = std::exchange(m_sink, makeSink(m_format, m_binary));
    m_counts = MeshExportCounts();
    m_wellStarted = false;
    // The libraries write a path of their own: a temporary beside the file, renamed over it
    // once whole, so that a failed or killed export leaves the previous file.
    io::AtomicOutput output(path);
    sink->write(output.path(), path);
    output.commit();
}

}  // namespace caliper3d::scenegraph
