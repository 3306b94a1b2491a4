#pragma once

#include <QDockWidget>
#include <QImage>
#include <QString>
#include <QtCharts/QChartGlobal>

#include "reconstruction/analysis/unrolled_image.h"

class QComboBox;

QT_CHARTS_BEGIN_NAMESPACE
class QChart;
class QChartView;
class QLineSeries;
class QValueAxis;
QT_CHARTS_END_NAMESPACE

namespace caliper3d::app {

class DeskModel;

// The current well's wall unrolled (the reference tool's 2D cylinder projection): the departure
// of the radius from the bit radius against angle around the hole (0-360 from north or from the
// high side) across and measured depth down, in the 3D wall's departure colours
// (reconstruction::departureColour over kDepartureRange_mm). A window of depth around the
// current depth (the wheel zooms it), a line at the current depth; a click sets the current
// depth and azimuth. The image is reconstruction::unrolledImage, drawn as the background of a
// Qt Charts plot area whose value axes give angle and depth.
class UnrolledImageDock : public QDockWidget {
    Q_OBJECT

public:
    explicit UnrolledImageDock(DeskModel* model, QWidget* parent = nullptr);

    QtCharts::QChartView* view() const { return m_view; }
    QtCharts::QChart* chart() const { return m_chart; }
    QComboBox* referenceBox() const { return m_reference; }
    // The image last computed (one cell per plot-area pixel), and the depth window shown.
    const reconstruction::UnrolledImage& image() const { return m_image; }
    double windowTop_m() const { return m_top_m; }
    double windowBottom_m() const { return m_bottom_m; }
    double windowLength_m() const { return m_window_m; }
    void setWindowLength(double length_m);

    static constexpr double kDefaultWindow_m = 20.0;

public slots:
    void refresh();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void buildChart();
    void placeWindow();
    void drawImage();
    void showCurrentDepth();
    void clicked(const QPointF& position);
    reconstruction::AngleReference reference() const;

    DeskModel* m_model;
    QComboBox* m_reference = nullptr;
    QtCharts::QChartView* m_view = nullptr;
    QtCharts::QChart* m_chart = nullptr;
    QtCharts::QValueAxis* m_angle = nullptr;
    QtCharts::QValueAxis* m_depth = nullptr;
    QtCharts::QLineSeries* m_currentLine = nullptr;
    reconstruction::UnrolledImage m_image;
    QImage m_picture;
    double m_window_m = kDefaultWindow_m;
    double m_top_m = 0.0, m_bottom_m = 0.0;
    const void* m_shown = nullptr;  // the geometry shown, to tell a new well
    bool m_drawing = false;         // re-entry guard: a new background can move the plot area
};

}  // namespace caliper3d::app
