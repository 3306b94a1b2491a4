#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>

#include <glm/vec3.hpp>

#include "app/desktop/background_job.h"
#include "app/input_options.h"
#include "app/lean_well.h"
#include "reconstruction/analysis/depth_match.h"
#include "reconstruction/load/detail_worker.h"
#include "scenegraph/detail_loader.h"
#include "scenegraph/label_placement.h"
#include "scenegraph/node_ref.h"
#include "scenegraph/picture/picture.h"
#include "scenegraph/segment_feeder.h"
#include "scenegraph/well_annotations.h"

class SbVec2s;
class SbViewportRegion;
class SoCamera;
class SoNode;
class SoSeparator;

namespace caliper3d::app {

class DeskModel;
class RetiredLoads;

// A click on the wall, as the session found it: the well (its record in the model), the
// section and direction hit, and a line for the status bar.
struct WellPick {
    int well = -1;
    std::size_t row = 0;
    double azimuth_deg = 0.0;
    QString text;
};

// How far the loads under way have got: reading is the first 70 % of a well's share
// (the fraction of the log read), drawing the rest (segments attached over the well's
// segments); the fraction is the mean over the wells loading.
struct LoadProgress {
    bool busy = false;
    double fraction = 0.0;  // 0..1
    // "Reading NAME", "Drawing NAME", or "Loading N wells, D of T done" (D loaded or failed)
    QString text;
};

// The wells shown (FreeCAD's App::Document): opens, adds, cancels, restyles, shows and hides
// them. Per well it owns the load pipeline, the segment feeder, the analysis job and the
// well's Coin nodes (scenegraph::WellView), keyed by a stable id; everything a view reads
// about a well (source, options, geometry, analysis, diagnostics, error, visibility) it
// writes into the DeskModel, the only store. It makes no widget; it reports by signals.
// Main thread only (Coin nodes are made here; workers hand over plain data).
class WellSession : public QObject {
    Q_OBJECT

public:
    // `probe` tells the detail loader where the camera is (null: no camera, no detail).
    WellSession(DeskModel& model, scenegraph::DetailLoader::CameraProbe probe,
                QObject* parent = nullptr);
    ~WellSession() override;
    WellSession(const WellSession&) = delete;
    WellSession& operator=(const WellSession&) = delete;

    // Every well's nodes: what a viewer shows and a scene export writes.
    SoSeparator* sceneRoot() const { return m_sceneRoot.get(); }
    DeskModel& model() const { return m_model; }

    // Replaces the wells shown by this one; its wellhead (if any) becomes the scene origin.
    // Returns the well's id.
    int openWell(const WellSource& source, const LoadOptions& options);
    int openWell(const QString& path, const LoadOptions& options);
    // Adds a well to those shown; each loads on its own worker.
    int addWell(const WellSource& source, const LoadOptions& options);
    int addWell(const QString& path, const LoadOptions& options);
    // Adds another run of the well whose first run is `mainId` (a well's id): it loads as a
    // well does, hidden (its wall lies on the main run's), is grouped under the main run in
    // the model (DeskWell::runOf) and, once both are analysed, depth-matched to it
    // (DeskWell::mapping). docs/user-guide.md, "Runs of one well".
    int addRun(const WellSource& source, const LoadOptions& options, int mainId);
    // Stops every load under way within a block of the log; the wells not yet loaded are
    // removed (a part of a well is never left drawn as if it were the whole).
    void cancelLoading();

    // Draws the wells with another radial exaggeration and wall colouring from the geometry
    // in memory: no file is read again and no path placed again; the coarse levels are
    // rebuilt and the detail near the camera follows. False, with the reason in status(),
    // while a well still loads or when a well cannot be coloured so (an unknown curve). The
    // colour range is shared by every well.
    bool restyle(double radialExaggeration, const reconstruction::ColourRequest& colour);
    // The exaggeration is the user's (--exaggerate, the View menu): loads keep it. Until
    // then, once every well is loaded they are drawn with the one `caliper3d render` chooses
    // for its default picture of them (scenegraph::chooseExaggeration).
    void keepExaggeration() { m_exaggerationKept = true; }
    bool exaggerationKept() const { return m_exaggerationKept; }
    // The same for one well (its record in the model) only, its colour range its own.
    bool restyleWell(int well, const reconstruction::ColourRequest& colour);
    // Shows or hides a well (its record in the model).
    void setWellVisible(int well, bool visible);

