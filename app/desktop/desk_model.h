#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include <QObject>
#include <QString>

#include "io/diagnostics.h"
#include "io/picks_reader.h"
#include "reconstruction/analysis/depth_match.h"
#include "reconstruction/analysis/well_analysis.h"
#include "reconstruction/load/load_well.h"
#include "reconstruction/well_geometry.h"

namespace caliper3d::app {

// One well as the window's views see it. Everything here is immutable once
// shared (the geometry and the analysis are const); the window replaces a
// well's record when something about it changes.
struct DeskWell {
    int id = -1;                          // stable while the well is shown (WellSession's key)
    QString name;                         // the log's WELL field, else the file's name
    QString path;                         // the file it was read from
    reconstruction::WellSource source;    // the file with its survey and wellhead
    reconstruction::LoadOptions options;  // as it was loaded (bit size, roles, units given)
    std::shared_ptr<const reconstruction::WellGeometry> geometry;  // null until placed
    // The report's analysis of the geometry (reconstruction::analyseWell): null until it is
    // made, on a worker, once the well has loaded.
    std::shared_ptr<const reconstruction::WellAnalysis> analysis;
    // Held lean (WellSession::setFieldRowBudget): the well's rows, of which `geometry` holds a
    // sample, and no analysis until it is read whole again as the current well; 0 while the
    // geometry holds every row.
    std::size_t wholeRows = 0;
    // Its lean form is being made on a worker (WellSession): it is not analysed meanwhile.
    bool makingLean = false;
    // The smallest bit size among every row of the log (NaN: none in the log), taken once from
    // the whole geometry as it is placed (WellSession), so that a well held lean still says
    // the whole log's; unset where no session took it (the Wells dock then takes it from
    // `geometry`).
    std::optional<double> smallestBit_mm;
    io::Diagnostics diagnostics;  // reader, survey and geometry warnings
    std::vector<io::Pick> picks;  // image-log picks (--picks), shown in the 3D, rose and log track
    QString error;                // why the load failed (empty when it did not)
    bool visible = true;
    // How far its load has got, 0 to 1: the log read (the first 70 %), then its segments
    // drawn; 1 once loaded (WellSession publishes it while the well loads).
    double loadFraction = 0.0;
    // Runs of one well (`view RUN1 RUN2 --runs`, docs/user-guide.md, "Runs of one well"): the
    // id of the well's first run, its main run, on every run of it (the main run's own id
    // included); -1 for a well of its own.
    int runOf = -1;
    // On a run other than the main one: where each depth of the main run lies in this run
    // (reconstruction::matchRuns, as `caliper3d compare MAIN RUN` finds it), set once both
    // runs are analysed; `matchError` says why it could not be found.
    std::optional<reconstruction::DepthMapping> mapping;
    QString matchError;
};

// The smallest finite bit size among the table's rows; NaN where it has none.
double smallestBitSize_mm(const io::SectionTable& table);

// The window's shared state: the wells, and the one current well, depth and angle that
// every view follows (the 3D camera, the section inspector, the log track, the unrolled
// image, the breakouts). Views change it through the setters and follow it through the
// signals; a view that sets the depth gets the signal too, and must not echo it back
// (the setters ignore a value equal to the current one). Main thread only.
class DeskModel : public QObject {
    Q_OBJECT

public:
    explicit DeskModel(QObject* parent = nullptr) : QObject(parent) {}

    int wellCount() const { return static_cast<int>(m_wells.size()); }
    const DeskWell& well(int i) const { return m_wells.at(static_cast<std::size_t>(i)); }
    // The current well's record; null when there is none.
    const DeskWell* current() const;

    // The index of the well whose DeskWell::id is `id`; -1 when none is.
    int indexOf(int id) const;

    // Called by the well session as wells load.
    // Until a well is chosen (setCurrent, setCurrentRow), the first well in order that has
    // geometry is current, at its first measured section (firstMeasuredRow): every view opens
    // on data, and on the first file given however the wells' loads finish.
    int addWell(DeskWell well);  // emits wellsChanged
    // Emits wellChanged(i); the current well keeps its depth (its row found in the new geometry).
    void updateWell(int i, DeskWell well);
    // Emits wellsChanged; when the current well goes, the first well with geometry becomes
    // current at its first measured section (currentChanged).
    void removeWell(int i);
    void clearWells();                     // emits wellsChanged and currentChanged
    void setVisible(int i, bool visible);  // emits wellChanged(i)
    // Makes well i a run of the well whose main run has id `mainId` (DeskWell::runOf);
    // emits wellsChanged (the wells dock groups the runs).
    void setRunOf(int i, int mainId);

    int currentWell() const { return m_well; }  // -1 when no well is loaded
    // The current measured depth, metres, always a row's depth (NaN when no well).
    double currentDepth_m() const { return m_depth_m; }
    // The current section: the row of the current well's table at currentDepth_m.
    std::size_t currentRow() const { return m_row; }
    // The current direction around the section, degrees clockwise from north (NaN: none).
    double currentAzimuth_deg() const { return m_azimuth_deg; }

    // Moves to the row of `well` nearest `md_m` (clamped to the log); emits currentChanged
    // when the well or the row changes. Ignored for a well without geometry.
    void setCurrent(int well, double md_m);
    void setCurrentDepth(double md_m) { setCurrent(m_well, md_m); }
    void setCurrentRow(int well, std::size_t row);
    void setCurrentAzimuth(double azimuth_deg);  // emits azimuthChanged

    // The other runs of well i's well (model indices, the main run first); empty for a well
    // of its own.
    std::vector<int> otherRuns(int i) const;
    // The main run of well i's well (i itself for a main run or a well of its own).
    int mainRun(int i) const;
    // Where `md_m` of well `from` lies in well `to`, two runs of one well, through their
    // depth match; NaN where a match is not (yet) known or they are not runs of one well.
    double matchedDepth_m(int from, int to, double md_m) const;

    // The row of `geometry`'s table nearest `md_m` (the log's first or last beyond its ends).
    static std::size_t nearestRow(const reconstruction::WellGeometry& geometry, double md_m);
    // The first row with a measured section (WellGeometry::measured); the first row when the
    // log has none.
    static std::size_t firstMeasuredRow(const reconstruction::WellGeometry& geometry);

signals:
    void wellsChanged();
    void wellChanged(int well);
    void currentChanged(int well, double md_m);
    void azimuthChanged(double azimuth_deg);

private:
    std::vector<DeskWell> m_wells;
    // Makes well `i` current when no well is chosen and none before it is (openOnFirstWell).
    void openOnFirstWell(int i);
    void moveTo(int well, std::size_t row);  // setCurrentRow's move, chosen or not
    bool m_chosen = false;  // a well was made current by setCurrent or setCurrentRow
    int m_well = -1;
    std::size_t m_row = 0;
    double m_depth_m = io::kNaN;
    double m_azimuth_deg = io::kNaN;
};

}  // namespace caliper3d::app
