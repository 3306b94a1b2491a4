#include "scenegraph/mesh_export.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include <assimp/scene.h>
#include <gtest/gtest.h>
#include <assimp/Importer.hpp>
#include <glm/geometric.hpp>

#include "reconstruction/mesh/lod_levels.h"
#include "reconstruction/mesh/mesh.h"
#include "reconstruction/section/section_frame.h"
#include "reconstruction/synthetic/synthetic_well.h"
#include "reconstruction/well_geometry.h"
#include "test_support.h"

using namespace caliper3d;
using scenegraph::MeshFormat;

namespace {

std::shared_ptr<const io::SectionTable> exampleTable(double length_m, double step_m) {
    return std::make_shared<const io::SectionTable>(reconstruction::makeSyntheticWell(
        reconstruction::syntheticProfile("example", length_m, step_m)));
}

using Point = std::array<float, 3>;

// Strip windows of three different vertices: the triangles a file should hold.
std::size_t distinctTriangles(const reconstruction::Mesh& mesh) {
    std::size_t count = 0;
    std::vector<std::int32_t> run;
    for (std::size_t k = 0; k <= mesh.stripIndices.size(); ++k) {
        if (k < mesh.stripIndices.size() && mesh.stripIndices[k] >= 0) {
            run.push_back(mesh.stripIndices[k]);
            continue;
        }
        for (std::size_t i = 0; i + 2 < run.size(); ++i)
            count += run[i] != run[i + 1] && run[i + 1] != run[i + 2] && run[i] != run[i + 2];
        run.clear();
    }
    return count;
}

// What a well's meshes at one level hold, as a file of them should.
struct Expected {
    std::size_t meshes = 0, vertices = 0, triangles = 0;
    std::set<Point> distinct;  // positions, once each (segments share their end rings)
    glm::vec3 lo{std::numeric_limits<float>::max()}, hi{-std::numeric_limits<float>::max()};
    std::vector<reconstruction::Mesh> levels;  // per segment
};

Expected expectedAt(const reconstruction::WellGeometry& g, int level) {
    Expected e;
    for (std::size_t s = 0; s < g.segmentCount(); ++s) {
        reconstruction::Mesh mesh =
            std::move(reconstruction::buildSegmentLevels(g, s, level, level + 1).levels.at(0));
        ++e.meshes;
        e.vertices += mesh.positions.size();
        e.triangles += distinctTriangles(mesh);
        for (const glm::vec3& p : mesh.positions) {
            e.distinct.insert({p.x, p.y, p.z});
            e.lo = glm::min(e.lo, p);
            e.hi = glm::max(e.hi, p);
        }
        e.levels.push_back(std::move(mesh));
    }
    return e;
}

// The first few points in one set and not the other, for a failure message.
std::string differences(const std::set<Point>& got, const std::set<Point>& want) {
    std::vector<Point> extra, missing;
    std::set_difference(got.begin(), got.end(), want.begin(), want.end(),
                        std::back_inserter(extra));
    std::set_difference(want.begin(), want.end(), got.begin(), got.end(),
                        std::back_inserter(missing));
    std::string out =
        std::to_string(extra.size()) + " extra, " + std::to_string(missing.size()) + " missing:";
    for (std::size_t i = 0; i < std::min<std::size_t>(extra.size(), 3); ++i)
        out += " +(" + std::to_string(extra[i][0]) + " " + std::to_string(extra[i][1]) + " " +
               std::to_string(extra[i][2]) + ")";
    for (std::size_t i = 0; i < std::min<std::size_t>(missing.size(), 3); ++i)
        out += " -(" + std::to_string(missing[i][0]) + " " + std::to_string(missing[i][1]) + " " +
               std::to_string(missing[i][2]) + ")";
    return out;
}

// Whether every point of `got` lies within `tolerance` of a point of `want`, as many of them:
// text is read back through the library's fast float parser, which may miss the nearest float
// by an ulp.
bool sameWithin(const std::set<Point>& got, const std::set<Point>& want, float tolerance) {
    if (got.size() != want.size()) return false;
    const float inf = std::numeric_limits<float>::infinity();
    for (const Point& p : got) {
        bool found = false;
        for (auto it = want.lower_bound({p[0] - tolerance, -inf, -inf});
             !found && it != want.end() && (*it)[0] <= p[0] + tolerance; ++it)
            found =
                std::abs((*it)[1] - p[1]) <= tolerance && std::abs((*it)[2] - p[2]) <= tolerance;
        if (!found) return false;
    }
    return true;
}

// A file read back with the same library, every mesh of it.
struct ReadBack {
    std::size_t meshes = 0, vertices = 0, faces = 0;
    std::set<Point> distinct;
    glm::vec3 lo{std::numeric_limits<float>::max()}, hi{-std::numeric_limits<float>::max()};
    bool colours = true;    // every mesh has per-vertex colours
    bool triangles = true;  // every face has three corners
    bool outwards = true;   // every face is counter-clockwise about its vertex normals
};

ReadBack readBack(const Assimp::Importer& importer) {
    ReadBack r;
    const aiScene* scene = importer.GetScene();
    for (unsigned int m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh* mesh = scene->mMeshes[m];
        ++r.meshes;
        r.vertices += mesh->mNumVertices;
        r.faces += mesh->mNumFaces;
        r.colours = r.colours && mesh->HasVertexColors(0);
        for (unsigned int v = 0; v < mesh->mNumVertices; ++v) {
            const aiVector3D& p = mesh->mVertices[v];
            r.distinct.insert({p.x, p.y, p.z});
            r.lo = glm::min(r.lo, glm::vec3(p.x, p.y, p.z));
            r.hi = glm::max(r.hi, glm::vec3(p.x, p.y, p.z));
        }
        for (unsigned int f = 0; f < mesh->mNumFaces; ++f) {
            const aiFace& face = mesh->mFaces[f];
            if (face.mNumIndices != 3) {
                r.triangles = false;
                continue;
            }
            if (!mesh->HasNormals()) continue;
            const aiVector3D& a = mesh->mVertices[face.mIndices[0]];
            const aiVector3D& b = mesh->mVertices[face.mIndices[1]];
            const aiVector3D& c = mesh->mVertices[face.mIndices[2]];
            const aiVector3D n = mesh->mNormals[face.mIndices[0]] +
                                 mesh->mNormals[face.mIndices[1]] +
                                 mesh->mNormals[face.mIndices[2]];
            r.outwards = r.outwards && ((b - a) ^ (c - a)) * n > 0.0f;
        }
    }
    return r;
}

const aiNode* findNode(const aiNode* node, const std::string& name) {
    if (name == node->mName.C_Str()) return node;
    for (unsigned int i = 0; i < node->mNumChildren; ++i)
        if (const aiNode* found = findNode(node->mChildren[i], name)) return found;
    return nullptr;
}

float linearFromSrgb(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}
float channel(std::uint32_t rgba, int shift) {
    return static_cast<float>((rgba >> shift) & 0xffu) / 255.0f;
}

struct FormatCase {
    const char* name;
    const char* extension;
    MeshFormat format;
    bool binary;
    bool sharedVertices;  // the file indexes shared vertices (else three per face, as read)
    bool meshPerSegment;  // the file keeps a mesh per segment (else one merged mesh)
    bool colours;
    bool text;  // positions read back within an ulp or so, not to the bit
};

void PrintTo(const FormatCase& c, std::ostream* os) {
    *os << c.name;
}

class MeshExportFormatTest : public testing::TestWithParam<FormatCase> {};

}  // namespace

