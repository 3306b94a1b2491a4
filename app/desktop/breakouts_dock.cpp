#include "app/desktop/breakouts_dock.h"

#include <algorithm>
#include <cmath>

#include <QHeaderView>
#include <QLabel>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <QtCharts/QAreaSeries>
#include <QtCharts/QChartView>
#include <QtCharts/QLineSeries>
#include <QtCharts/QPolarChart>
#include <QtCharts/QValueAxis>

#include "app/desktop/desk_model.h"
#include "reconstruction/analysis/breakout_rose.h"
#include "reconstruction/analysis/pick_comparison.h"
#include "reconstruction/analysis/wall_colour_request.h"

QT_CHARTS_USE_NAMESPACE

namespace caliper3d::app {

namespace {

QColor classQColour(reconstruction::BoreholeClass cls, int alpha = 255) {
    const std::uint32_t rgba = reconstruction::classColour(cls);
    return QColor(int(rgba >> 24) & 0xFF, int(rgba >> 16) & 0xFF, int(rgba >> 8) & 0xFF, alpha);
}

QString number(double value, int decimals) {
    return std::isfinite(value) ? QString::number(value, 'f', decimals) : QString("-");
}

QString degrees(double value) {
    return std::isfinite(value) ? QString::number(value, 'f', 0) + QChar(0x00B0) : QString("-");
}

}  // namespace

BreakoutsDock::BreakoutsDock(DeskModel& model, QWidget* parent)
    : QDockWidget("Breakouts", parent), m_model(model) {
    setObjectName("breakouts");
    m_chart = new QPolarChart;
    m_chart->setAnimationOptions(QChart::NoAnimation);
    // Room for the angle labels outside the rose, which a narrow dock would put on it.
    m_chart->setMargins(QMargins(8, 4, 8, 8));
    // The summary under the rose says what its lines are: the chart's own legend would
    // cut their names short in a narrow dock.
    m_chart->legend()->hide();
    // Azimuths clockwise from north at the top: the polar chart's own convention.
    auto* angular = new QValueAxis(m_chart);
    angular->setRange(0.0, 360.0);
    // Labelled every 90 degrees, a line every 30: twelve labels crowd a rose this small.
    angular->setTickCount(5);
    angular->setMinorTickCount(2);
    angular->setLabelFormat("%d");
    m_chart->addAxis(angular, QPolarChart::PolarOrientationAngular);
    m_radial = new QValueAxis(m_chart);
    m_radial->setLabelFormat("%.0f m");
    m_radial->setTickCount(3);
    m_chart->addAxis(m_radial, QPolarChart::PolarOrientationRadial);
    m_view = new QChartView(m_chart);
    m_view->setRenderHint(QPainter::Antialiasing);
    m_view->setMinimumSize(180, 180);
    m_summary = new QLabel;
    m_summary->setWordWrap(true);
    m_summary->setObjectName("breakoutSummary");
    m_table = new QTableWidget(0, kColumns);
    m_table->setHorizontalHeaderLabels(
        {"class", "top m", "bottom m", "length m", "azimuth", "SD", "dmax / dmin mm"});
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setToolTip("Every zone of the analysis; a click goes to the zone's top");
    connect(m_table, &QTableWidget::cellClicked, this, [this](int row, int) { rowClicked(row); });

    auto* top = new QWidget;
    auto* layout = new QVBoxLayout(top);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_view, 1);
    layout->addWidget(m_summary);
    auto* split = new QSplitter(Qt::Vertical, this);
    split->addWidget(top);
    split->addWidget(m_table);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    setWidget(split);

    connect(&m_model, &DeskModel::wellsChanged, this, &BreakoutsDock::sync);
    connect(&m_model, &DeskModel::wellChanged, this, [this](int well) {
        if (well == m_model.currentWell()) sync();
    });
    connect(&m_model, &DeskModel::currentChanged, this, [this](int well, double md_m) {
        if (well != m_well || !m_analysis) return sync();
        selectZoneAt(md_m);
    });
    sync();
}

QSize BreakoutsDock::sizeHint() const {
    return {kWidth_px, 480};
}

QString BreakoutsDock::summaryText() const {
    return m_summary->text();
}

