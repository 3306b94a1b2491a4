#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "io/picks_reader.h"
#include "reconstruction/mesh/lod_levels.h"
#include "scenegraph/node_ref.h"

class SoGroup;
class SoSeparator;
class SoSwitch;

namespace caliper3d::reconstruction {
class WellGeometry;
struct CoarseMeshes;
}  // namespace caliper3d::reconstruction

namespace caliper3d::scenegraph {

class WellScene;
struct AnnotationView;
struct PlannedWell;
struct WellLabels;

// The nodes one shown well owns (FreeCAD's view provider): a switch that shows or hides it,
// its WellScene, and its annotations (depth ticks, labels, name, the path above the log).
//
//   parent
//     shown: SoSwitch
//       WellScene::root()
//       annotations (once the well is placed)
//
// The switch is added under `parent` on construction and removed on destruction. Main thread
// only.
class WellView {
public:
    // Its scene's segments hold their levels from `firstCoarseLevel` on (rebuild included).
    explicit WellView(SoGroup* parent, int firstCoarseLevel = reconstruction::kFirstCoarseLevel);
    ~WellView();
    WellView(const WellView&) = delete;
    WellView& operator=(const WellView&) = delete;

    WellScene& scene() const { return *m_scene; }
    SoSwitch* shown() const { return m_shown.get(); }
    void setVisible(bool visible);
    bool visible() const;

    // Image-log picks drawn with the annotations (scenegraph/pick_markers.h) from the next
    // annotate() on.
    void setPicks(std::vector<io::Pick> picks) { m_picks = std::move(picks); }
    // Whether the annotations carry depth ticks, from the next annotate() on (a window of
    // several wells ticks the current one only).
    void setDepthTicks(bool ticks) { m_depthTicks = ticks; }
    bool depthTicks() const { return m_depthTicks; }
    // Adds (or replaces) the annotations for `geometry` as drawn at `radialExaggeration`,
    // every label where it first goes.
    void annotate(const reconstruction::WellGeometry& geometry, double radialExaggeration);
    // The same seen as `view` says, with its labels as placed (placeAnnotations).
    void annotate(const reconstruction::WellGeometry& geometry, const AnnotationView& view,
                  const WellLabels& labels);
    // A new scene in place of the one shown, every segment's coarse levels built here (a
    // restyled geometry), and its annotations.
    void rebuild(const reconstruction::WellGeometry& geometry, double radialExaggeration);
    // The same from coarse meshes built elsewhere (a well of a field held lean, from its plan
    // and the rows it holds: reconstruction::buildCoarseMeshes), `geometry` those rows as drawn.
    void rebuild(const reconstruction::WellGeometry& geometry,
                 const reconstruction::CoarseMeshes& meshes, double radialExaggeration);
    // The same with its segments made when near (planWaitingWell): the spans now, each
    // segment's nodes when the camera first comes near enough (WellScene::wantedDetail).
    void rebuild(const reconstruction::WellGeometry& geometry, PlannedWell planned,
                 double radialExaggeration);
    int firstCoarseLevel() const { return m_firstCoarseLevel; }

private:
    // Shows `scene` in place of the scene shown, and its annotations for `geometry`.
    void replaceScene(std::unique_ptr<WellScene> scene,
                      const reconstruction::WellGeometry& geometry, double radialExaggeration);
    // Shows `annotations` (the well's, made for `radialExaggeration`) with the picks.
    void show(SoSeparator* annotations, const reconstruction::WellGeometry& geometry,
              double radialExaggeration);

    SoGroup* m_parent = nullptr;
    NodeRef<SoSwitch> m_shown;
    std::unique_ptr<WellScene> m_scene;
    SoSeparator* m_annotations = nullptr;  // a child of m_shown
    std::vector<io::Pick> m_picks;
    bool m_depthTicks = true;
    int m_firstCoarseLevel = reconstruction::kFirstCoarseLevel;
};

}  // namespace caliper3d::scenegraph