TEST(MeshExportTest, FormatFollowsTheExtension) {
    EXPECT_EQ(scenegraph::meshFormatFor("a/well.glb"), MeshFormat::Glb);
    EXPECT_EQ(scenegraph::meshFormatFor("well.ply"), MeshFormat::Ply);
    EXPECT_EQ(scenegraph::meshFormatFor("well.stl"), MeshFormat::Stl);
    EXPECT_EQ(scenegraph::meshFormatFor("well.obj"), MeshFormat::Obj);
    EXPECT_EQ(scenegraph::meshFormatFor("well.iv"), std::nullopt);
    EXPECT_EQ(scenegraph::meshFormatFor("well.gltf"), std::nullopt);
    EXPECT_EQ(scenegraph::meshFormatFor(".glb"), std::nullopt);  // no name before it
}

TEST(MeshExportTest, ShownIsTheFinestCoarseLevelAndFullIsLevelZero) {
    EXPECT_EQ(scenegraph::meshDetailLevel(scenegraph::MeshDetail::Shown),
              reconstruction::kFirstCoarseLevel);
    EXPECT_EQ(scenegraph::meshDetailLevel(scenegraph::MeshDetail::Full), 0);
}

TEST(MeshExportTest, StripTrianglesLeaveOutZeroAreaJoinsAndFaceOutwards) {
    // A ring of four joined to a ring of two: A0 B0 A1 B1 A2 B1 A3 B0 A0 B0, of whose eight
    // strip triangles two repeat a vertex.
    reconstruction::Mesh joined;
    joined.positions.resize(6);
    reconstruction::appendClosedStrip(joined.stripIndices, 0, 4, 4, 2);
    ASSERT_EQ(joined.triangleCount(), 8u);
    const std::vector<std::uint32_t> triangles = scenegraph::stripTriangles(joined);
    ASSERT_EQ(triangles.size(), 6u * 3u);
    // The first strip triangle (A0 B0 A1) reversed, the second (B0 A1 B1, turned to A1 B0 B1
    // by the strip) reversed.
    EXPECT_EQ(std::vector<std::uint32_t>(triangles.begin(), triangles.begin() + 6),
              (std::vector<std::uint32_t>{0, 1, 4, 4, 1, 5}));

    // On a real well every triangle, at every level, turns counter-clockwise about the
    // outward vertex normals, and only repeated-vertex triangles are left out.
    reconstruction::GeometryOptions options;
    const reconstruction::WellGeometry geometry(exampleTable(6.0, 0.1), options);
    std::size_t degenerate = 0;
    for (std::size_t s = 0; s < geometry.segmentCount(); ++s) {
        for (const reconstruction::Mesh& mesh : geometry.buildSegment(s).levels) {
            const std::vector<std::uint32_t> t = scenegraph::stripTriangles(mesh);
            EXPECT_EQ(t.size() / 3, distinctTriangles(mesh));
            degenerate += mesh.triangleCount() - t.size() / 3;
            for (std::size_t i = 0; i < t.size(); i += 3) {
                const glm::vec3 &a = mesh.positions[t[i]], &b = mesh.positions[t[i + 1]],
                                &c = mesh.positions[t[i + 2]];
                const glm::vec3 n =
                    mesh.normals[t[i]] + mesh.normals[t[i + 1]] + mesh.normals[t[i + 2]];
                ASSERT_GT(glm::dot(glm::cross(b - a, c - a), n), 0.0f)
                    << "segment " << s << " triangle " << i / 3;
            }
        }
    }
    // Coarse levels join 12-point rings to the 48-point rings segments end with.
    EXPECT_GT(degenerate, 0u);
}

