#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <QMainWindow>
#include <QSize>

#include "app/desktop/desk_model.h"
#include "app/input_options.h"

class QComboBox;
class QLabel;
class QMenu;
class QProgressBar;
class QPushButton;
class QTimer;
class QToolButton;
class SbVec2s;
class SoQtExaminerViewer;
class SoSeparator;
class SoSwitch;

namespace caliper3d::reconstruction {
class WellLoadPipeline;
}
namespace caliper3d::scenegraph {
class DetailLoader;
class SegmentFeeder;
class ViewOverlay;
class WellScene;
}  // namespace caliper3d::scenegraph

namespace caliper3d::app {

class AnalysisJob;
class DeskModel;
class RetiredLoads;
class WarningsDock;
class WellNavigator;
class FileMenu;
class WellViewer;

// The desktop window: an SoQtExaminerViewer in the centre, a status bar that
// reports loading, and File/View menus. Wells load on a worker thread; their
// segments enter the scene through the SegmentFeeder's timer sensor on this
// (the main) thread, so the window stays responsive while a well loads.
class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Replaces the wells shown by this one; its wellhead (if any) becomes the
    // scene origin.
    void openWell(const WellSource& well, const LoadOptions& options);
    void openWell(const QString& path, const LoadOptions& options);
    // Adds a well to those shown; each loads on its own worker.
    void addWell(const WellSource& well, const LoadOptions& options);
    void addWell(const QString& path, const LoadOptions& options);
    std::size_t wellCount() const { return m_wells.size(); }
    SoQtExaminerViewer* viewer() const;
    bool loading() const;
    // The warnings of the wells shown (reader, survey, geometry), as loaded so
    // far: their count, and the text the warnings dialog shows.
    std::size_t warningCount() const;
    QString warningsText() const;
    QString statusText() const;

    // Draws the wells shown with another radial exaggeration and wall colouring, from the
    // geometry in memory: no file is read again and no path placed again; the coarse levels
    // are rebuilt (two threads) and the detail near the camera follows. Returns false, with
    // the reason in the status bar, while a well still loads or when a well cannot be
    // coloured so (an unknown curve). The colour range is shared by every well.
    bool restyle(double radialExaggeration, const reconstruction::ColourRequest& colour);
    // The same for one well (its record in the model) only, its colour range its own.
    bool restyleWell(int well, const reconstruction::ColourRequest& colour);
    // Shows or hides a well (its record in the model) in the 3D view.
    void setWellVisible(int well, bool visible);
    // Stops every load under way within a block of the log; the wells not yet loaded are
    // removed (a part of a well is never left drawn as if it were the whole).
    void cancelLoading();
    // Picks the wall at `pixel` of the 3D view (Coin's pixels, origin at the bottom left), as a
    // click does: the section hit becomes the current depth and the direction the current
    // azimuth; the camera stays. False when nothing analysed is there.
    bool pickAt(const SbVec2s& pixel);
    // The camera's side of the current depth (follow, inside the hole, flight, zones).
    WellNavigator& navigator() const { return *m_navigator; }
    QProgressBar* loadProgress() const { return m_progress; }
    // Cancelled loads whose workers have not stopped yet (they stop within a block).
    int retiredLoadsRunning() const;
    // The geometry well `i` is drawn from (null until its load has placed it).
    std::shared_ptr<const reconstruction::WellGeometry> geometry(std::size_t i) const;
    // The legend shown over the scene (null before a well is loaded).
    const reconstruction::ColourLegend* legend() const;
    // The wells and the current depth every view follows.
    DeskModel& model() const { return *m_model; }
    // The files of the wells shown, with their surveys and wellheads.
    std::vector<WellSource> wellSources() const;
    // What every well is drawn with (radial exaggeration, colouring): all a newly opened well
    // takes from those shown.
    const LoadOptions& look() const { return m_lastOptions; }
    // File menu, recent files, drops, exports, pictures, reports (app/desktop/file_menu.h).
    FileMenu& files() const { return *m_files; }

protected:
    void closeEvent(QCloseEvent* event) override;

signals:
    void wellLoaded(int segments);  // once per well
    void allWellsLoaded();
    void wellFailed(const QString& message);
    // Once per well, when the report's analysis of it is in the model.
    void wellAnalysed(int well);
    // A load was stopped by cancelLoading (the cancel button).
    void loadCancelled();

private:
    void buildMenus();
    void buildViewMenu();
    void buildDocks();
    void buildProgress();
    void updateProgress();
    void goToDepthDialog();
    void showShortcuts();
    void showLoadError(const QString& name, const QString& message);
    void openDialog(bool add);
    void exportDialog();
    void setView(int direction);
    void viewAll();  // the scene with room around it for the labels at its ends
    static constexpr float kViewAllRoom = 1.12f;  // distance, over SoCamera::viewAll's
    static QSize defaultSize();
    static constexpr QSize kMinimumViewSize{480, 360};
    static constexpr int kProgressSteps = 1000;
    static constexpr int kProgressInterval_ms = 100;
    static constexpr double kReadShare = 0.7;        // of a well's progress bar: reading the log
    static constexpr double kFlightSpeed_m_s = 5.0;  // fly along: the current depth per second
    void setExaggeration(double factor);
    void colourByChosen(int index);
    // The names of the "Colour by" box: the built-in quantities and the first well's curves.
    void fillColourBox();
    // Once every well is loaded: its colours as asked (a quantity other than the departure
    // from bit size, a range, a well without a bit size) and the legend.
    void applyStyleAfterLoad();
    void showWarnings();
    void updateWarningsButton();

