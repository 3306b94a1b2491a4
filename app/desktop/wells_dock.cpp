#include "app/desktop/wells_dock.h"

#include <cmath>

#include <QComboBox>
#include <QFileInfo>
#include <QHeaderView>
#include <QTreeWidget>

#include "app/desktop/desk_model.h"
#include "reconstruction/analysis/wall_colour_request.h"

namespace caliper3d::app {

namespace {
constexpr int kFit_ms = 250;
}  // namespace

WellsDock::WellsDock(DeskModel& model, QWidget* parent)
    : QDockWidget("Wells", parent), m_model(model) {
    setObjectName("wells");
    m_tree = new QTreeWidget(this);
    m_tree->setRootIsDecorated(false);
    // Every row is one line: a change to one well's row then measures that row alone (a field
    // of 100 wells changes rows hundreds of times as it loads, and measuring every row each
    // time was a third of the window's load).
    m_tree->setUniformRowHeights(true);
    m_tree->setColumnCount(ColumnCount);
    m_tree->setHeaderLabels({"Well", "Colour by", "Bit size", "Units", "Rows", "MD (m)", "State"});
    // Fitted to their texts now and then, not on every change: ResizeToContents measured
    // every row's text each time one row changed, most of a 100-well field's load.
    m_fit.setSingleShot(true);
    m_fit.setInterval(kFit_ms);
    connect(&m_fit, &QTimer::timeout, this,
            [this] { m_tree->header()->resizeSections(QHeaderView::ResizeToContents); });
    setWidget(m_tree);
    connect(&model, &DeskModel::wellsChanged, this, &WellsDock::rebuild);
    connect(&model, &DeskModel::wellChanged, this, &WellsDock::refresh);
    connect(&model, &DeskModel::currentChanged, this, [this](int well) {
        if (QTreeWidgetItem* shown = item(well)) m_tree->setCurrentItem(shown);
    });
    connect(m_tree, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item, int column) {
        if (column != Name) return;
        const int well = wellOf(item);
        const bool visible = item->checkState(Name) == Qt::Checked;
        if (well >= 0 && m_model.well(well).visible != visible)
            emit visibilityToggled(well, visible);
    });
    connect(m_tree, &QTreeWidget::itemClicked, this, [this](QTreeWidgetItem* item) {
        const int well = wellOf(item);
        if (well < 0 || well == m_model.currentWell()) return;
        // Another run of the current well opens at the matched depth.
        const double matched =
            m_model.matchedDepth_m(m_model.currentWell(), well, m_model.currentDepth_m());
        m_model.setCurrent(well, std::isfinite(matched) ? matched : m_model.currentDepth_m());
    });
    rebuild();
}

QTreeWidgetItem* WellsDock::item(int well) const {
    return well >= 0 && well < static_cast<int>(m_items.size())
               ? m_items[static_cast<std::size_t>(well)]
               : nullptr;
}

int WellsDock::wellOf(const QTreeWidgetItem* item) const {
    return item ? item->data(Name, Qt::UserRole).toInt() : -1;
}

void WellsDock::rebuild() {
    const QSignalBlocker block(m_tree);
    // A well added at the end that is no other well's run is one row more: the others stay
    // (a field of 100 wells opened one by one rebuilt 5,050 rows, a third of a second before
    // the window showed).
    const int added = m_model.wellCount() - 1;
    if (added >= 0 && static_cast<std::size_t>(added) == m_items.size() &&
        m_model.well(added).runOf < 0) {
        auto* entry = new QTreeWidgetItem;
        entry->setData(Name, Qt::UserRole, added);
        m_items.push_back(entry);
        m_tree->addTopLevelItem(entry);
        addColourChoice(added);
        fill(entry, added);
        if (!m_fit.isActive()) m_fit.start();
        return;
    }
    m_tree->clear();
    m_items.assign(static_cast<std::size_t>(m_model.wellCount()), nullptr);
    bool grouped = false;
    // The items are made outside the tree and put in at once: an item made in the tree lays
    // the whole tree out again, which for a field of a hundred wells, rebuilt as each is
    // added, kept the window from showing for seconds.
    QList<QTreeWidgetItem*> topLevel;
    for (int i = 0; i < m_model.wellCount(); ++i) {
        // A run other than the main one goes under its main run (which comes first).
        const int main = m_model.mainRun(i);
        QTreeWidgetItem* parent = main != i && main < i ? item(main) : nullptr;
        auto* entry = parent ? new QTreeWidgetItem(parent) : new QTreeWidgetItem;
        if (!parent) topLevel.append(entry);
        grouped = grouped || parent != nullptr;
        entry->setData(Name, Qt::UserRole, i);
        m_items[static_cast<std::size_t>(i)] = entry;
    }
    m_tree->addTopLevelItems(topLevel);
    for (int i = 0; i < m_model.wellCount(); ++i) {
        addColourChoice(i);
        fill(item(i), i);
    }
    m_tree->setRootIsDecorated(grouped);
    m_tree->expandAll();
    m_tree->header()->resizeSections(QHeaderView::ResizeToContents);
}

