#include "app/desktop/log_track_dock.h"

#include <algorithm>
#include <cmath>
#include <set>

#include <QFileInfo>
#include <QFontMetrics>
#include <QLabel>
#include <QMouseEvent>
#include <QStackedWidget>
#include <QVBoxLayout>
#include <QWheelEvent>
#include <QtCharts/QAreaSeries>
#include <QtCharts/QChart>
#include <QtCharts/QChartView>
#include <QtCharts/QLineSeries>
#include <QtCharts/QValueAxis>

#include "app/desktop/desk_model.h"
#include "app/desktop/trace_decimation.h"
#include "reconstruction/analysis/wall_colour_request.h"

QT_CHARTS_USE_NAMESPACE

namespace caliper3d::app {

namespace {

// The value of the p-th fraction (0-1) of the finite values (NaN when none).
double percentile(const RowCurve& curve, double p) {
    std::vector<double> values;
    for (std::size_t i = 0; i < curve.size(); ++i)
        if (std::isfinite(curve[i])) values.push_back(curve[i]);
    if (values.empty()) return std::nan("");
    const auto k = static_cast<std::ptrdiff_t>(p * double(values.size() - 1));
    std::nth_element(values.begin(), values.begin() + k, values.end());
    return values[std::size_t(k)];
}

// A round tick interval (1, 2, 2.5 or 5 times a power of ten) giving at most `ticks`
// intervals over `span`.
double niceStep(double span, int ticks) {
    const double raw = span / ticks;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 2.5, 5.0})
        if (m * power >= raw) return m * power;
    return 10.0 * power;
}

// A legend entry: a square of the colour as drawn over the white plot, then the name.
// Sets a dynamic-tick axis to [min, max] with ticks every `step`. The axis lays its ticks
// out as soon as either changes: a small step over the old, wide range (or the reverse)
// would make thousands of ticks on the way, so the order depends on which shrinks.
void setAxis(QValueAxis* axis, double min, double max, double step) {
    if (step < axis->tickInterval()) {
        axis->setRange(min, max);
        axis->setTickInterval(step);
    } else {
        axis->setTickInterval(step);
        axis->setRange(min, max);
    }
}

QString swatch(const QColor& colour, const QString& name) {
    const double a = colour.alphaF();
    const QString label = name.toHtmlEscaped().replace(' ', "&nbsp;");
    const QColor onWhite(int(std::lround(a * colour.red() + (1.0 - a) * 255.0)),
                         int(std::lround(a * colour.green() + (1.0 - a) * 255.0)),
                         int(std::lround(a * colour.blue() + (1.0 - a) * 255.0)));
    return QString("<span style=\"color:%1\">&#9632;</span>&nbsp;%2").arg(onWhite.name(), label);
}

QColor bandColour(reconstruction::BoreholeClass cls) {
    const std::uint32_t rgba = reconstruction::classColour(cls);
    return QColor(int(rgba >> 24) & 0xFF, int(rgba >> 16) & 0xFF, int(rgba >> 8) & 0xFF, 120);
}

// The depth half-way between row i and its neighbour above (below when `below`), so a band
// covers its rows' whole steps.
double rowEdge_m(const RowCurve& depth_m, std::size_t row, bool below) {
    if (below)
        return row + 1 < depth_m.size() ? 0.5 * (depth_m[row] + depth_m[row + 1]) : depth_m[row];
    return row > 0 ? 0.5 * (depth_m[row - 1] + depth_m[row]) : depth_m[row];
}

}  // namespace