    DeskModel* m_model = nullptr;
    std::unique_ptr<RetiredLoads> m_retired;  // declared first: destroyed after the wells
    FileMenu* m_files = nullptr;
    WellViewer* m_viewer = nullptr;
    WellNavigator* m_navigator = nullptr;
    WarningsDock* m_warningsDock = nullptr;
    QMenu* m_docksMenu = nullptr;  // View > Docks: a toggle per dock
    QProgressBar* m_progress = nullptr;
    QToolButton* m_cancelButton = nullptr;
    QTimer* m_progressTimer = nullptr;
    QComboBox* m_colourBox = nullptr;
    std::unique_ptr<scenegraph::DetailLoader> m_detail;
    SoSeparator* m_sceneRoot = nullptr;  // the wells, their annotations; what is exported
    SoSeparator* m_viewRoot = nullptr;   // the viewer's graph: the scene, then the overlay
    std::unique_ptr<scenegraph::ViewOverlay> m_overlay;  // north arrow, radial exaggeration
    QLabel* m_status = nullptr;
    QPushButton* m_warningsButton = nullptr;  // "N warnings": opens the list
    LoadOptions m_lastOptions;
    reconstruction::Wellhead m_origin;  // the first well's wellhead
    // One well being shown: its nodes, and while it loads its worker and feeder.
    // Members are destroyed feeder first, then the worker, then the nodes.
    struct Well {
        WellSource source;
        LoadOptions options;
        io::Diagnostics diagnostics;  // from the worker, once the geometry is ready
        std::shared_ptr<const reconstruction::WellGeometry> geometry;  // once placed
        // The report's section values, computed the first time a colouring needs them.
        std::shared_ptr<const reconstruction::SectionValues> values;
        // The report's analysis (what the docks show), made on a worker once the well loads.
        std::shared_ptr<const reconstruction::WellAnalysis> analysis;
        QString error;              // why the load failed
        SoSwitch* shown = nullptr;  // under the scene's root: the well's scene and annotations
        std::unique_ptr<scenegraph::WellScene> scene;
        // Its depth ticks, labels, name and path above the log, beside the scene's root.
        SoSeparator* annotations = nullptr;
        std::unique_ptr<reconstruction::WellLoadPipeline> pipeline;
        std::unique_ptr<scenegraph::SegmentFeeder> feeder;
        std::unique_ptr<AnalysisJob> analysisJob;  // after the load, until the analysis is in
        int modelIndex = -1;                       // its record in m_model
        bool done = false;
    };
    // The model's record of `well` as it is now, and publishing it there.
    DeskWell record(const Well& well) const;
    void publish(Well& well);
    void analyse(Well& well);
    void wellDone();
    bool restyleWells(double radialExaggeration, const reconstruction::ColourRequest& colour,
                      int only);  // only: a model index, or -1 for every well
    std::vector<std::unique_ptr<Well>>::iterator wellOf(int modelIndex);
    // Adds (or replaces) the well's annotations in the scene, for its geometry as drawn.
    void annotate(Well& well);
    std::vector<std::unique_ptr<Well>> m_wells;
    bool m_viewedAll = false;
    // What the legend shows (a copy: the colouring's per-row values stay with the geometry).
    std::optional<reconstruction::ColourLegend> m_legend;
};

}  // namespace caliper3d::app