TEST(MeshExportTest, VerticesNoTriangleUsesAreLeftOut) {
    reconstruction::Mesh mesh;
    for (int ring = 0; ring < 2; ++ring)
        for (int j = 0; j < 4; ++j) {
            const float phi = static_cast<float>(j) * 1.5707964f;
            mesh.positions.emplace_back(std::cos(phi), -static_cast<float>(ring), -std::sin(phi));
            mesh.normals.emplace_back(std::cos(phi), 0.0f, -std::sin(phi));
        }
    mesh.positions.emplace_back(5.0f, 5.0f, 5.0f);  // a ring of its own, joined to nothing
    mesh.normals.emplace_back(1.0f, 0.0f, 0.0f);
    reconstruction::appendClosedStrip(mesh.stripIndices, 0, 4, 4);
    scenegraph::MeshFileWriter writer(MeshFormat::Glb);
    writer.addMesh(mesh, "one");
    writer.addMesh(reconstruction::Mesh(), "empty");  // no triangles: nothing added
    EXPECT_EQ(writer.counts().meshes, 1u);
    EXPECT_EQ(writer.counts().vertices, 8u);
    EXPECT_EQ(writer.counts().triangles, 8u);
    const auto path = test::scratch("unused_vertex.glb");
    writer.write(path.string());
    EXPECT_EQ(writer.counts().meshes, 0u);  // released by write
    Assimp::Importer importer;
    ASSERT_NE(importer.ReadFile(path.string(), 0), nullptr) << importer.GetErrorString();
    const ReadBack back = readBack(importer);
    EXPECT_EQ(back.vertices, 8u);
    EXPECT_EQ(back.faces, 8u);
    EXPECT_FLOAT_EQ(back.hi.x, 1.0f);  // the lone vertex at (5, 5, 5) is not in the file
    EXPECT_FLOAT_EQ(back.hi.y, 0.0f);
    EXPECT_FALSE(back.colours);  // the mesh had none
}