void BreakoutsDock::sync() {
    const DeskWell* well = m_model.current();
    const int index = m_model.currentWell();
    if (!well || !well->geometry || !well->analysis) {
        m_well = index;
        m_analysis.reset();
        return clear(!well ? "No well loaded" : !well->geometry ? "No geometry" : "analysing...");
    }
    if (index != m_well || well->analysis != m_analysis) {
        m_well = index;
        m_analysis = well->analysis;
        fillRose(*m_analysis);
        addPicks(well->picks);
        fillSummary(*m_analysis);
        fillTable(*m_analysis);
    }
    selectZoneAt(m_model.currentDepth_m());
}

void BreakoutsDock::clear(const QString& message) {
    m_chart->removeAllSeries();
    m_chart->setTitle(message);
    m_summary->setText(message);
    m_table->setRowCount(0);
}

void BreakoutsDock::fillRose(const reconstruction::WellAnalysis& analysis) {
    m_chart->removeAllSeries();
    m_chart->setTitle(QString());
    const reconstruction::BreakoutRose rose = reconstruction::breakoutRose(analysis.zones);
    const std::vector<double> bins_m = rose.mirrored();
    const double largest_m = rose.largest_m();
    m_radial->setRange(0.0, largest_m > 0.0 ? largest_m * 1.1 : 1.0);
    m_radial->setLabelFormat(largest_m >= 5.0 ? "%.0f m" : "%.1f m");
    m_radial->setLabelsVisible(largest_m > 0.0);  // no scale to read on an empty rose
    if (largest_m > 0.0) {
        // Each bin a wedge: its arc traced a degree at a time (a polar chart joins points
        // with straight lines), the next bin's radius reached along the shared edge.
        auto* outline = new QLineSeries;
        auto* centre = new QLineSeries;
        for (std::size_t i = 0; i < bins_m.size(); ++i)
            for (int step = 0; step <= int(rose.binWidth_deg); ++step)
                outline->append(double(i) * rose.binWidth_deg + step, bins_m[i]);
        centre->append(0.0, 0.0);
        centre->append(360.0, 0.0);
        auto* area = new QAreaSeries(outline, centre);
        outline->setParent(area);
        centre->setParent(area);
        area->setName(QString("m a %1%2").arg(rose.binWidth_deg).arg(QChar(0x00B0)));
        area->setBrush(classQColour(reconstruction::BoreholeClass::Breakout, 200));
        area->setPen(QPen(classQColour(reconstruction::BoreholeClass::Breakout).darker(150), 1));
        m_chart->addSeries(area);
        for (QAbstractAxis* axis : m_chart->axes()) area->attachAxis(axis);
    }
    const reconstruction::BreakoutSummary& s = analysis.breakouts;
    if (s.zoneCount > 0 && std::isfinite(s.meanAzimuth_deg)) {
        const double reach = m_radial->max();
        addAxisLine(s.meanAzimuth_deg, reach, "mean " + degrees(s.meanAzimuth_deg),
                    QPen(QColor(0x00, 0x72, 0xB2), 2, Qt::DashLine));
        addAxisLine(s.shmaxAzimuth_deg, reach, "SHmax " + degrees(s.shmaxAzimuth_deg),
                    QPen(Qt::black, 2.5));
    }
    if (largest_m <= 0.0) m_chart->setTitle("No breakouts");
}

// Breakouts picked on an image log (--picks): a thin magenta axis each, inside the rose's
// reach, to compare with the caliper's (docs/analysis.md, "Picks").
void BreakoutsDock::addPicks(const std::vector<io::Pick>& picks) {
    const double reach = 0.85 * m_radial->max();
    int shown = 0;
    for (const io::Pick& p : picks) {
        if (!reconstruction::isBreakoutPick(p.type) || !std::isfinite(p.azimuth_deg)) continue;
        if (++shown > 200) break;  // beyond that the rose is a disc of lines
        addAxisLine(p.azimuth_deg, reach, "image-log pick " + degrees(p.azimuth_deg),
                    QPen(QColor(0xFF, 0x00, 0xFF), 1));
    }
}

void BreakoutsDock::addAxisLine(double azimuth_deg, double length, const QString& name,
                                const QPen& pen) {
    // Both ends of the axis, through the centre (the data are axial).
    const double a = std::fmod(azimuth_deg, 180.0), b = a + 180.0;
    auto* line = new QLineSeries;
    line->append(a, length);
    line->append(a, 0.0);
    line->append(b, 0.0);
    line->append(b, length);
    line->setName(name);
    line->setPen(pen);
    m_chart->addSeries(line);
    for (QAbstractAxis* axis : m_chart->axes()) line->attachAxis(axis);
}

