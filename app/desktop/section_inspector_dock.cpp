#include "app/desktop/section_inspector_dock.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <QBoxLayout>
#include <QFileInfo>
#include <QFormLayout>
#include <QLabel>
#include <QResizeEvent>
#include <QScrollArea>
#include <QScrollBar>
#include <QStringList>
#include <QVBoxLayout>
#include <QtCharts/QChartView>
#include <QtCharts/QLegend>
#include <QtCharts/QLineSeries>
#include <QtCharts/QPolarChart>
#include <QtCharts/QScatterSeries>
#include <QtCharts/QValueAxis>

#include "app/desktop/desk_model.h"
#include "app/desktop/polar_series.h"
#include "reconstruction/analysis/report_writer.h"

QT_CHARTS_USE_NAMESPACE

namespace caliper3d::app {

namespace {

using reconstruction::PolarPoint;

// The report fields shown, in order, with their labels.
struct Field {
    const char* name;
    const char* label;
};
constexpr Field kFields[] = {
    {"md_m", "MD (m)"},
    {"dmin_mm", "dmin (mm)"},
    {"dmax_mm", "dmax (mm)"},
    {"ellipticity", "ellipticity"},
    {"major_azimuth_deg", "major axis azimuth (deg)"},
    {"major_from_high_side_deg", "major axis from high side (deg)"},
    {"area_mm2", "area (mm\u00b2)"},
    {"equivalent_diameter_mm", "equivalent diameter (mm)"},
    {"centre_offset_mm", "centre offset (mm)"},
    {"class", "class"},
};

constexpr int kAxisPoints = 33;  // along each ellipse axis

// The series' colours, named once for the plot and its key.
const QColor kBitColour(150, 150, 150), kEllipseColour(230, 140, 20), kMajorColour(200, 60, 30),
    kMinorColour(40, 120, 200), kSplineColour(20, 20, 20), kNorthColour(30, 150, 60),
    kHighSideColour(150, 60, 170), kOtherRunColour(0, 114, 178);

QString keyText() {
    const auto item = [](const QColor& c, const char* mark, const char* name) {
        return QString("<span style='color:%1'><b>%2</b></span>&nbsp;%3").arg(c.name(), mark, name);
    };
    return QStringList{item(kSplineColour, "\u25cf", "pads"),
                       item(kSplineColour, "\u2014", "spline"),
                       item(kEllipseColour, "\u2014", "fitted ellipse"),
                       item(kMajorColour, "\u2014", "major"),
                       item(kMinorColour, "\u2014", "minor axis"),
                       item(kBitColour, "- -", "bit size"),
                       item(kNorthColour, "\u2014", "north"),
                       item(kHighSideColour, "\u2014", "high side"),
                       item(kOtherRunColour, "- -", "another run of the well")}
        .join(" &nbsp; ");
}

QList<QPointF> spoke(double angle_deg, double radius_mm) {
    if (!std::isfinite(angle_deg)) return {};
    return {QPointF(angle_deg, 0.0), QPointF(angle_deg, radius_mm)};
}

// The radial axis's end: the farthest thing drawn, with room, to a round 40 mm (four rings of a
// multiple of 10 mm).
double radialRange(const reconstruction::SectionOutline& o,
                   const std::vector<PolarPoint>& ellipse) {
    double r = std::isfinite(o.bitRadius_mm) ? o.bitRadius_mm : 0.0;
    for (const auto* points : {&o.spline, &o.pads, &ellipse})
        for (const PolarPoint& p : *points) r = std::max(r, p.radius_mm);
    return r > 0.0 ? 40.0 * std::ceil(r * 1.05 / 40.0) : 160.0;
}

}  // namespace

SectionInspectorDock::SectionInspectorDock(DeskModel* model, QWidget* parent)
    : QDockWidget("Section inspector", parent), m_model(model) {
    setObjectName("sectionInspector");
    auto* body = new QWidget(this);
    m_layout = new QBoxLayout(QBoxLayout::TopToBottom, body);
    buildChart();
    auto* plot = new QWidget(body);
    auto* plotLayout = new QVBoxLayout(plot);
    plotLayout->setContentsMargins(0, 0, 0, 0);
    plotLayout->addWidget(m_view, 1);
    auto* key = new QLabel(keyText(), plot);
    key->setWordWrap(true);
    plotLayout->addWidget(key);
    m_layout->addWidget(plot, 1);
    // The numbers ask for their whole height (the plot gives way first, its chart down to 160
    // px), and scroll when the dock is shorter than even that (the window's right column
    // shares its height with the breakouts): a squeezed form lays its rows over one another,
    // the heading's wrapped lines over the first numbers.
    m_numbers = new QScrollArea(body);
    m_numbers->setFrameShape(QFrame::NoFrame);
    m_numbers->setWidgetResizable(true);
    m_numbers->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_numbers->setSizePolicy(QSizePolicy::Minimum, QSizePolicy::Minimum);
    auto* panel = new QWidget;
    buildNumbers(panel);
    m_numbers->setWidget(panel);
    m_layout->addWidget(m_numbers, 0);
    setWidget(body);
    connect(m_model, &DeskModel::currentChanged, this, &SectionInspectorDock::refresh);
    // The current well's section, and its other run's: another well's change leaves them.
    connect(m_model, &DeskModel::wellChanged, this, [this](int well) {
        const int current = m_model->currentWell();
        if (current < 0 || well == current) return refresh();
        const std::vector<int> others = m_model->otherRuns(current);
        if (std::find(others.begin(), others.end(), well) != others.end()) refresh();
    });
    connect(m_model, &DeskModel::wellsChanged, this, &SectionInspectorDock::refresh);
    refresh();
}

QXYSeries* SectionInspectorDock::addSeries(QXYSeries* series, const QString& name,
                                           const QColor& colour, qreal width) {
    series->setName(name);
    QPen pen(colour);
    pen.setWidthF(width);
    series->setPen(pen);
    series->setColor(colour);
    m_chart->addSeries(series);
    series->attachAxis(m_angle);
    series->attachAxis(m_radius);
    m_series[name] = series;
    return series;
}

void SectionInspectorDock::buildChart() {
    m_chart = new QPolarChart;
    m_chart->setMargins(QMargins(2, 2, 2, 2));
    // Eight series: a legend under the plot would elide every name in a dock's width, so a
    // key in words sits under it instead (keyText).
    m_chart->legend()->hide();
    m_angle = new QValueAxis;
    m_angle->setRange(0.0, 360.0);
    m_angle->setTickCount(9);  // every 45 degrees
    m_angle->setLabelFormat("%.0f");
    m_chart->addAxis(m_angle, QPolarChart::PolarOrientationAngular);
    m_radius = new QValueAxis;
    m_radius->setLabelFormat("%.0f");
    m_radius->setTickCount(5);
    m_chart->addAxis(m_radius, QPolarChart::PolarOrientationRadial);
    addSeries(new QLineSeries, "bit size", QColor(150, 150, 150), 1.5)
        ->setPen(QPen(QColor(150, 150, 150), 1.5, Qt::DashLine));
    addSeries(new QLineSeries, "ellipse", QColor(230, 140, 20), 1.5);
    addSeries(new QLineSeries, "major axis", QColor(200, 60, 30), 1.5);
    addSeries(new QLineSeries, "minor axis", QColor(40, 120, 200), 1.5);
    addSeries(new QLineSeries, "other run", kOtherRunColour, 2.0)
        ->setPen(QPen(kOtherRunColour, 2.0, Qt::DashLine));
    addSeries(new QLineSeries, "spline", QColor(20, 20, 20), 2.0);
    addSeries(new QLineSeries, "north", QColor(30, 150, 60), 2.0);
    addSeries(new QLineSeries, "high side", QColor(150, 60, 170), 2.0);
    auto* pads = new QScatterSeries;
    pads->setMarkerSize(8.0);
    pads->setBorderColor(Qt::white);
    addSeries(pads, "pads", QColor(20, 20, 20), 1.0);
    m_view = new QChartView(m_chart);
    m_view->setRenderHint(QPainter::Antialiasing);
    // Short docks shrink the plot, not the numbers: a form given less than its height lays its
    // rows over one another (the window's right column shares its height with the breakouts).
    m_view->setMinimumSize(260, 160);
}

void SectionInspectorDock::buildNumbers(QWidget* panel) {
    auto* form = new QFormLayout(panel);
    form->setContentsMargins(4, 0, 4, 4);
    m_heading = new QLabel(panel);
    m_heading->setObjectName("heading");
    m_heading->setWordWrap(true);
    form->addRow(m_heading);
    for (const Field& f : kFields) {
        auto* value = new QLabel(panel);
        value->setObjectName(QString("value_") + f.name);
        value->setTextInteractionFlags(Qt::TextSelectableByMouse);
        form->addRow(QString(f.label), value);
        m_values[f.name] = value;
    }
}

QString SectionInspectorDock::value(const QString& field) const {
    const auto it = m_values.find(field);
    return it == m_values.end() ? QString() : it->second->text();
}

QXYSeries* SectionInspectorDock::series(const QString& name) const {
    const auto it = m_series.find(name);
    return it == m_series.end() ? nullptr : it->second;
}

void SectionInspectorDock::refresh() {
    const DeskWell* well = m_model->current();
    m_outline = reconstruction::SectionOutline{};
    m_otherOutline = reconstruction::SectionOutline{};
    m_otherWell = -1;
    m_otherDepth_m = io::kNaN;
    if (well && well->geometry) {
        // North where it is known, else the high side (an inclined hole without azimuth whose
        // arm 1 came from RB).
        const std::size_t row = m_model->currentRow();
        const auto reference = reconstruction::referenceKnown(*well->geometry, row,
                                                              reconstruction::AngleReference::North)
                                   ? reconstruction::AngleReference::North
                                   : reconstruction::AngleReference::HighSide;
        m_outline = reconstruction::sectionOutline(*well->geometry, row, reference, kSplineSamples);
        otherRunOutline(reference);
    }
    showOutline();
    showNumbers();
    fitNumbersWidth();
}

// Another run of the current well (the main run, or the main run's first other run) at the
// depth matched to the current one, about its own tool axis from the same reference.
void SectionInspectorDock::otherRunOutline(reconstruction::AngleReference reference) {
    const int current = m_model->currentWell();
    const std::vector<int> others = m_model->otherRuns(current);
    if (others.empty()) return;
    m_otherWell = others.front();
    const DeskWell& other = m_model->well(m_otherWell);
    m_otherDepth_m = m_model->matchedDepth_m(current, m_otherWell, m_model->currentDepth_m());
    if (!other.geometry || !std::isfinite(m_otherDepth_m)) return;
    const std::vector<double>& md = other.geometry->table().depth_m;
    if (md.empty() || m_otherDepth_m < md.front() || m_otherDepth_m > md.back()) return;
    const std::size_t row = DeskModel::nearestRow(*other.geometry, m_otherDepth_m);
    if (!reconstruction::referenceKnown(*other.geometry, row, reference)) return;
    m_otherOutline =
        reconstruction::sectionOutline(*other.geometry, row, reference, kSplineSamples);
}

void SectionInspectorDock::showOutline() {
    const reconstruction::SectionOutline& o = m_outline;
    std::vector<PolarPoint> ellipse;
    if (o.measured) ellipse = reconstruction::ellipsePoints(o.ellipse, kSplineSamples);
    // The other run's outline in view too.
    std::vector<PolarPoint> shown = ellipse;
    if (m_otherOutline.measured)
        shown.insert(shown.end(), m_otherOutline.spline.begin(), m_otherOutline.spline.end());
    const double range = radialRange(o, shown);
    m_radius->setRange(0.0, range);
    QList<QPointF> pads;
    for (const PolarPoint& p : o.pads) pads.append({p.angle_deg, p.radius_mm});
    m_series.at("pads")->replace(pads);
    m_series.at("spline")->replace(polarPolyline(o.spline, true));
    m_series.at("other run")
        ->replace(m_otherOutline.measured ? polarPolyline(m_otherOutline.spline, true)
                                          : QList<QPointF>{});
    m_series.at("ellipse")->replace(polarPolyline(ellipse, true));
    const bool axes = o.measured && elongated();
    m_series.at("major axis")
        ->replace(
            axes ? polarPolyline(reconstruction::ellipseAxis(o.ellipse, true, kAxisPoints), false)
                 : QList<QPointF>{});
    m_series.at("minor axis")
        ->replace(
            axes ? polarPolyline(reconstruction::ellipseAxis(o.ellipse, false, kAxisPoints), false)
                 : QList<QPointF>{});
    std::vector<PolarPoint> bit;
    if (std::isfinite(o.bitRadius_mm))
        for (int j = 0; j < kSplineSamples; ++j)
            bit.push_back({360.0 * j / kSplineSamples, o.bitRadius_mm});
    m_series.at("bit size")->replace(polarPolyline(bit, true));
    m_series.at("north")->replace(spoke(o.northAngle_deg, range));
    m_series.at("high side")->replace(spoke(o.highSideAngle_deg, range));

    const DeskWell* well = m_model->current();
    QString title = "no section";
    if (well && well->geometry) {
        title = o.reference == reconstruction::AngleReference::North
                    ? "clockwise from north"
                    : "clockwise from the high side (no north here)";
        if (!o.measured) title += ": no data";
    }
    m_chart->setTitle(title);
}

bool SectionInspectorDock::elongated() const {
    // A round section has no major axis (the report leaves its angles empty): the fitted
    // axes' direction would be rounding noise.
    const DeskWell* well = m_model->current();
    const std::size_t row = m_model->currentRow();
    if (well && well->analysis && row < well->analysis->sections.size()) {
        const reconstruction::SectionResult& r = well->analysis->sections[row];
        return std::isfinite(r.majorAzimuth_deg) || std::isfinite(r.majorFromHighSide_deg);
    }
    return m_outline.ellipse.major_mm - m_outline.ellipse.minor_mm >=
           reconstruction::ClassificationRules{}.axisMinElongation_mm;
}

QString SectionInspectorDock::otherRunText() const {
    if (m_otherWell < 0) return {};
    const DeskWell& other = m_model->well(m_otherWell);
    const QString name = QFileInfo(other.path).fileName().toHtmlEscaped();
    // The match's error is on the record of whichever of the two is not the main run.
    const DeskWell* current = m_model->current();
    const QString error = !other.matchError.isEmpty() ? other.matchError
                          : current                   ? current->matchError
                                                      : QString();
    QString text;
    if (!std::isfinite(m_otherDepth_m))
        text = name + (error.isEmpty() ? QString(": depth match not known yet")
                                       : ": not matched: " + error.toHtmlEscaped());
    else if (!m_otherOutline.measured)
        text =
            QString("%1 at MD %2 m (matched): no section").arg(name).arg(m_otherDepth_m, 0, 'f', 2);
    else
        text = QString("<span style='color:%1'>- -</span> %2 at MD %3 m (matched)")
                   .arg(kOtherRunColour.name(), name)
                   .arg(m_otherDepth_m, 0, 'f', 2);
    return "<br><small>" + text + "</small>";
}

void SectionInspectorDock::setAllValues(const QString& text) {
    for (auto& entry : m_values) entry.second->setText(text);
}

void SectionInspectorDock::showNumbers() {
    const DeskWell* well = m_model->current();
    if (!well || !well->geometry) {
        m_heading->setText("No well loaded");
        setAllValues(QString());
        return;
    }
    const std::size_t row = m_model->currentRow();
    // Which north the azimuths below are from, and the declination applied
    // (docs/conventions.md, "North").
    const std::string& north = well->geometry->table().north;
    m_heading->setText(
        QString("<b>%1</b> at MD %2 m (section %3 of %4)%5")
            .arg(well->name.toHtmlEscaped())
            .arg(m_model->currentDepth_m(), 0, 'f', 2)
            .arg(row + 1)
            .arg(well->geometry->table().rowCount())
            .arg((north.empty() ? QString()
                                : "<br><small>North: " +
                                      QString::fromStdString(north).toHtmlEscaped() + "</small>") +
                 otherRunText()));
    fitHeading();
    if (!well->analysis || row >= well->analysis->sections.size()) {
        setAllValues("analysing...");
        return;
    }
    const reconstruction::SectionResult& r = well->analysis->sections[row];
    const bool noData = r.cls == reconstruction::BoreholeClass::NoData;
    const bool azimuthUnknown = well->analysis->holeAzimuthUnknown;
    // No pad-1 azimuth nor relative bearing on this row: every angle of the shape is unknown.
    const bool unoriented =
        well->geometry && row < well->geometry->table().rowCount() &&
        well->geometry->orientation(row) == reconstruction::WellGeometry::Orientation::Unoriented;
    for (const auto& [name, text] : reconstruction::sectionReportFields(r)) {
        const auto it = m_values.find(QString::fromStdString(name));
        if (it == m_values.end()) continue;
        QString shown = QString::fromStdString(text);
        // An empty field: a section without data, an angle that depends on an unknown hole
        // azimuth, or a round section's axis and a centred tool's offset direction.
        const bool axisAngle = name == "major_azimuth_deg" || name == "major_from_high_side_deg";
        const bool elongatedAxis =
            std::isfinite(r.majorAzimuth_deg) || std::isfinite(r.majorFromHighSide_deg);
        const bool angleField = name.find("azimuth") != std::string::npos ||
                                name.find("high_side") != std::string::npos;
        if (shown.isEmpty() && !noData && unoriented && angleField)
            shown = "unknown: no orientation";
        else if (shown.isEmpty())
            shown = noData ? "no data"
                           : (azimuthUnknown && axisAngle && elongatedAxis ? "unknown" : "none");
        it->second->setText(shown);
    }
}

// As wide as the numbers are, with room for the scroll bar: the dock keeps them whole.
void SectionInspectorDock::fitNumbersWidth() {
    m_numbers->setMinimumWidth(m_numbers->widget()->sizeHint().width() +
                               m_numbers->verticalScrollBar()->sizeHint().width());
}

void SectionInspectorDock::resizeEvent(QResizeEvent* event) {
    QDockWidget::resizeEvent(event);
    // Beside the plot when the dock is wide, under it when it is tall.
    m_layout->setDirection(event->size().width() > event->size().height() * 5 / 4
                               ? QBoxLayout::LeftToRight
                               : QBoxLayout::TopToBottom);
    fitHeading();
}

// A wrapped label in a form gets the height of its first lines only: give it the height its
// text takes at its width (the north line can run to four lines).
void SectionInspectorDock::fitHeading() {
    const int width = std::max(m_heading->width(), 200);
    m_heading->setMinimumHeight(m_heading->heightForWidth(width));
}

}  // namespace caliper3d::app