LogTrackDock::LogTrackDock(DeskModel& model, QWidget* parent)
    : QDockWidget("Log track", parent), m_model(model) {
    setObjectName("logTrack");
    m_stack = new QStackedWidget(this);
    m_message = new QLabel(m_stack);
    m_message->setAlignment(Qt::AlignCenter);
    m_chart = new QChart;
    m_chart->setAnimationOptions(QChart::NoAnimation);
    m_chart->setMargins(QMargins(4, 4, 4, 4));
    // The legend is a label under the chart: it wraps in a narrow dock, where the chart's
    // own legend (one row) would cut every name short.
    m_chart->legend()->hide();
    m_depthAxis = new QValueAxis(m_chart);
    m_depthAxis->setReverse(true);  // depth down the page
    m_depthAxis->setTitleText("MD (m)");
    m_depthAxis->setTickInterval(1.0);  // over the default range 0-1, until a well comes
    m_depthAxis->setTickType(QValueAxis::TicksDynamic);
    m_depthAxis->setTickAnchor(0.0);
    m_chart->addAxis(m_depthAxis, Qt::AlignLeft);
    m_valueAxis = new QValueAxis(m_chart);
    m_valueAxis->setTitleText("mm");  // the legend names the curves
    m_valueAxis->setLabelFormat("%.0f");
    m_valueAxis->setTickInterval(1.0);
    m_valueAxis->setTickType(QValueAxis::TicksDynamic);
    m_valueAxis->setTickAnchor(0.0);
    m_chart->addAxis(m_valueAxis, Qt::AlignTop);
    m_cursor = new QLineSeries(m_chart);
    m_cursor->setName("current depth");
    m_cursor->setPen(QPen(Qt::black, 1.5));
    m_view = new QChartView(m_chart, m_stack);
    m_view->setRenderHint(QPainter::Antialiasing);
    m_view->viewport()->installEventFilter(this);
    m_view->setMinimumWidth(kMinWidth_px);  // the axes' labels need this much
    m_legend = new QLabel(m_stack);
    m_legend->setWordWrap(true);
    m_legend->setObjectName("logTrackLegend");
    auto* track = new QWidget(m_stack);
    auto* layout = new QVBoxLayout(track);
    layout->setContentsMargins(0, 0, 0, 2);
    layout->addWidget(m_view, 1);
    layout->addWidget(m_legend);
    m_track = track;
    m_stack->addWidget(m_message);
    m_stack->addWidget(track);
    setWidget(m_stack);

    connect(&m_model, &DeskModel::wellsChanged, this, &LogTrackDock::sync);
    connect(&m_model, &DeskModel::wellChanged, this, [this](int well) {
        if (well == m_model.currentWell()) sync();
    });
    connect(&m_model, &DeskModel::currentChanged, this, [this](int well, double md_m) {
        if (well != m_well || !m_analysis) return sync();
        moveCursor();
        follow(md_m);
    });
    // Thinned to the plot's height: drawn again when that changes (queued: the chart is in
    // the middle of its layout when it says so).
    connect(
        m_chart, &QChart::plotAreaChanged, this,
        [this] {
            if (!m_analysis) return;
            const bool narrower = plotWidth_px() != m_fittedWidth_px;
            if (narrower) fitValueAxis();
            if (narrower || plotHeight_px() != m_drawnHeight_px) redraw();
        },
        Qt::QueuedConnection);
    sync();
}

QSize LogTrackDock::sizeHint() const {
    return {kWidth_px, 480};
}

bool LogTrackDock::showsChart() const {
    return m_stack->currentWidget() == m_track;
}

QString LogTrackDock::message() const {
    return m_message->text();
}

QString LogTrackDock::legendText() const {
    return m_legend->text();
}

double LogTrackDock::top_m() const {
    return m_depthAxis->min();
}

double LogTrackDock::bottom_m() const {
    return m_depthAxis->max();
}

void LogTrackDock::sync() {
    const DeskWell* well = m_model.current();
    const int index = m_model.currentWell();
    if (!well || !well->geometry || !well->analysis) {
        m_well = index;
        m_analysis.reset();
        m_depth_m = m_dmin_mm = m_dmax_mm = m_bit_mm = RowCurve();  // they read m_analysis
        m_message->setText(!well             ? "No well loaded"
                           : !well->geometry ? "No geometry: " + well->error
                                             : "analysing...");
        m_stack->setCurrentWidget(m_message);
        return;
    }
    if (index == m_well && well->analysis == m_analysis) {
        if (loadOtherRun()) redraw();
        moveCursor();
        follow(m_model.currentDepth_m());
        return;
    }
    m_well = index;
    m_analysis = well->analysis;
    m_picks = well->picks;
    loadCurves(*m_analysis);
    loadOtherRun();
    m_stack->setCurrentWidget(m_track);
    defaultWindow();
}

