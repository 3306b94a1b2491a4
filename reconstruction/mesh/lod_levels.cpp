#include "reconstruction/mesh/lod_levels.h"

#include <stdexcept>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include "reconstruction/mesh/colour_map.h"
#include "reconstruction/well_geometry.h"

namespace caliper3d::reconstruction {

namespace {

// Appends the ring of one row: the spline samples (spline) or the pads themselves, with outward
// normals and colours by departure from the bit.
void appendRing(const WellGeometry& g, Mesh& mesh, std::size_t row, bool spline) {
    std::vector<double> pads(static_cast<std::size_t>(g.knotCount()));
    g.sectionKnots(row, pads.data());
    std::vector<double> radii;
    if (spline) {
        radii.resize(static_cast<std::size_t>(g.sampler().samples()));
        g.sampler().sample(pads.data(), radii.data());
    } else {
        radii = pads;
    }
    const int points = static_cast<int>(radii.size());
    const SectionFrame& f = g.frame(row);
    const Ned c = g.centre(row);
    const double bitRadius = g.bitRadius_mm(row);
    const std::size_t base = mesh.positions.size();
    for (int j = 0; j < points; ++j) {
        const double phi = glm::two_pi<double>() * j / points;
        const double drawn_m =
            radii[static_cast<std::size_t>(j)] / 1000.0 * g.options().radialExaggeration;
        const Ned p = c + drawn_m * f.direction(phi);
        mesh.positions.emplace_back(toScene(p));
        mesh.colours.push_back(gaugeColour(radii[static_cast<std::size_t>(j)], bitRadius));
    }
    // Outward normals: in-plane tangent (clockwise) crossed with the hole axis.
    for (int j = 0; j < points; ++j) {
        const glm::vec3& next = mesh.positions[base + static_cast<std::size_t>((j + 1) % points)];
        const glm::vec3& prev =
            mesh.positions[base + static_cast<std::size_t>((j + points - 1) % points)];
        const glm::dvec3 d = glm::dvec3(next - prev);
        glm::dvec3 normal = glm::cross(d, toScene(f.tangent));
        const double len = glm::length(normal);
        mesh.normals.emplace_back(
            len > 0 ? normal / len : toScene(f.direction(glm::two_pi<double>() * j / points)));
    }
}

bool measuredThrough(const WellGeometry& g, std::size_t first, std::size_t last) {
    for (std::size_t r = first; r <= last; ++r)
        if (!g.measured(r)) return false;
    return true;
}

// Rings of the measured rows among `rows`; a strip joins two consecutive ones
// only when every row between them is measured, so a no-data interval is a
// gap in the wall at every level (the path line still crosses it).
Mesh buildLevel(const WellGeometry& g, const std::vector<std::size_t>& rows, bool spline) {
    Mesh mesh;
    const int points = spline ? g.sampler().samples() : g.knotCount();
    mesh.positions.reserve(rows.size() * static_cast<std::size_t>(points));
    std::int32_t rings = 0;
    bool joinable = false;  // the last ring appended was rows[i - 1]
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (!g.measured(rows[i])) {
            joinable = false;
            continue;
        }
        appendRing(g, mesh, rows[i], spline);
        ++rings;
        if (joinable && measuredThrough(g, rows[i - 1], rows[i]))
            appendClosedStrip(mesh.stripIndices, (rings - 2) * points, (rings - 1) * points,
                              points);
        joinable = true;
    }
    return mesh;
}

// Rows of a coarse level: picked at a fixed depth spacing, ends always kept so that
// neighbouring segments meet without a gap at every level.
std::vector<std::size_t> coarseRows(const WellGeometry& g, std::size_t first, std::size_t last,
                                    double spacing_m) {
    const std::vector<double>& depth = g.table().depth_m;
    std::vector<std::size_t> rows{first};
    double next = depth[first] + spacing_m;
    for (std::size_t r = first + 1; r < last; ++r) {
        // The measured rows next to a gap are kept too, so that the wall
        // reaches the gap's edges as it does at full detail.
        const bool gapEdge = g.measured(r) && (!g.measured(r - 1) || !g.measured(r + 1));
        if (depth[r] >= next || gapEdge) {
            rows.push_back(r);
            next = depth[r] + spacing_m;
        }
    }
    rows.push_back(last);
    return rows;
}

}  // namespace

SegmentMesh buildSegmentMesh(const WellGeometry& geometry, std::size_t segment) {
    if (segment >= geometry.segmentCount())
        throw std::out_of_range("buildSegmentMesh: no segment " + std::to_string(segment));
    const auto [first, last] = geometry.segmentRows(segment);
    SegmentMesh out;
    out.index = segment;
    out.firstRow = first;
    out.lastRow = last;
    out.top_m = geometry.table().depth_m[first];
    out.bottom_m = geometry.table().depth_m[last];

    std::vector<std::size_t> all;
    for (std::size_t r = first; r <= last; ++r) all.push_back(r);
    out.levels.push_back(buildLevel(geometry, all, true));
    for (double spacing :
         {geometry.options().coarseSpacing_m, geometry.options().coarsestSpacing_m})
        out.levels.push_back(
            buildLevel(geometry, coarseRows(geometry, first, last, spacing), false));

    const glm::dvec3 a = toScene(geometry.centre(first)), b = toScene(geometry.centre(last));
    out.centre = glm::vec3((a + b) / 2.0);
    out.radius = static_cast<float>(glm::length(b - a) / 2.0 + 1.0);
    return out;
}

}  // namespace caliper3d::reconstruction