TEST_P(MeshExportFormatTest, ShownDetailReadsBackWithEveryVertexTriangleAndBound) {
    const FormatCase& c = GetParam();
    reconstruction::GeometryOptions options;
    const reconstruction::WellGeometry geometry(exampleTable(60.0, 0.1), options);
    const Expected e = expectedAt(geometry, reconstruction::kFirstCoarseLevel);
    // The level written is the one the window shows up front.
    for (std::size_t s = 0; s < geometry.segmentCount(); s += 17)
        EXPECT_EQ(reconstruction::buildCoarseSegment(geometry, s).levels.at(0).positions,
                  e.levels[s].positions);

    scenegraph::MeshFileWriter writer(c.format, c.binary);
    writer.addWell(geometry, "example", scenegraph::MeshDetail::Shown);
    EXPECT_EQ(writer.counts().meshes, e.meshes);
    EXPECT_EQ(writer.counts().vertices, e.vertices);
    EXPECT_EQ(writer.counts().triangles, e.triangles);
    const auto path = test::scratch(std::string("shown_") + c.name + c.extension);
    writer.write(path.string());

    Assimp::Importer importer;
    ASSERT_NE(importer.ReadFile(path.string(), 0), nullptr) << importer.GetErrorString();
    const ReadBack back = readBack(importer);
    EXPECT_TRUE(back.triangles);
    EXPECT_EQ(back.faces, e.triangles);
    EXPECT_EQ(back.vertices, c.sharedVertices ? e.vertices : 3 * e.triangles);
    if (c.text)
        EXPECT_TRUE(sameWithin(back.distinct, e.distinct, 1e-5f))
            << differences(back.distinct, e.distinct);
    else
        EXPECT_TRUE(back.distinct == e.distinct) << differences(back.distinct, e.distinct);
    EXPECT_EQ(back.meshes, c.meshPerSegment ? e.meshes : 1u);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(back.lo[k], e.lo[k], 1e-5f) << k;
        EXPECT_NEAR(back.hi[k], e.hi[k], 1e-5f) << k;
    }
    EXPECT_EQ(back.colours, c.colours);
    EXPECT_TRUE(back.outwards);
}

INSTANTIATE_TEST_SUITE_P(
    EveryFormat, MeshExportFormatTest,
    testing::Values(FormatCase{"glb", ".glb", MeshFormat::Glb, true, true, true, true, false},
                    FormatCase{"ply", ".ply", MeshFormat::Ply, true, true, false, true, true},
                    FormatCase{"stl", ".stl", MeshFormat::Stl, true, false, false, false, false},
                    FormatCase{"ascii_stl", ".stl", MeshFormat::Stl, false, false, false, false,
                               true},
                    FormatCase{"obj", ".obj", MeshFormat::Obj, false, false, true, true, true}),
    [](const testing::TestParamInfo<FormatCase>& info) { return std::string(info.param.name); });