bool LogTrackDock::loadOtherRun() {
    const std::vector<int> others = m_model.otherRuns(m_well);
    std::shared_ptr<const reconstruction::WellAnalysis> analysis;
    std::vector<double> depth_m;
    QString name;
    if (!others.empty()) {
        const DeskWell& other = m_model.well(others.front());
        name = QFileInfo(other.path).fileName();
        if (other.analysis) {
            const std::size_t rows = other.analysis->sections.size();
            const auto& path = other.analysis->sections.path();
            depth_m.reserve(rows);
            for (std::size_t row = 0; row < rows; ++row) {
                const double md = m_model.matchedDepth_m(others.front(), m_well, path[row].md);
                if (!std::isfinite(md)) break;  // no match yet
                depth_m.push_back(md);
            }
            if (depth_m.size() == rows) analysis = other.analysis;
        }
    }
    if (!analysis) depth_m.clear();
    if (analysis == m_otherAnalysis && depth_m == m_otherDepth_m) return false;
    m_otherAnalysis = analysis;
    m_otherDepth_m = std::move(depth_m);
    m_otherName = name;
    using reconstruction::SectionMeasure;
    const std::size_t rows = m_otherAnalysis ? m_otherDepth_m.size() : 0;
    const SectionMeasure* sections = m_otherAnalysis ? m_otherAnalysis->sections.data() : nullptr;
    m_otherDmin_mm =
        sections ? RowCurve::field(sections, &SectionMeasure::dmin_mm, rows) : RowCurve();
    m_otherDmax_mm =
        sections ? RowCurve::field(sections, &SectionMeasure::dmax_mm, rows) : RowCurve();
    return true;
}

void LogTrackDock::loadCurves(const reconstruction::WellAnalysis& analysis) {
    // Read in place: m_analysis holds them (and a share of the path) while the dock shows them.
    using reconstruction::SectionMeasure;
    const reconstruction::SectionResults& sections = analysis.sections;
    const std::size_t rows = sections.size();
    m_depth_m = RowCurve::field(sections.path().data(), &reconstruction::PathPoint::md, rows);
    m_dmin_mm = RowCurve::field(sections.data(), &SectionMeasure::dmin_mm, rows);
    m_dmax_mm = RowCurve::field(sections.data(), &SectionMeasure::dmax_mm, rows);
    m_bit_mm = RowCurve::field(sections.data(), &SectionMeasure::bit_mm, rows);
    // The diameters' range without the rare spike (one row in a thousand may run off the
    // edge), and the bit size always in view.
    double low = percentile(m_dmin_mm, 0.001), high = percentile(m_dmax_mm, 0.999);
    const double bitLow = percentile(m_bit_mm, 0.0), bitHigh = percentile(m_bit_mm, 1.0);
    if (std::isfinite(bitLow)) low = std::isfinite(low) ? std::min(low, bitLow) : bitLow;
    if (std::isfinite(bitHigh)) high = std::isfinite(high) ? std::max(high, bitHigh) : bitHigh;
    if (!std::isfinite(low) || !std::isfinite(high)) low = 150.0, high = 300.0;
    const double pad = 0.08 * (high - low) + 5.0;
    m_valueLow_mm = low - pad;
    m_valueHigh_mm = high + pad;
    fitValueAxis();
}

// As many labels as the plot's width holds whole (at most four), each with room for a gap
// the width of a label beside it: Qt Charts elides a label that does not fit its tick's
// interval ("1..."). Laid out again when the plot's width changes.
void LogTrackDock::fitValueAxis() {
    m_fittedWidth_px = plotWidth_px();
    const QFontMetrics metrics(m_valueAxis->labelsFont());
    const double span = m_valueHigh_mm - m_valueLow_mm;
    double step = 0.0;
    for (int intervals = 3; intervals >= 1; --intervals) {
        step = niceStep(span, intervals);
        const double lo = std::floor(m_valueLow_mm / step) * step;
        const double hi = std::ceil(m_valueHigh_mm / step) * step;
        int widest = 0;
        for (double v = lo; v <= hi + 0.5 * step; v += step)
            widest = std::max(widest, metrics.horizontalAdvance(QString::number(v, 'f', 0)));
        const double labels = std::round((hi - lo) / step) + 1.0;
        if (labels * 2.0 * widest <= m_fittedWidth_px + widest) break;
    }
    setAxis(m_valueAxis, std::floor(m_valueLow_mm / step) * step,
            std::ceil(m_valueHigh_mm / step) * step, step);
}