    std::size_t wellCount() const { return m_wells.size(); }
    // Whether this opening's first segments are shown (firstSegmentsShown sent).
    bool framed() const { return m_framed; }
    // Wells load a few at a time (loadsAtOnce: the machine's threads, at least 2), in the
    // order they were added: a field of a hundred started at once had two hundred threads
    // share the cores with the window, which showed nothing for eight seconds. A well added
    // beyond them waits its turn (no geometry yet, its load fraction 0); each load that ends
    // starts the next. loadsRunning: the loads started and not ended.
    static int loadsAtOnce();
    int loadsRunning() const;
    // True until every well's load has ended (one loaded as its geometry only: until it is
    // drawn, Well::drawn) and what follows the last one is done: the
    // colours and exaggeration the whole set decides (applyStyleAfterLoad), allWellsLoaded.
    bool loading() const;
    LoadProgress progress() const;
    // Writes each loading well's fraction done into its record (DeskWell::loadFraction), where
    // the wells dock shows it; a timer calls it while wells load.
    void publishProgress();
    // The warnings of the wells shown (reader, survey, geometry) as loaded so far.
    std::size_t warningCount() const;
    QString warningsText() const;
    // The files of the wells shown, with their surveys and wellheads.
    std::vector<WellSource> wellSources() const;
    // What every well is drawn with (radial exaggeration, colouring): all a newly opened
    // well takes from those shown.
    const LoadOptions& look() const { return m_look; }
    // The radial exaggerations the wells shown are drawn at, increasing: the look's alone,
    // but while a field loads, where its wells drawn from their plans already take the one
    // the field is bound for (loadExaggeration) and those drawn as they loaded do not yet.
    std::vector<double> drawnExaggerations() const;
    // The legend of the wall's colours (null before a well is loaded).
    const reconstruction::ColourLegend* legend() const;
    // The visible wells' scenes: their logs, without the path above or the labels.
    std::vector<SoNode*> wellScenes() const;
    // The geometry well `i` (a record of the model) is drawn from (null until placed).
    std::shared_ptr<const reconstruction::WellGeometry> geometry(std::size_t i) const;
    // The scene well `i` (a record of the model) is drawn in (null when there is none).
    const scenegraph::WellScene* scene(std::size_t i) const;
    // The visible wells with geometry, in the model's order, as a picture draws them
    // (scenegraph::drawPicture): each in a scene of its own, built here; a well held lean drawn
    // from its plan and the rows it holds, and read whole again where the picture's camera
    // wants its finer levels. Main thread only.
    std::vector<scenegraph::PictureWell> pictureWells() const;
    // What the wall can be coloured by: the built-in quantities and the first well's curves.
    std::vector<std::string> colourQuantities() const;
    // Cancelled loads whose workers have not stopped yet (they stop within a block).
    int retiredLoadsRunning() const;

    // A field held lean (docs/architecture.md, "The window holds a field lean"): once its
    // wells hold more than `rows` rows, every loaded and analysed well but the current one (and
    // the runs of one well) keeps a sample of its rows and no analysis. It is drawn from the
    // plan of its coarse meshes, and read whole again from its log for the detail near the
    // camera and when it becomes the current well. 0: every well is held whole.
    void setFieldRowBudget(std::size_t rows) { m_rowBudget = rows; }
    std::size_t fieldRowBudget() const { return m_rowBudget; }
    // Whether well i (a record of the model) is held lean now.
    bool heldLean(int well) const;
    // Wells being made lean, or read whole again to become current or to be restyled.
    int leanJobsRunning() const;
    // Nothing left to do after the loads: every well placed is analysed or held lean, and no
    // well is being made lean or read again.
    bool settled() const;