TEST(MeshExportTest, GlbHasANodePerSegmentInTheSceneFrameWithLinearColours) {
    reconstruction::GeometryOptions options;
    const reconstruction::WellGeometry geometry(exampleTable(60.0, 0.1), options);
    const Expected e = expectedAt(geometry, reconstruction::kFirstCoarseLevel);
    const auto path = test::scratch("nodes.glb");
    scenegraph::MeshFileWriter writer(MeshFormat::Glb);
    writer.addWell(geometry, "example", scenegraph::MeshDetail::Shown);
    writer.write(path.string());
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path.string(), 0);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();

    const aiNode* well = findNode(scene->mRootNode, "example");
    ASSERT_NE(well, nullptr);
    ASSERT_EQ(well->mNumChildren, geometry.segmentCount());
    for (std::size_t s = 0; s < geometry.segmentCount(); ++s) {
        const aiNode* node = well->mChildren[s];
        ASSERT_EQ(std::string(node->mName.C_Str()), "segment " + std::to_string(s));
        ASSERT_EQ(node->mNumMeshes, 1u);
        EXPECT_TRUE(node->mTransformation.IsIdentity());
        const aiMesh* mesh = scene->mMeshes[node->mMeshes[0]];
        const reconstruction::Mesh& written = e.levels[s];
        ASSERT_EQ(mesh->mNumVertices, written.positions.size()) << s;
        ASSERT_TRUE(mesh->HasVertexColors(0));
        for (unsigned int v = 0; v < mesh->mNumVertices; v += 7) {
            EXPECT_EQ(mesh->mVertices[v], aiVector3D(written.positions[v].x, written.positions[v].y,
                                                     written.positions[v].z));
            // glTF's COLOR_0 is linear: the scene's sRGB colour converted (16 bits a channel).
            const aiColor4D& colour = mesh->mColors[0][v];
            const std::uint32_t rgba = written.colours[v];
            EXPECT_NEAR(colour.r, linearFromSrgb(channel(rgba, 24)), 1e-5f);
            EXPECT_NEAR(colour.g, linearFromSrgb(channel(rgba, 16)), 1e-5f);
            EXPECT_NEAR(colour.b, linearFromSrgb(channel(rgba, 8)), 1e-5f);
            EXPECT_NEAR(colour.a, channel(rgba, 0), 1e-5f);
        }
    }

    // The scene frame is glTF's: y up, x east, z south, metres from the wellhead. The example
    // is vertical to a third of its length, then builds towards azimuth 45 (north-east).
    const aiMesh* top = scene->mMeshes[well->mChildren[0]->mMeshes[0]];
    const double topSegmentBottom_m = geometry.table().depth_m[geometry.segmentRows(0).second];
    for (unsigned int v = 0; v < top->mNumVertices; ++v) {
        EXPECT_LE(top->mVertices[v].y, -geometry.table().depth_m.front() + 1e-4);
        EXPECT_GE(top->mVertices[v].y, -topSegmentBottom_m - 1e-4);
    }
    const std::size_t last = geometry.segmentCount() - 1;
    const aiMesh* bottom = scene->mMeshes[well->mChildren[last]->mMeshes[0]];
    aiVector3D centre(0.0f, 0.0f, 0.0f);
    for (unsigned int v = 0; v < bottom->mNumVertices; ++v) centre += bottom->mVertices[v];
    centre /= static_cast<float>(bottom->mNumVertices);
    const auto [first, lastRow] = geometry.segmentRows(last);
    const reconstruction::Ned axis = geometry.centre((first + lastRow) / 2);  // north, east, down
    EXPECT_GT(axis.x, 0.5);
    EXPECT_NEAR(axis.x, axis.y, 1e-6);  // azimuth 45
    EXPECT_NEAR(centre.x, axis.y, 0.05);
    EXPECT_NEAR(centre.y, -axis.z, 0.05);
    EXPECT_NEAR(centre.z, -axis.x, 0.05);
}

TEST(MeshExportTest, PlyKeepsTheScenesColours) {
    reconstruction::GeometryOptions options;
    const reconstruction::WellGeometry geometry(exampleTable(6.0, 0.1), options);
    const Expected e = expectedAt(geometry, reconstruction::kFirstCoarseLevel);
    const auto path = test::scratch("colours.ply");
    scenegraph::MeshFileWriter writer(MeshFormat::Ply, true);
    writer.addWell(geometry, "example", scenegraph::MeshDetail::Shown);
    writer.write(path.string());
    {
        // Text even when binary is asked for (the library's binary PLY garbles colours).
        std::ifstream in(path);
        std::string magic, format;
        std::getline(in, magic);
        std::getline(in, format);
        EXPECT_EQ(format, "format ascii 1.0");
    }
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path.string(), 0);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    ASSERT_EQ(scene->mNumMeshes, 1u);  // merged, segment after segment
    const aiMesh* mesh = scene->mMeshes[0];
    ASSERT_TRUE(mesh->HasVertexColors(0));
    unsigned int v = 0;
    for (const reconstruction::Mesh& written : e.levels)
        for (std::size_t i = 0; i < written.positions.size(); ++i, ++v) {
            ASSERT_LT(v, mesh->mNumVertices);
            const aiColor4D& colour = mesh->mColors[0][v];
            // Bytes in the file, as the scene has them (to the byte: 1/255).
            EXPECT_NEAR(colour.r, channel(written.colours[i], 24), 1.01f / 255.0f);
            EXPECT_NEAR(colour.g, channel(written.colours[i], 16), 1.01f / 255.0f);
            EXPECT_NEAR(colour.b, channel(written.colours[i], 8), 1.01f / 255.0f);
        }
    EXPECT_EQ(v, mesh->mNumVertices);
}