int LogTrackDock::plotWidth_px() const {
    const int width = int(std::lround(m_chart->plotArea().width()));
    return width >= 20 ? width : kMinWidth_px - 60;  // before the first layout
}

void LogTrackDock::defaultWindow() {
    if (m_depth_m.empty()) return;
    const double length_m = m_depth_m.back() - m_depth_m.front();
    if (length_m <= kWholeWellUpTo_m) return setDepthWindow(m_depth_m.front(), m_depth_m.back());
    const double md_m =
        std::isfinite(m_model.currentDepth_m()) ? m_model.currentDepth_m() : m_depth_m.front();
    setDepthWindow(md_m - 0.5 * kDefaultSpan_m, md_m + 0.5 * kDefaultSpan_m);
}

void LogTrackDock::setDepthWindow(double top_m, double bottom_m) {
    if (m_depth_m.empty()) return;
    const double first_m = m_depth_m.front(), last_m = m_depth_m.back();
    const double length_m = std::max(last_m - first_m, kMinSpan_m);
    const double span_m = std::clamp(bottom_m - top_m, kMinSpan_m, length_m);
    top_m = std::clamp(top_m, first_m, std::max(first_m, last_m - span_m));
    const double step = niceStep(span_m, 8);
    setAxis(m_depthAxis, top_m, top_m + span_m, step);
    m_depthAxis->setLabelFormat(step >= 1.0 ? "%.0f" : step >= 0.1 ? "%.1f" : "%.2f");
    redraw();
}

void LogTrackDock::zoom(double factor, double md_m) {
    const double top = top_m(), span_m = bottom_m() - top;
    if (!(factor > 0.0) || !(span_m > 0.0)) return;
    const double fraction = std::clamp((md_m - top) / span_m, 0.0, 1.0);
    const double newSpan_m = span_m / factor;
    setDepthWindow(md_m - fraction * newSpan_m, md_m + (1.0 - fraction) * newSpan_m);
}

void LogTrackDock::redraw() {
    m_drawnHeight_px = plotHeight_px();
    for (QAbstractSeries* series : m_chart->series()) {
        m_chart->removeSeries(series);
        if (series != m_cursor) delete series;
    }
    addBands();
    // The bit size last, dashed: where the hole is in gauge the three lines coincide, and
    // the dashes show both it and the diameters under it.
    addCurve(m_dmax_mm, "dmax", QPen(Qt::black, 1.2));
    addCurve(m_dmin_mm, "dmin", QPen(QColor(0x00, 0x9E, 0x73), 1.2));
    if (m_otherAnalysis) {  // another run of the well at the matched depths, dashed
        addCurve(m_otherDepth_m, m_otherDmax_mm, m_otherName + " dmax",
                 QPen(QColor(0xCC, 0x79, 0xA7), 1.2, Qt::DashLine));
        addCurve(m_otherDepth_m, m_otherDmin_mm, m_otherName + " dmin",
                 QPen(QColor(0xD5, 0x5E, 0x00), 1.2, Qt::DashLine));
    }
    addCurve(m_bit_mm, "bit size", QPen(QColor(0x56, 0xB4, 0xE9), 1.5, Qt::DashLine));
    addPicks();
    m_chart->addSeries(m_cursor);  // last: drawn over the rest
    m_cursor->attachAxis(m_valueAxis);
    m_cursor->attachAxis(m_depthAxis);
    // A series attached to a reversed axis is drawn the right way up only once the axis
    // says it is reversed again (Qt Charts 5.15 sets a new series' domain unreversed).
    m_depthAxis->setReverse(false);
    m_depthAxis->setReverse(true);
    moveCursor();
    // What the window shows, each name once (a curve split by gaps is several series).
    std::set<QString> named;
    QStringList legend;
    for (QAbstractSeries* series : m_chart->series()) {
        if (!named.insert(series->name()).second) continue;
        if (auto* area = qobject_cast<QAreaSeries*>(series))
            legend << swatch(area->brush().color(), area->name());
        else if (auto* line = qobject_cast<QLineSeries*>(series))
            legend << swatch(line->pen().color(), line->name());
    }
    m_legend->setText(legend.join(" &nbsp; "));
}