void WellsDock::addColourChoice(int well) {
    auto* colour = new QComboBox(m_tree);
    colour->setObjectName(QString("colourBy%1").arg(well));
    m_tree->setItemWidget(item(well), Colour, colour);
    connect(colour, QOverload<int>::of(&QComboBox::activated), this,
            [this, well, colour](int) { emit colourChosen(well, colour->currentText()); });
}

void WellsDock::refresh(int well) {
    if (!item(well)) return;
    const QSignalBlocker block(m_tree);
    fill(item(well), well);
    if (!m_fit.isActive()) m_fit.start();
}

void WellsDock::fill(QTreeWidgetItem* item, int well) {
    const DeskWell& w = m_model.well(well);
    const std::vector<int> others = m_model.otherRuns(well);
    const bool run = w.runOf >= 0;
    const bool mainRun = run && m_model.mainRun(well) == well;
    // Runs are told apart by their files (one well's runs share its name).
    item->setText(Name, !run ? w.name
                             : QString("%1 (%2 %3)")
                                   .arg(w.name, mainRun ? QString("main run,") : QString("run,"),
                                        QFileInfo(w.path).fileName()));
    item->setToolTip(Name, w.path);
    item->setCheckState(Name, w.visible ? Qt::Checked : Qt::Unchecked);
    auto* colour = qobject_cast<QComboBox*>(m_tree->itemWidget(item, Colour));
    if (colour) {
        const QSignalBlocker block(colour);
        colour->clear();
        if (w.geometry)
            for (const std::string& name : reconstruction::colourQuantities(w.geometry->table()))
                colour->addItem(QString::fromStdString(name));
        if (w.geometry && !others.empty())  // against the main run, or the main's first run
            colour->insertItem(5, reconstruction::kChangeQuantity);
        colour->setCurrentText(QString::fromStdString(w.options.colour.quantity));
        colour->setEnabled(w.geometry != nullptr);
    }
    QString bit = "-", units = "-", rows = "-", depths = "-";
    if (w.geometry) {
        const io::SectionTable& t = w.geometry->table();
        const double smallest = w.smallestBit_mm ? *w.smallestBit_mm : smallestBitSize_mm(t);
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
        rows = QString::number(w.wholeRows > 0 ? w.wholeRows : t.rowCount());
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
    item->setText(State, !w.error.isEmpty()      ? QString("failed")
                         : w.loadFraction >= 1.0 ? (w.makingLean      ? QString("making lean")
                                                    : w.analysis      ? QString("loaded")
                                                    : w.wholeRows > 0 ? QString("held lean")
                                                                      : QString("analysing"))
                         : w.geometry            ? "drawing" + done
                                                 : "reading" + done);
    item->setToolTip(
        State, !w.error.isEmpty() ? w.error
               : w.makingLean ? QString("The field is large: the plan of its coarse meshes and a "
                                        "sample of its rows are being made, and it is not "
                                        "analysed unless it becomes the current well")
               : w.wholeRows > 0 ? QString("A sample of its %1 rows is held (the field is large): "
                                           "it is read whole again, and analysed, when it becomes "
                                           "the current well")
                                       .arg(w.wholeRows)
                                 : QString());
    if (run && !mainRun && w.error.isEmpty() && w.analysis) {
        // Its depth match to the main run (as `caliper3d compare MAIN RUN` finds it).
        if (w.mapping)
            item->setText(State, QString("matched %1 m (%2, correlation %3)")
                                     .arg(w.mapping->shift_m, 0, 'f', 3)
                                     .arg(QString::fromStdString(w.mapping->curve))
                                     .arg(w.mapping->match.correlation, 0, 'f', 3));
        else if (!w.matchError.isEmpty())
            item->setText(State, "not matched");
        item->setToolTip(State, w.matchError);
    }
}

}  // namespace caliper3d::app