TEST(MeshExportTest, FullDetailIsEverySectionWithTheFullSpline) {
    reconstruction::GeometryOptions options;
    const reconstruction::WellGeometry geometry(exampleTable(5.0, 0.1), options);
    const std::size_t rows = geometry.table().rowCount();
    ASSERT_EQ(geometry.measuredRows(), rows);
    // Every neighbouring pair of rows joined by 2 x 48 triangles; a ring of 48 per row, the
    // rows segments share written once in each.
    const std::size_t triangles = 2 * 48 * (rows - 1);
    const std::size_t vertices = 48 * (rows + geometry.segmentCount() - 1);
    const auto path = test::scratch("full.glb");
    scenegraph::MeshFileWriter writer(MeshFormat::Glb);
    writer.addWell(geometry, "example", scenegraph::MeshDetail::Full);
    EXPECT_EQ(writer.counts().triangles, triangles);
    EXPECT_EQ(writer.counts().vertices, vertices);
    writer.write(path.string());
    Assimp::Importer importer;
    ASSERT_NE(importer.ReadFile(path.string(), 0), nullptr) << importer.GetErrorString();
    const ReadBack back = readBack(importer);
    EXPECT_EQ(back.faces, triangles);
    EXPECT_EQ(back.vertices, vertices);
    const std::set<Point> distinct = expectedAt(geometry, 0).distinct;
    EXPECT_TRUE(back.distinct == distinct) << differences(back.distinct, distinct);
}

TEST(MeshExportTest, AFullDetailExportPastTheMemoryLimitIsRefusedBeforeBuilding) {
    reconstruction::GeometryOptions options;
    const reconstruction::WellGeometry geometry(exampleTable(5.0, 0.1), options);
    const std::size_t triangles = 2 * 48 * (geometry.table().rowCount() - 1);
    for (const MeshFormat format : {MeshFormat::Glb, MeshFormat::Ply}) {
        const std::size_t bytes = scenegraph::meshExportBytes(format, triangles);
        {
            scenegraph::MeshFileWriter writer(format, true, bytes - 1);
            try {
                writer.addWell(geometry, "example", scenegraph::MeshDetail::Full);
                FAIL() << "expected MeshTooLarge";
            } catch (const scenegraph::MeshTooLarge& e) {
                EXPECT_NE(std::string(e.what()).find(std::to_string(triangles) + " triangles"),
                          std::string::npos)
                    << e.what();
            }
            EXPECT_EQ(writer.counts().meshes, 0u);  // nothing was built
        }
        scenegraph::MeshFileWriter writer(format, true, bytes);
        writer.addWell(geometry, "example", scenegraph::MeshDetail::Full);
        EXPECT_EQ(writer.counts().triangles, triangles);
    }
}

TEST(MeshExportTest, UnwritablePathIsAnErrorNamingTheFile) {
    reconstruction::GeometryOptions options;
    const reconstruction::WellGeometry geometry(exampleTable(3.0, 0.1), options);
    for (const MeshFormat format :
         {MeshFormat::Glb, MeshFormat::Ply, MeshFormat::Stl, MeshFormat::Obj}) {
        scenegraph::MeshFileWriter writer(format);
        writer.addWell(geometry, "example", scenegraph::MeshDetail::Shown);
        try {
            writer.write("/nonexistent-dir/x.mesh");
            FAIL() << "expected an error";
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/x.mesh"), std::string::npos)
                << e.what();
        }
    }
}
