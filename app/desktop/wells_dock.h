#pragma once

#include <QDockWidget>

class QTreeWidget;
class QTreeWidgetItem;

namespace caliper3d::app {

class DeskModel;

// The wells shown: each with a box to show or hide it, what its wall is coloured by, its bit
// size and units as read, its rows and depths, and whether it is reading or drawing (with
// the fraction of its load done), analysing, loaded or failed. Clicking a well makes it the current
// one.
class WellsDock : public QDockWidget {
    Q_OBJECT

public:
    explicit WellsDock(DeskModel& model, QWidget* parent = nullptr);
    QTreeWidget* tree() const { return m_tree; }

    enum Column { Name, Colour, BitSize, Units, Rows, Depths, State, ColumnCount };

signals:
    void visibilityToggled(int well, bool visible);
    void colourChosen(int well, const QString& quantity);

private:
    void rebuild();
    void refresh(int well);
    void fill(QTreeWidgetItem* item, int well);

    DeskModel& m_model;
    QTreeWidget* m_tree = nullptr;
};

}  // namespace caliper3d::app
