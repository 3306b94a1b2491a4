#include "app/desktop/wells_dock.h"

#include <cmath>

#include <QComboBox>
#include <QHeaderView>
#include <QTreeWidget>

#include "app/desktop/desk_model.h"
#include "reconstruction/analysis/wall_colour_request.h"

namespace caliper3d::app {

WellsDock::WellsDock(DeskModel& model, QWidget* parent)
    : QDockWidget("Wells", parent), m_model(model) {
    setObjectName("wells");
    m_tree = new QTreeWidget(this);
    m_tree->setRootIsDecorated(false);
    m_tree->setColumnCount(ColumnCount);
    m_tree->setHeaderLabels({"Well", "Colour by", "Bit size", "Units", "Rows", "MD (m)", "State"});
    m_tree->header()->setSectionResizeMode(QHeaderView::ResizeToContents);
    setWidget(m_tree);
    connect(&model, &DeskModel::wellsChanged, this, &WellsDock::rebuild);
    connect(&model, &DeskModel::wellChanged, this, &WellsDock::refresh);
    connect(&model, &DeskModel::currentChanged, this, [this](int well) {
        if (well >= 0 && well < m_tree->topLevelItemCount())
            m_tree->setCurrentItem(m_tree->topLevelItem(well));
    });
    connect(m_tree, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item, int column) {
        if (column != Name) return;
        const int well = m_tree->indexOfTopLevelItem(item);
        const bool visible = item->checkState(Name) == Qt::Checked;
        if (well >= 0 && m_model.well(well).visible != visible)
            emit visibilityToggled(well, visible);
    });
    connect(m_tree, &QTreeWidget::itemClicked, this, [this](QTreeWidgetItem* item) {
        const int well = m_tree->indexOfTopLevelItem(item);
        if (well != m_model.currentWell()) m_model.setCurrent(well, m_model.currentDepth_m());
    });
    rebuild();
}

void WellsDock::rebuild() {
    const QSignalBlocker block(m_tree);
    m_tree->clear();
    for (int i = 0; i < m_model.wellCount(); ++i) {
        auto* item = new QTreeWidgetItem(m_tree);
        auto* colour = new QComboBox(m_tree);
        colour->setObjectName(QString("colourBy%1").arg(i));
        m_tree->setItemWidget(item, Colour, colour);
        connect(colour, QOverload<int>::of(&QComboBox::activated), this,
                [this, i, colour](int) { emit colourChosen(i, colour->currentText()); });
        fill(item, i);
    }
}

void WellsDock::refresh(int well) {
    if (well < 0 || well >= m_tree->topLevelItemCount()) return;
    const QSignalBlocker block(m_tree);
    fill(m_tree->topLevelItem(well), well);
}

void WellsDock::fill(QTreeWidgetItem* item, int well) {
    const DeskWell& w = m_model.well(well);
    item->setText(Name, w.name);
    item->setToolTip(Name, w.path);
    item->setCheckState(Name, w.visible ? Qt::Checked : Qt::Unchecked);
    auto* colour = qobject_cast<QComboBox*>(m_tree->itemWidget(item, Colour));
    if (colour) {
        const QSignalBlocker block(colour);
        colour->clear();
        if (w.geometry)
            for (const std::string& name : reconstruction::colourQuantities(w.geometry->table()))
                colour->addItem(QString::fromStdString(name));
        colour->setCurrentText(QString::fromStdString(w.options.colour.quantity));
        colour->setEnabled(w.geometry != nullptr);
    }
    QString bit = "-", units = "-", rows = "-", depths = "-";
    if (w.geometry) {
        const io::SectionTable& t = w.geometry->table();
        double smallest = NAN;
        for (double b : t.bitSize_mm)
            if (std::isfinite(b) && !(b >= smallest)) smallest = b;
        bit =
            std::isfinite(smallest)
                ? QString("%1 mm (%2 in)").arg(smallest, 0, 'f', 1).arg(smallest / 25.4, 0, 'f', 3)
                : QString("none in the log");
        if (w.options.read.bitSize_mm) bit += " (given)";
        // As the file wrote them (the table holds metres and millimetres), or as given.
        const auto unitOf = [](const std::string& written, bool given) {
            return given             ? QString("given")
                   : written.empty() ? QString("none written")
                                     : QString::fromStdString(written);
        };
        units = "depth " + unitOf(t.fileDepthUnit, w.options.read.depthUnit.has_value()) +
                ", caliper " + unitOf(t.fileCaliperUnit, w.options.read.radiusUnit.has_value());
        rows = QString::number(t.rowCount());
        if (t.rowCount() > 0)
            depths = QString("%1 - %2")
                         .arg(t.depth_m.front(), 0, 'f', 2)
                         .arg(t.depth_m.back(), 0, 'f', 2);
    }
    item->setText(BitSize, bit);
    item->setText(Units, units);
    item->setText(Rows, rows);
    item->setText(Depths, depths);
    // While it loads, how far: reading the log, then drawing its segments.
    const QString done = QString(" %1%").arg(std::floor(100.0 * w.loadFraction), 0, 'f', 0);
    item->setText(State, !w.error.isEmpty() ? QString("failed")
                         : w.loadFraction >= 1.0
                             ? (w.analysis ? QString("loaded") : QString("analysing"))
                         : w.geometry ? "drawing" + done
                                      : "reading" + done);
    item->setToolTip(State, w.error);
}

}  // namespace caliper3d::app