    // Every visible well's name and the ticked well's depth labels placed for `camera`, seen in
    // a view of `width` x `height` pixels, with tick marks unless `tickMarks` is false (down the
    // hole): no label over another nor over `obstacles` (the caption, the legend). The window
    // calls it once its camera rests; a well loaded, ticked, shown or restyled after it has its
    // labels where they first go until the next call (annotationGeneration).
    // Returns how many of the wells named in view had no room for their name.
    scenegraph::NamesInView placeLabels(const SoCamera& camera, int width, int height,
                                        bool tickMarks,
                                        const std::vector<scenegraph::ScreenBox>& obstacles);
    // Counts the times a well's labels went back to where they first go.
    unsigned annotationGeneration() const { return m_annotationGeneration; }

    // The wall at `pixel` of a view of `root` (Coin's pixels, origin bottom left) among the
    // visible wells analysed or held lean; nothing when none is hit. On a well held lean it
    // gives the row held nearest the point hit and remembers the point: once the well, made
    // current, is read whole, the current section becomes the one hit.
    std::optional<WellPick> pick(SoNode* root, const SbViewportRegion& viewport,
                                 const SbVec2s& pixel);

signals:
    void status(const QString& text);
    void loadStarted();
    // The first segments of a load are in the scene (the camera may frame them).
    void firstSegmentsShown();
    void wellLoaded(int segments);  // once per well
    void allWellsLoaded();
    // A well could not be loaded: its file's name and why (file, line and reason).
    void wellFailed(const QString& name, const QString& message);
    void wellAnalysed(int well);  // its record in the model now holds the report's analysis
    void loadCancelled();
    void warningsChanged();
    // The legend, exaggeration or colouring the wells are drawn with changed.
    void lookChanged();

private:
    struct Well;
    struct LeanForm;
    Well* find(int id) const;
    int modelIndex(const Well& well) const;
    template <typename Edit>
    void edit(const Well& well, Edit change);
    void analyse(Well& well);
    void matchRuns(int modelIndex);  // the depth match of a run to its main run, when due
    void runMatched(int id, int mainId, const std::optional<reconstruction::DepthMapping>& mapping,
                    const std::string& error);
    bool allAnalysed() const;
    static void giveBackFreedMemory();  // once every well is loaded and analysed
    void startWaitingLoads();
    // What the well's segment feeder calls as its load arrives (geometry, warnings, progress,
    // the end), its picks read from `picksPath` ("" none) once it is placed.
    scenegraph::SegmentFeeder::Callbacks feederCallbacks(Well& w, const std::string& picksPath);
    void wellDone();
    // Once every well is loaded and drawn: the colours and exaggeration the set decides
    // (applyStyleAfterLoad), then allWellsLoaded.
    void endLoadWhenDone();
    double loadFraction(const Well& well) const;
    void applyStyleAfterLoad();
    // The exaggeration a field's well drawn from its plan while the field loads is drawn at:
    // the one the wells placed so far would get (applyStyleAfterLoad's choice), taken again
    // each time their count doubles; the look's where it is kept.
    double loadExaggeration();
    // Depth ticks on the current well only when several wells have geometry (their labels
    // would pile up), on the one well otherwise; re-annotates the wells whose ticks change.
    void tickCurrentWell();
    // The well's annotations for `geometry` at `radialExaggeration`, labels where they first go.
    void annotate(Well& well, const reconstruction::WellGeometry& geometry,
                  double radialExaggeration);
    // A well's new colours, made for its geometry of then.
    struct ColouredWell {
        int id = -1;
        std::shared_ptr<const reconstruction::WellGeometry> geometry;
        // The whole well's colours; held lean (`lean`), those of the rows it holds.
        std::shared_ptr<const reconstruction::WallColouring> colouring;
        std::shared_ptr<const LeanForm> lean;
        std::optional<reconstruction::ColourRequest> shared;  // the range shared, if any
        std::size_t wells = 1;                                // by this many wells
    };
    // Restyles the chosen wells (-1: every well), then calls `applied`; colouring by change
    // starts a worker and applies when it is in. False (and a status) when nothing is done.
    bool restyleWells(double radialExaggeration, const reconstruction::ColourRequest& colour,
                      int onlyId, const std::function<void()>& applied);
    bool startChangeColouring(double radialExaggeration,
                              const reconstruction::ColourRequest& colour, int onlyId,
                              const std::function<void()>& applied);
    void applyColourings(double radialExaggeration, const reconstruction::ColourRequest& colour,
                         const std::vector<ColouredWell>& coloured, const QElapsedTimer& clock);

