#pragma once

#include <map>

#include <QDockWidget>
#include <QString>
#include <QtCharts/QChartGlobal>

#include "reconstruction/analysis/section_outline.h"

class QBoxLayout;
class QFormLayout;
class QLabel;
class QScrollArea;

QT_CHARTS_BEGIN_NAMESPACE
class QChartView;
class QPolarChart;
class QValueAxis;
class QXYSeries;
QT_CHARTS_END_NAMESPACE

namespace caliper3d::app {

class DeskModel;

// The current section (DeskModel::current(), currentRow()) seen down the hole: a polar plot of
// its pads, spline, fitted ellipse with its axes, bit-size circle, north and high side
// (reconstruction::sectionOutline), and beside it the report's numbers for the section
// (reconstruction::sectionReportFields of the well's WellAnalysis). Follows the model.
class SectionInspectorDock : public QDockWidget {
    Q_OBJECT

public:
    explicit SectionInspectorDock(DeskModel* model, QWidget* parent = nullptr);

    // The text shown for a report field ("md_m", "dmin_mm", "class", ...): the report's own
    // text, "no data", "none", "unknown" or "analysing..."; empty for a field not shown.
    QString value(const QString& field) const;
    // The series named "pads", "spline", "ellipse", "major axis", "minor axis", "bit size",
    // "north", "high side", "other run" (null for another name).
    QtCharts::QXYSeries* series(const QString& name) const;
    QtCharts::QPolarChart* chart() const { return m_chart; }
    // The outline plotted (empty when there is no current section).
    const reconstruction::SectionOutline& outline() const { return m_outline; }
    // Where the current well has other runs (DeskModel::otherRuns): the first of them, its
    // outline at the matched depth (series "other run", dashed) and that depth; -1, empty and
    // NaN otherwise.
    int otherWell() const { return m_otherWell; }
    const reconstruction::SectionOutline& otherOutline() const { return m_otherOutline; }
    double otherDepth_m() const { return m_otherDepth_m; }

    static constexpr int kSplineSamples = 180;  // of the plotted spline and ellipse

public slots:
    void refresh();

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void fitHeading();
    void fitNumbersWidth();
    void buildChart();
    void buildNumbers(QWidget* panel);
    void showOutline();
    void otherRunOutline(reconstruction::AngleReference reference);
    QString otherRunText() const;
    void showNumbers();
    void setAllValues(const QString& text);
    bool elongated() const;  // whether the section has a major axis to draw
    QtCharts::QXYSeries* addSeries(QtCharts::QXYSeries* series, const QString& name,
                                   const QColor& colour, qreal width);

    DeskModel* m_model;
    QBoxLayout* m_layout = nullptr;
    QtCharts::QChartView* m_view = nullptr;
    QScrollArea* m_numbers = nullptr;  // the heading and the numbers' form
    QtCharts::QPolarChart* m_chart = nullptr;
    QtCharts::QValueAxis* m_angle = nullptr;
    QtCharts::QValueAxis* m_radius = nullptr;
    std::map<QString, QtCharts::QXYSeries*> m_series;
    std::map<QString, QLabel*> m_values;  // by report field
    QLabel* m_heading = nullptr;
    reconstruction::SectionOutline m_outline;
    reconstruction::SectionOutline m_otherOutline;
    int m_otherWell = -1;
    double m_otherDepth_m = 0.0;
};

}  // namespace caliper3d::app
