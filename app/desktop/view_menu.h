#pragma once

#include <QObject>
#include <QString>

class QAction;
class QMainWindow;
class QMenu;

namespace caliper3d::app {

class WellNavigator;
class WellSession;

// The window's View and Help menus, a command each (FreeCAD's CommandView): framing and the
// view presets, Go to depth, the next and previous zone, inside the hole and the flight,
// the radial exaggeration, a toggle per dock, the keyboard shortcuts (read from the menu
// bar) and About. It adds them to `window`'s menu bar and uses the window as the dialogs'
// parent only.
class ViewMenu : public QObject {
    Q_OBJECT

public:
    ViewMenu(QMainWindow& window, WellSession& session, WellNavigator& navigator);

    // View > Docks: the window adds a toggle per dock.
    QMenu* docksMenu() const { return m_docks; }
    // Help > Keyboard shortcuts: every menu action with a shortcut, as the menus show them.
    QString shortcutsTable() const;

signals:
    void status(const QString& text);
    void warningsWanted();  // View > Well warnings

private:
    void goToDepth();
    void showShortcuts();
    void buildHelp();
    void buildExaggeration(QMenu& view);
    void showExaggeration();
    void setExaggeration(double factor);
    void askExaggeration();  // a dialog: any factor --exaggerate takes

    static constexpr double kFlightSpeed_m_s = 5.0;  // fly along: the current depth per second
    QMainWindow& m_window;
    WellSession& m_session;
    WellNavigator& m_navigator;
    QMenu* m_docks = nullptr;
    QMenu* m_exaggeration = nullptr;
    QAction* m_otherExaggeration = nullptr;
    static constexpr double kExaggerations[] = {1.0, 10.0, 50.0, 200.0};
};

}  // namespace caliper3d::app
