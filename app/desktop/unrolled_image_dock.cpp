#include "app/desktop/unrolled_image_dock.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPixmap>
#include <QSignalBlocker>
#include <QVBoxLayout>
#include <QWheelEvent>
#include <QtCharts/QChart>
#include <QtCharts/QChartView>
#include <QtCharts/QLegend>
#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>

#include "app/desktop/desk_model.h"
#include "reconstruction/mesh/wall_colouring.h"

QT_CHARTS_USE_NAMESPACE

namespace caliper3d::app {

namespace {

constexpr double kMinWindow_m = 1.0;
constexpr double kZoomStep = 1.25;
constexpr int kMaxColumns = 720;
constexpr double kTickSpacing_px = 30.0;  // half a degree: finer than any caliper's arms
// The window follows the current depth once it comes this close to either end (a fraction of
// the window), so that a click inside the window does not move the picture under the pointer.
constexpr double kFollowMargin = 0.1;

bool logHasBitSize(const io::SectionTable& t) {
    return std::any_of(t.bitSize_mm.begin(), t.bitSize_mm.end(),
                       [](double b) { return std::isfinite(b); });
}

QImage toPicture(const reconstruction::UnrolledImage& image) {
    QImage picture(image.columns, image.rows, QImage::Format_RGB32);
    for (int r = 0; r < image.rows; ++r) {
        auto* line = reinterpret_cast<QRgb*>(picture.scanLine(r));
        for (int c = 0; c < image.columns; ++c) {
            // The 3D wall's departure colours: departureColour(radius, bit radius).
            const std::uint32_t colour =
                reconstruction::departureColour(static_cast<double>(image.at(r, c)), 0.0);
            line[c] = qRgb(reconstruction::red(colour), reconstruction::green(colour),
                           reconstruction::blue(colour));
        }
    }
    return picture;
}

// The departure colours from -kDepartureRange_mm to +kDepartureRange_mm, left to right.
QImage colourKey(int width, int height) {
    QImage key(width, height, QImage::Format_RGB32);
    for (int x = 0; x < width; ++x) {
        const double d = reconstruction::kDepartureRange_mm * (2.0 * (x + 0.5) / width - 1.0);
        const std::uint32_t c = reconstruction::departureColour(d, 0.0);
        for (int y = 0; y < height; ++y)
            key.setPixel(
                x, y,
                qRgb(reconstruction::red(c), reconstruction::green(c), reconstruction::blue(c)));
    }
    return key;
}

}  // namespace

UnrolledImageDock::UnrolledImageDock(DeskModel* model, QWidget* parent)
    : QDockWidget("Unrolled image", parent), m_model(model) {
    setObjectName("unrolledImage");
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(2, 2, 2, 2);
    auto* bar = new QHBoxLayout;
    bar->addWidget(new QLabel("Angle", body));
    m_reference = new QComboBox(body);
    m_reference->setObjectName("angleReference");
    m_reference->addItem("from north");
    m_reference->addItem("from high side");
    m_reference->setToolTip("What the angle across the image is counted from, clockwise");
    bar->addWidget(m_reference);
    bar->addStretch(1);
    // The colour key: the 3D wall's departure map over its fixed range.
    bar->addWidget(new QLabel(QString::number(-reconstruction::kDepartureRange_mm), body));
    auto* key = new QLabel(body);
    key->setPixmap(QPixmap::fromImage(colourKey(96, 12)));
    key->setToolTip("radius - bit radius: blue narrower, grey in gauge, red wider");
    bar->addWidget(key);
    bar->addWidget(new QLabel(QString("+%1 mm").arg(reconstruction::kDepartureRange_mm), body));
    layout->addLayout(bar);
    buildChart();
    layout->addWidget(m_view, 1);
    setWidget(body);
    connect(m_reference, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
            [this](int) { drawImage(); });
    connect(m_model, &DeskModel::currentChanged, this, &UnrolledImageDock::refresh);
    // The image is the current well's: another well's change (a field's progress) leaves it.
    connect(m_model, &DeskModel::wellChanged, this, [this](int well) {
        if (well == m_model->currentWell()) refresh();
    });
    connect(m_model, &DeskModel::wellsChanged, this, &UnrolledImageDock::refresh);
    refresh();
}

void UnrolledImageDock::buildChart() {
    m_chart = new QChart;
    m_chart->legend()->hide();
    m_chart->setMargins(QMargins(2, 2, 6, 2));
    m_angle = new QValueAxis;
    m_angle->setRange(0.0, 360.0);
    m_angle->setTickCount(5);
    m_angle->setLabelFormat("%.0f");
    m_angle->setGridLineVisible(false);
    m_chart->addAxis(m_angle, Qt::AlignTop);
    m_depth = new QValueAxis;
    m_depth->setReverse(true);  // depth down
    m_depth->setLabelFormat("%.1f");
    m_depth->setTitleText("MD (m)");
    m_depth->setGridLineVisible(false);
    m_chart->addAxis(m_depth, Qt::AlignLeft);
    m_currentLine = new QLineSeries;
    m_currentLine->setPen(QPen(Qt::black, 2.0));
    m_chart->addSeries(m_currentLine);
    m_currentLine->attachAxis(m_angle);
    m_currentLine->attachAxis(m_depth);
    m_chart->setPlotAreaBackgroundVisible(true);
    m_view = new QChartView(m_chart);
    m_view->setMinimumSize(220, 240);
    m_view->viewport()->installEventFilter(this);
    connect(m_chart, &QChart::plotAreaChanged, this, [this](const QRectF&) {
        placeWindow();
        drawImage();
    });
}

reconstruction::AngleReference UnrolledImageDock::reference() const {
    return m_reference->currentIndex() == 1 ? reconstruction::AngleReference::HighSide
                                            : reconstruction::AngleReference::North;
}

void UnrolledImageDock::setWindowLength(double length_m) {
    m_window_m = std::max(length_m, kMinWindow_m);
    if (const DeskWell* well = m_model->current(); well && well->geometry) {
        const auto& depth = well->geometry->table().depth_m;
        m_window_m = std::min(m_window_m, std::max(depth.back() - depth.front(), kMinWindow_m));
    }
    m_top_m = m_bottom_m = 0.0;  // place it again about the current depth
    refresh();
}

void UnrolledImageDock::refresh() {
    const DeskWell* well = m_model->current();
    if (well && well->geometry && well->geometry.get() != m_shown) {
        // A new well starts from north where its current section has one, else from the high
        // side (an inclined hole without azimuth, arm 1 from RB).
        m_shown = well->geometry.get();
        const QSignalBlocker block(m_reference);
        m_reference->setCurrentIndex(
            reconstruction::referenceKnown(*well->geometry, m_model->currentRow(),
                                           reconstruction::AngleReference::North)
                ? 0
                : 1);
    }
    placeWindow();
    showCurrentDepth();
    drawImage();
}

void UnrolledImageDock::placeWindow() {
    const DeskWell* well = m_model->current();
    if (!well || !well->geometry) return;
    const auto& depth = well->geometry->table().depth_m;
    const double first = depth.front(), last = depth.back();
    const double length = std::min(m_window_m, last - first);
    const double md = m_model->currentDepth_m();
    const double margin = kFollowMargin * length;
    const bool inside = std::abs(m_bottom_m - m_top_m - length) < 1e-9 && md >= m_top_m + margin &&
                        md <= m_bottom_m - margin && m_top_m >= first && m_bottom_m <= last;
    if (!inside) {
        m_top_m = std::clamp(md - length / 2.0, first, last - length);
        m_bottom_m = m_top_m + length;
    }
    m_depth->setRange(m_top_m, m_bottom_m);
    // Ticks at round depths: the smallest 1-2-5 step that leaves a label room (kTickSpacing_px)
    // and gives at most ten.
    const double height = m_chart->plotArea().height();
    const double ticks = std::clamp(height > 0.0 ? height / kTickSpacing_px : 5.0, 2.0, 10.0);
    double step = std::pow(10.0, std::floor(std::log10(std::max(length, 1e-3) / ticks)));
    for (double factor : {2.0, 2.5, 2.0, 2.0, 2.5, 2.0})
        if (length / step > ticks) step *= factor;
    m_depth->setTickType(QValueAxis::TicksDynamic);
    m_depth->setTickAnchor(0.0);
    m_depth->setTickInterval(step);
    m_depth->setLabelFormat(step < 1.0 ? "%.1f" : "%.0f");
}

void UnrolledImageDock::showCurrentDepth() {
    const double md = m_model->currentDepth_m();
    if (std::isfinite(md))
        m_currentLine->replace(QList<QPointF>{QPointF(0.0, md), QPointF(360.0, md)});
    else
        m_currentLine->clear();
}

void UnrolledImageDock::drawImage() {
    const DeskWell* well = m_model->current();
    const QRectF plot = m_chart->plotArea();
    if (m_drawing || !well || !well->geometry || plot.width() < 2.0 || plot.height() < 2.0) {
        if (!well || !well->geometry) m_chart->setTitle("No well loaded");
        return;
    }
    m_drawing = true;
    const bool north = reference() == reconstruction::AngleReference::North;
    m_angle->setTitleText(north ? "angle from north (deg)" : "angle from high side (deg)");
    reconstruction::UnrolledImageRequest request;
    request.top_m = m_top_m;
    request.bottom_m = m_bottom_m;
    request.rows = static_cast<int>(std::lround(plot.height()));
    request.columns = std::min(static_cast<int>(std::lround(plot.width())), kMaxColumns);
    request.reference = reference();
    // No bit size anywhere: the report's gauge (the median equivalent diameter) stands in.
    std::function<double(std::size_t)> gauge;
    QString gaugeText = "bit radius";
    if (!logHasBitSize(well->geometry->table())) {
        if (well->analysis && well->analysis->bitSizeFromSections) {
            std::shared_ptr<const reconstruction::WellAnalysis> analysis = well->analysis;
            gauge = [analysis](std::size_t row) {
                return analysis->sections.measure(row).bit_mm / 2.0;
            };
            gaugeText = "gauge from the sections (no bit size)";
        } else {
            gaugeText = "gauge: analysing... (no bit size)";
        }
    }
    m_image = reconstruction::unrolledImage(*well->geometry, request, gauge);
    m_picture =
        toPicture(m_image).scaled(static_cast<int>(std::lround(plot.width())), request.rows);
    QBrush brush(m_picture);
    brush.setTransform(QTransform::fromTranslate(plot.left(), plot.top()));
    m_chart->setPlotAreaBackgroundBrush(brush);
    QString title = QString("radius - %1").arg(gaugeText);
    QString tip = well->name;
    if (!well->geometry->holeAzimuthKnown()) {
        title += " (no hole azimuth)";
        tip += QString(": the hole azimuth is unknown, rows without a %1 are left blank")
                   .arg(north ? "north (arm 1 from RB)" : "high side (arm 1 from P1AZ)");
    }
    m_chart->setTitle(title);
    m_view->setToolTip(tip);
    m_drawing = false;
}

void UnrolledImageDock::clicked(const QPointF& position) {
    const DeskWell* well = m_model->current();
    const QPointF inChart = m_chart->mapFromScene(m_view->mapToScene(position.toPoint()));
    if (!well || !well->geometry || !m_chart->plotArea().contains(inChart)) return;
    const QPointF value = m_chart->mapToValue(inChart, m_currentLine);
    m_model->setCurrentDepth(value.y());
    double angle = value.x();
    if (reference() == reconstruction::AngleReference::HighSide) {
        if (!reconstruction::referenceKnown(*well->geometry, m_model->currentRow(),
                                            reconstruction::AngleReference::North))
            return;
        // From the high side to north at the section clicked.
        const reconstruction::SectionFrame& frame = well->geometry->frame(m_model->currentRow());
        angle -= reconstruction::angleFromReference_deg(
            frame,
            reconstruction::referenceDirection(frame.tangent,
                                               reconstruction::AngleReference::North),
            reconstruction::AngleReference::HighSide);
    }
    m_model->setCurrentAzimuth(angle);
}

bool UnrolledImageDock::eventFilter(QObject* watched, QEvent* event) {
    if (watched != m_view->viewport()) return QDockWidget::eventFilter(watched, event);
    if (event->type() == QEvent::MouseButtonPress) {
        auto* mouse = static_cast<QMouseEvent*>(event);
        if (mouse->button() != Qt::LeftButton) return false;
        clicked(mouse->localPos());
        return true;
    }
    if (event->type() == QEvent::Wheel) {
        const int delta = static_cast<QWheelEvent*>(event)->angleDelta().y();
        if (delta == 0) return false;
        setWindowLength(delta > 0 ? m_window_m / kZoomStep : m_window_m * kZoomStep);
        return true;
    }
    return false;
}

}  // namespace caliper3d::app
