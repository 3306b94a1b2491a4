#pragma once

#include <vector>

#include <QDockWidget>
#include <QTimer>

class QTreeWidget;
class QTreeWidgetItem;

namespace caliper3d::app {

class DeskModel;

// The wells shown, the runs of one well grouped under its main run (their depth match in
// their state): each with a box to show or hide it, what its wall is coloured by, its bit
// size and units as read, its rows and depths, and whether it is reading or drawing (with
// the fraction of its load done), analysing, loaded or failed. Clicking a well makes it the current
// one.
class WellsDock : public QDockWidget {
    Q_OBJECT

public:
    explicit WellsDock(DeskModel& model, QWidget* parent = nullptr);
    QTreeWidget* tree() const { return m_tree; }
    // The item of well i (a record of the model): top level, or under its well's main run.
    QTreeWidgetItem* item(int well) const;

    enum Column { Name, Colour, BitSize, Units, Rows, Depths, State, ColumnCount };

signals:
    void visibilityToggled(int well, bool visible);
    void colourChosen(int well, const QString& quantity);

private:
    void rebuild();
    void refresh(int well);
    void addColourChoice(int well);  // well `well`'s "Colour by" box, in its row
    void fill(QTreeWidgetItem* item, int well);

    int wellOf(const QTreeWidgetItem* item) const;

    DeskModel& m_model;
    QTreeWidget* m_tree = nullptr;
    std::vector<QTreeWidgetItem*> m_items;  // by well
    QTimer m_fit;  // the columns fitted to their texts, at most every kFit_ms while rows change
};

}  // namespace caliper3d::app