void LogTrackDock::addBands() {
    using reconstruction::BoreholeClass;
    const double top = top_m(), bottom = bottom_m();
    const double left = m_valueAxis->min(), right = m_valueAxis->max();
    // One area series a class: its bands traced as one outline that comes back up the left
    // edge (a line of no width), so a window of many zones stays a handful of series.
    auto band = [&](const QString& name, const QBrush& brush, auto&& intervals) {
        auto* upper = new QLineSeries;
        auto* lower = new QLineSeries;
        intervals([&](double from_m, double to_m) {
            if (to_m < top || from_m > bottom) return;
            upper->append(left, from_m);
            upper->append(right, from_m);
            upper->append(right, to_m);
            upper->append(left, to_m);
        });
        if (upper->count() == 0) {
            delete upper;
            delete lower;
            return;
        }
        lower->append(left, upper->at(0).y());
        lower->append(left, upper->at(upper->count() - 1).y());
        auto* area = new QAreaSeries(upper, lower);
        upper->setParent(area);
        lower->setParent(area);
        area->setName(name);
        area->setBrush(brush);
        area->setPen(Qt::NoPen);
        m_chart->addSeries(area);
        area->attachAxis(m_valueAxis);
        area->attachAxis(m_depthAxis);
    };
    for (BoreholeClass cls : {BoreholeClass::Breakout, BoreholeClass::Washout,
                              BoreholeClass::Keyseat, BoreholeClass::Undergauge})
        band(QString::fromUtf8(reconstruction::className(cls).data()), bandColour(cls),
             [&](auto&& add) {
                 for (const reconstruction::Zone& zone : m_analysis->zones)
                     if (zone.kind == cls) add(zone.top_m, zone.bottom_m);
             });
    band("cased", bandColour(BoreholeClass::Cased), [&](auto&& add) {
        for (const reconstruction::CasingCheck& c : m_analysis->casing)
            if (!m_depth_m.empty() && c.casing.bottom_m >= m_depth_m.front())
                add(m_depth_m.front(), std::min(c.casing.bottom_m, m_depth_m.back()));
    });
    band("no data", QBrush(QColor(120, 120, 120, 110), Qt::BDiagPattern), [&](auto&& add) {
        for (const reconstruction::NoDataInterval& gap : m_analysis->noData)
            add(rowEdge_m(m_depth_m, gap.firstRow, false), rowEdge_m(m_depth_m, gap.lastRow, true));
    });
    band("arms not open", QBrush(QColor(120, 120, 120, 110), Qt::FDiagPattern), [&](auto&& add) {
        for (const reconstruction::NoDataInterval& gap : m_analysis->armsNotOpen)
            add(rowEdge_m(m_depth_m, gap.firstRow, false), rowEdge_m(m_depth_m, gap.lastRow, true));
    });
}

void LogTrackDock::addCurve(const RowCurve& values, const QString& name, const QPen& pen) {
    addCurve(m_depth_m, values, name, pen);
}

void LogTrackDock::addCurve(const RowCurve& depth_m, const RowCurve& values, const QString& name,
                            const QPen& pen) {
    for (const TraceRun& run :
         decimateTrace(depth_m, values, top_m(), bottom_m(), m_drawnHeight_px)) {
        auto* series = new QLineSeries;
        QVector<QPointF> points;
        points.reserve(int(run.size()));
        for (const TracePoint& p : run) points.append(QPointF(p.value, p.depth_m));
        series->replace(points);
        series->setName(name);
        series->setPen(pen);
        series->setPointsVisible(run.size() == 1);  // a lone row between gaps: a dot
        m_chart->addSeries(series);
        series->attachAxis(m_valueAxis);
        series->attachAxis(m_depthAxis);
    }
}

