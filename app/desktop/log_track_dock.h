#pragma once

#include <memory>
#include <vector>

#include <QDockWidget>
#include <QtCharts/QChartGlobal>

#include "app/desktop/row_curve.h"
#include "io/picks_reader.h"
#include "reconstruction/analysis/well_analysis.h"

class QLabel;
class QStackedWidget;
QT_CHARTS_BEGIN_NAMESPACE
class QChart;
class QChartView;
class QLineSeries;
class QValueAxis;
QT_CHARTS_END_NAMESPACE

namespace caliper3d::app {

class DeskModel;

// The log track: the current well's dmin, dmax and bit size against measured depth (depth
// down the page, as logs are drawn), over bands of the zones coloured by class (the 3D
// wall's colours) and of the runs without data, with a line at the current depth. A click
// or a drag sets the current depth; the wheel zooms about the pointer; the track scrolls to
// keep the current depth in view. Curves are thinned to two points a pixel of the depth
// window (decimateTrace) and redrawn when the window changes, so a 400,000-row log stays
// light; rows without data leave gaps. Shows "analysing..." until the well's analysis is in.
class LogTrackDock : public QDockWidget {
    Q_OBJECT

public:
    explicit LogTrackDock(DeskModel& model, QWidget* parent = nullptr);
    // Narrow, as a log track is: the 3D view keeps the window's middle.
    QSize sizeHint() const override;
    static constexpr int kWidth_px = 220;
    static constexpr int kMinWidth_px = 180;

    QT_CHARTS_NAMESPACE::QChartView* chartView() const { return m_view; }
    QT_CHARTS_NAMESPACE::QChart* chart() const { return m_chart; }
    // Whether the chart is shown (false while there is no well, or no analysis yet).
    bool showsChart() const;
    QString message() const;     // what is shown instead of the chart
    QString legendText() const;  // the legend under the chart (rich text)
    double top_m() const;        // the depth window shown
    double bottom_m() const;
    // Shows [top_m, bottom_m] (clamped to the log, at least kMinSpan_m tall).
    void setDepthWindow(double top_m, double bottom_m);
    // Zooms by `factor` (> 1: closer) about `md_m`, keeping it at the same height.
    void zoom(double factor, double md_m);

    // Wells up to this long are shown whole at first: on a track some 700 pixels tall that
    // is under a metre a pixel, so a metre-long zone still shows. Longer wells open on a
    // window of kDefaultSpan_m around the current depth (a 1:500 log's page) and scroll.
    static constexpr double kWholeWellUpTo_m = 500.0;
    static constexpr double kDefaultSpan_m = 200.0;
    static constexpr double kMinSpan_m = 1.0;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void sync();  // follows the model's current well and its analysis
    void loadCurves(const reconstruction::WellAnalysis& analysis);
    void defaultWindow();
    void redraw();  // the curves and bands of the depth window
    void addBands();
    void addCurve(const RowCurve& values, const QString& name, const QPen& pen);
    void addCurve(const RowCurve& depth_m, const RowCurve& values, const QString& name,
                  const QPen& pen);
    bool loadOtherRun();  // the other run's traces; true when they changed
    void addPicks();
    void moveCursor();
    void follow(double md_m);  // scrolls so that md_m is in view
    bool depthAt(const QPoint& viewportPos, double& md_m) const;
    int plotHeight_px() const;
    int plotWidth_px() const;
    void fitValueAxis();  // the diameter axis's ticks, as many as the plot's width labels

    DeskModel& m_model;
    QStackedWidget* m_stack = nullptr;
    QLabel* m_message = nullptr;
    QWidget* m_track = nullptr;  // the chart and its legend
    QLabel* m_legend = nullptr;
    QT_CHARTS_NAMESPACE::QChartView* m_view = nullptr;
    QT_CHARTS_NAMESPACE::QChart* m_chart = nullptr;
    QT_CHARTS_NAMESPACE::QValueAxis* m_depthAxis = nullptr;
    QT_CHARTS_NAMESPACE::QValueAxis* m_valueAxis = nullptr;
    QT_CHARTS_NAMESPACE::QLineSeries* m_cursor = nullptr;  // the current depth
    int m_well = -1;
    std::shared_ptr<const reconstruction::WellAnalysis> m_analysis;
    // The curves, one value a row (NaN: no data), read where m_analysis holds them, to be
    // thinned for each window.
    RowCurve m_depth_m, m_dmin_mm, m_dmax_mm, m_bit_mm;
    std::vector<io::Pick> m_picks;  // the current well's image-log picks
    // Another run of the current well (DeskModel::otherRuns, the first): its dmin and dmax
    // at its rows' depths matched into the current well's (dashed), once the match is known.
    std::shared_ptr<const reconstruction::WellAnalysis> m_otherAnalysis;
    std::vector<double> m_otherDepth_m;  // its rows' depths in the current well's depths
    RowCurve m_otherDmin_mm, m_otherDmax_mm;
    QString m_otherName;
    int m_drawnHeight_px = 0;
    double m_valueLow_mm = 150.0, m_valueHigh_mm = 300.0;  // the diameters shown, padded
    int m_fittedWidth_px = 0;                              // fitValueAxis's plot width
    bool m_dragging = false;
};

}  // namespace caliper3d::app