void BreakoutsDock::fillSummary(const reconstruction::WellAnalysis& analysis) {
    const reconstruction::BreakoutSummary& s = analysis.breakouts;
    QString text;
    if (s.zoneCount == 0) {
        text = "No breakout zones: World Stress Map quality E.";
    } else {
        text = QString(
                   "%1 breakout zone%2, %3 m combined; mean azimuth %4, circular SD %5; "
                   "SHmax %6; World Stress Map quality <b>%7</b>.")
                   .arg(s.zoneCount)
                   .arg(s.zoneCount == 1 ? "" : "s")
                   .arg(number(s.combinedLength_m, 1), degrees(s.meanAzimuth_deg),
                        degrees(s.circularSd_deg), degrees(s.shmaxAzimuth_deg),
                        QString(QChar(s.quality)));
    }
    if (analysis.twoPads) text += " A two-pad tool: its sections are round, no breakout shows.";
    // What the azimuths above rest on, for this well (docs/conventions.md).
    if (analysis.unorientedSections > 0)
        text += QString(
                    " %1 section%2 without a pad-1 azimuth or relative bearing: their "
                    "azimuths are unknown and left out.")
                    .arg(analysis.unorientedSections)
                    .arg(analysis.unorientedSections == 1 ? "" : "s");
    if (analysis.holeAzimuthUnknown)
        text +=
            " The hole's azimuth is unknown: azimuths come from the pad-1 azimuth where the "
            "log has one; those that need the hole's direction are left out.";
    m_summary->setText(text);
    m_summary->setToolTip(
        "Breakouts form across the largest horizontal stress: SHmax is the mean + 90 degrees "
        "in a near-vertical well. Quality after Heidbach et al. 2010 (docs/analysis.md).");
}

void BreakoutsDock::fillTable(const reconstruction::WellAnalysis& analysis) {
    m_table->setUpdatesEnabled(false);
    m_table->clearContents();
    m_table->setRowCount(int(analysis.zones.size()));
    for (std::size_t i = 0; i < analysis.zones.size(); ++i) {
        const reconstruction::Zone& z = analysis.zones[i];
        const int row = int(i);
        auto* cls =
            new QTableWidgetItem(QString::fromUtf8(reconstruction::className(z.kind).data()));
        cls->setBackground(classQColour(z.kind, 110));
        m_table->setItem(row, kClass, cls);
        m_table->setItem(row, kTop, new QTableWidgetItem(number(z.top_m, 2)));
        m_table->setItem(row, kBottom, new QTableWidgetItem(number(z.bottom_m, 2)));
        m_table->setItem(row, kLength, new QTableWidgetItem(number(z.length_m, 2)));
        m_table->setItem(row, kAzimuth, new QTableWidgetItem(degrees(z.meanAzimuth_deg)));
        m_table->setItem(row, kSd, new QTableWidgetItem(degrees(z.circularSd_deg)));
        m_table->setItem(
            row, kDiameters,
            new QTableWidgetItem(number(z.meanDmax_mm, 1) + " / " + number(z.meanDmin_mm, 1)));
        for (int column = kTop; column < kColumns; ++column)
            m_table->item(row, column)->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    }
    m_table->resizeColumnsToContents();
    m_table->setUpdatesEnabled(true);
}

void BreakoutsDock::selectZoneAt(double md_m) {
    const QSignalBlocker block(m_table);
    if (!m_analysis || !std::isfinite(md_m)) return m_table->clearSelection();
    const auto& zones = m_analysis->zones;
    // The first zone whose bottom is at or below md_m; md_m is in it when its top is above.
    const auto it = std::lower_bound(zones.begin(), zones.end(), md_m,
                                     [](const auto& z, double md) { return z.bottom_m < md; });
    if (it == zones.end() || it->top_m > md_m) return m_table->clearSelection();
    const int row = int(it - zones.begin());
    m_table->selectRow(row);
    m_table->scrollTo(m_table->model()->index(row, 0));
}

void BreakoutsDock::rowClicked(int row) {
    if (!m_analysis || row < 0 || row >= int(m_analysis->zones.size())) return;
    // The zone's top lies half a step above its first row, as far from the row above: go to
    // the first row, so that the current section is in the zone.
    const reconstruction::Zone& zone = m_analysis->zones[std::size_t(row)];
    m_model.setCurrentDepth(m_analysis->sections[zone.firstSection].md_m);
}

}  // namespace caliper3d::app