// Image-log picks (--picks) at the right edge of the track: a magenta bar over a pick's
// depths, a tick at a pick's one depth.
void LogTrackDock::addPicks() {
    const double right = m_valueHigh_mm, tick = 0.08 * (m_valueHigh_mm - m_valueLow_mm);
    for (const io::Pick& p : m_picks) {
        if (p.bottom_m < top_m() || p.top_m > bottom_m()) continue;
        auto* series = new QLineSeries;
        if (p.bottom_m > p.top_m) {
            series->append(right - tick / 2, p.top_m);
            series->append(right - tick / 2, p.bottom_m);
        } else {
            series->append(right - tick, p.top_m);
            series->append(right, p.top_m);
        }
        series->setName("image-log pick");
        series->setPen(QPen(QColor(0xFF, 0x00, 0xFF), 3));
        m_chart->addSeries(series);
        series->attachAxis(m_valueAxis);
        series->attachAxis(m_depthAxis);
    }
}

void LogTrackDock::moveCursor() {
    const double md_m = m_model.currentDepth_m();
    if (m_model.currentWell() != m_well || !std::isfinite(md_m)) return m_cursor->clear();
    m_cursor->replace(
        QVector<QPointF>{QPointF(m_valueAxis->min(), md_m), QPointF(m_valueAxis->max(), md_m)});
}

void LogTrackDock::follow(double md_m) {
    const double top = top_m(), span_m = bottom_m() - top;
    if (!std::isfinite(md_m) || !(span_m > 0.0)) return;
    const double room_m = 0.05 * span_m;  // keep the line off the very edge
    if (md_m < top + room_m)
        setDepthWindow(md_m - room_m, md_m - room_m + span_m);
    else if (md_m > top + span_m - room_m)
        setDepthWindow(md_m + room_m - span_m, md_m + room_m);
}

bool LogTrackDock::depthAt(const QPoint& viewportPos, double& md_m) const {
    const QPointF chartPos = m_chart->mapFromScene(m_view->mapToScene(viewportPos));
    const QRectF plot = m_chart->plotArea();
    if (chartPos.x() < plot.left() || chartPos.x() > plot.right()) return false;
    // A drag past the top or bottom keeps going along the edge (and the track scrolls).
    const QPointF inside(chartPos.x(), std::clamp(chartPos.y(), plot.top(), plot.bottom()));
    md_m = m_chart->mapToValue(inside, m_cursor).y();
    return std::isfinite(md_m);
}

int LogTrackDock::plotHeight_px() const {
    const int height = int(std::lround(m_chart->plotArea().height()));
    return height >= 50 ? height : 400;  // before the first layout
}

bool LogTrackDock::eventFilter(QObject* watched, QEvent* event) {
    if (watched != m_view->viewport() || !m_analysis)
        return QDockWidget::eventFilter(watched, event);
    double md_m = 0.0;
    switch (event->type()) {
        case QEvent::MouseButtonPress:
        case QEvent::MouseMove: {
            const auto* mouse = static_cast<QMouseEvent*>(event);
            if (event->type() == QEvent::MouseButtonPress) {
                if (mouse->button() != Qt::LeftButton) return false;
                m_dragging = m_chart->plotArea().contains(
                    m_chart->mapFromScene(m_view->mapToScene(mouse->pos())));
            }
            if (m_dragging && depthAt(mouse->pos(), md_m)) m_model.setCurrentDepth(md_m);
            return m_dragging;
        }
        case QEvent::MouseButtonRelease:
            m_dragging = false;
            return false;
        case QEvent::Wheel: {
            const auto* wheel = static_cast<QWheelEvent*>(event);
            if (!depthAt(wheel->position().toPoint(), md_m)) return false;
            zoom(std::pow(1.25, wheel->angleDelta().y() / 120.0), md_m);
            return true;
        }
        default:
            return false;
    }
}

}  // namespace caliper3d::app