    // A field held lean (setFieldRowBudget).
    bool mayBeLean() const;  // a budget is set, there are wells to hold lean, no change colouring
    // The rows of a well placed (its whole rows where it is held lean); nullopt while it is not.
    std::optional<std::size_t> placedRows(const Well& well) const;
    bool leanDue() const;  // the wells hold more rows than the budget
    // They will once every well is read, by the wells placed and the files of those not yet
    // placed (WellSession::startWaitingLoads).
    bool leanExpected() const;
    // Whether a loaded well held whole may be made lean: not the current well, not a run of one
    // well, not being made lean and not refused.
    bool mayHoldLean(const Well& well) const;
    // At the end of a well's load: made lean straight away when due (it is not analysed: a well
    // held lean keeps no analysis), else analysed.
    void analyseOrHoldLean(Well& well);
    // Draws a well whose load drew nothing (Well::drawn) from its whole geometry; ends the
    // load where it was the last thing waited for.
    void drawWhole(Well& well);
    // Draws a well its load left undrawn by `rebuild` (its view's scene replaced: the detail
    // loader forgets the old one), then ends the load where it was the last thing waited for.
    void drawNow(Well& well, const std::function<void()>& rebuild);
    // Analyses a well held whole that has no analysis, nor one under way (one not made lean).
    void analyseIfWhole(Well& well);
    // Starts making lean every loaded well that is held whole and may be held lean (once its
    // analysis, if one is under way, is in).
    void holdLeanWhereDue();
    void startLeanForm(Well& well);
    void holdLean(Well& well, std::shared_ptr<const LeanForm> form);
    // Reads the current well, held lean, whole again with its analysis.
    void startWholeRead(Well& well);
    void followCurrent();
    // Reads the wells held lean that cannot be drawn so from what they hold, then restyles.
    bool startLeanReading(double radialExaggeration, const reconstruction::ColourRequest& colour,
                          int onlyId, const std::function<void()>& applied);
    // What the detail loader builds the well's finer levels from: its geometry, or held lean,
    // the whole well read again as drawn (wholeReader).
    void setDetail(Well& well);
    reconstruction::WholeWellReader wholeReader(const Well& well) const;

    DeskModel& m_model;
    std::unique_ptr<RetiredLoads> m_retired;  // declared first: destroyed after the wells
    scenegraph::NodeRef<SoSeparator> m_sceneRoot;
    std::unique_ptr<scenegraph::DetailLoader> m_detail;
    std::vector<std::unique_ptr<Well>> m_wells;
    int m_nextId = 0;
    LoadOptions m_look;
    reconstruction::Wellhead m_origin;  // the first well's wellhead
    bool m_framed = false;              // firstSegmentsShown sent for this opening
    bool m_exaggerationKept = false;
    // loadExaggeration's, and the count of wells it was taken over (0: none yet).
    double m_loadExaggeration = 1.0;
    int m_loadExaggerationWells = 0;
    unsigned m_annotationGeneration = 0;
    // Loads that have ended and whose end the event loop has still to take (wellDone):
    // loading() stays true until it has.
    int m_endsQueued = 0;
    QString m_loadedText;    // the last load's status line, its exaggeration a %1
    QTimer m_progressTimer;  // publishProgress while wells load
    // What the legend shows (a copy: the colouring's per-row values stay with the geometry).
    std::optional<reconstruction::ColourLegend> m_legend;
    std::unique_ptr<BackgroundJob> m_changeJob;  // the comparison a colouring by change waits for
    std::size_t m_rowBudget = kFieldRowBudget;
    // Counts restyles: a well made lean, or read whole, for an older style is made again.
    unsigned m_styleGeneration = 0;
    std::unique_ptr<BackgroundJob> m_leanReadJob;  // wells held lean read again to restyle them
    bool m_leanReading = false;
    // Where the last pick on a well held lean hit it (its id; -1 none): its section is found
    // once the well is read whole.
    struct LeanPick {
        int id = -1;
        std::size_t segment = 0;
        glm::vec3 point{0.0f};
    };
    LeanPick m_leanPick;
};

}  // namespace caliper3d::app
