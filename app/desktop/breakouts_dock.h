#pragma once

#include <memory>
#include <vector>

#include <QDockWidget>
#include <QtCharts/QChartGlobal>

#include "io/picks_reader.h"
#include "reconstruction/analysis/well_analysis.h"

class QLabel;
class QTableWidget;
QT_CHARTS_BEGIN_NAMESPACE
class QChartView;
class QPolarChart;
class QValueAxis;
QT_CHARTS_END_NAMESPACE

namespace caliper3d::app {

class DeskModel;

// The breakouts of the current well: a rose of the breakout zones' azimuths (10-degree bins,
// weighted by zone length, mirrored half a turn as the data are axial; breakoutRose), with
// the doubled-angle mean and SHmax drawn across it; a line with the count, combined length,
// circular SD and World Stress Map quality; and the table of every zone of the analysis.
// A click on a zone's row sets the current depth to its top; the row of the zone holding
// the current depth is selected as it moves.
class BreakoutsDock : public QDockWidget {
    Q_OBJECT

public:
    explicit BreakoutsDock(DeskModel& model, QWidget* parent = nullptr);
    // Room for the rose and the table's first columns; the 3D view keeps the middle.
    QSize sizeHint() const override;
    static constexpr int kWidth_px = 260;

    QT_CHARTS_NAMESPACE::QChartView* roseView() const { return m_view; }
    QT_CHARTS_NAMESPACE::QPolarChart* rose() const { return m_chart; }
    QTableWidget* zoneTable() const { return m_table; }
    QString summaryText() const;

    enum Column { kClass, kTop, kBottom, kLength, kAzimuth, kSd, kDiameters, kColumns };

private:
    void sync();  // follows the model's current well and its analysis
    void clear(const QString& message);
    void fillRose(const reconstruction::WellAnalysis& analysis);
    void fillSummary(const reconstruction::WellAnalysis& analysis);
    void fillTable(const reconstruction::WellAnalysis& analysis);
    void addAxisLine(double azimuth_deg, double length, const QString& name, const QPen& pen);
    void addPicks(const std::vector<io::Pick>& picks);
    void selectZoneAt(double md_m);
    void rowClicked(int row);

    DeskModel& m_model;
    QT_CHARTS_NAMESPACE::QPolarChart* m_chart = nullptr;
    QT_CHARTS_NAMESPACE::QChartView* m_view = nullptr;
    QT_CHARTS_NAMESPACE::QValueAxis* m_radial = nullptr;  // metres of breakout
    QLabel* m_summary = nullptr;
    QTableWidget* m_table = nullptr;
    int m_well = -1;
    std::shared_ptr<const reconstruction::WellAnalysis> m_analysis;
};

}  // namespace caliper3d::app
