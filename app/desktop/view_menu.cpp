#include "app/desktop/view_menu.h"

#include <QAction>
#include <QActionGroup>
#include <QInputDialog>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>

#include <Inventor/SoDB.h>

#include "app/desktop/desk_model.h"
#include "app/desktop/well_navigator.h"
#include "app/desktop/well_session.h"
#include "scenegraph/camera_setup.h"

namespace caliper3d::app {

ViewMenu::ViewMenu(QMainWindow& window, WellSession& session, WellNavigator& navigator)
    : QObject(&window), m_window(window), m_session(session), m_navigator(navigator) {
    QMenu* view = window.menuBar()->addMenu("&View");
    view->setObjectName("viewMenu");
    view->addAction("Well &warnings...", this, &ViewMenu::warningsWanted);
    view->addSeparator();
    view->addAction(
        "View &all", this, [this] { m_navigator.viewAll(); }, QKeySequence("Ctrl+R"));
    using scenegraph::ViewDirection;
    const std::pair<const char*, ViewDirection> presets[] = {
        {"&Iso", ViewDirection::Iso},
        {"Looking &north", ViewDirection::North},
        {"Looking &east", ViewDirection::East},
        // The window frames whole wells and names them at their wellheads: from the top is
        // render's map.
        {"From &top (map)", ViewDirection::Map}};
    for (const auto& [name, direction] : presets)
        view->addAction(name, this, [this, d = direction] { m_navigator.viewFrom(d); });
    view->addSeparator();
    view->addAction("&Go to depth...", this, &ViewMenu::goToDepth, QKeySequence("Ctrl+G"));
    view->addAction(
        "Ne&xt zone", this,
        [this] {
            if (!m_navigator.nextZone()) emit status("No zone below the current depth");
        },
        QKeySequence("Ctrl+Down"));
    view->addAction(
        "&Previous zone", this,
        [this] {
            if (!m_navigator.previousZone()) emit status("No zone above the current depth");
        },
        QKeySequence("Ctrl+Up"));
    QAction* inside = view->addAction("Inside the &hole");
    inside->setCheckable(true);
    inside->setShortcut(QKeySequence("Ctrl+I"));
    connect(inside, &QAction::toggled, this, [this](bool on) { m_navigator.setInside(on); });
    // View all and the presets bring the camera out: the menu says so.
    connect(&m_navigator, &WellNavigator::insideChanged, inside, &QAction::setChecked);
    QAction* fly = view->addAction("&Fly along the well");
    fly->setCheckable(true);
    fly->setShortcut(QKeySequence("Ctrl+Shift+F"));
    connect(fly, &QAction::toggled, this, [this, inside](bool on) {
        if (on) {
            inside->setChecked(true);
            m_navigator.startFlight(kFlightSpeed_m_s);
        } else {
            m_navigator.stopFlight();
        }
    });
    connect(&m_navigator, &WellNavigator::flightStopped, fly, [fly] { fly->setChecked(false); });
    view->addSeparator();
    buildExaggeration(*view);
    m_docks = view->addMenu("&Docks");
    m_docks->setObjectName("docksMenu");
    buildHelp();
}

void ViewMenu::buildExaggeration(QMenu& view) {
    m_exaggeration = view.addMenu("Radial e&xaggeration");
    m_exaggeration->setObjectName("exaggerationMenu");
    auto* group = new QActionGroup(m_exaggeration);
    for (double factor : kExaggerations) {
        QAction* action = m_exaggeration->addAction(QString("x%1").arg(factor));
        action->setCheckable(true);
        action->setData(factor);
        group->addAction(action);
        connect(action, &QAction::triggered, this, [this, factor] { setExaggeration(factor); });
    }
    m_exaggeration->addSeparator();
    m_otherExaggeration = m_exaggeration->addAction("&Other...");
    m_otherExaggeration->setObjectName("otherExaggeration");
    m_otherExaggeration->setCheckable(true);
    group->addAction(m_otherExaggeration);
    connect(m_otherExaggeration, &QAction::triggered, this, &ViewMenu::askExaggeration);
    connect(&m_session, &WellSession::lookChanged, this, &ViewMenu::showExaggeration);
    showExaggeration();
}

// The menu's title says the factor drawn; its entry is checked (Other, with the factor, when
// it is none of the presets).
void ViewMenu::showExaggeration() {
    const double current = m_session.look().radialExaggeration;
    m_exaggeration->setTitle(QString("Radial e&xaggeration (x%1)").arg(current));
    bool preset = false;
    for (QAction* action : m_exaggeration->actions())
        if (action->isCheckable() && action != m_otherExaggeration) {
            const bool on = action->data().toDouble() == current;
            action->setChecked(on);
            preset = preset || on;
        }
    m_otherExaggeration->setChecked(!preset);
    m_otherExaggeration->setText(preset ? QString("&Other...")
                                        : QString("&Other (x%1)...").arg(current));
}

void ViewMenu::setExaggeration(double factor) {
    if (m_session.wellCount() == 0) {
        emit status("No well loaded");
    } else if (m_session.restyle(factor, m_session.look().colour)) {
        m_session.keepExaggeration();
    }
    showExaggeration();  // the checks say what is drawn, whatever happened
}

void ViewMenu::askExaggeration() {
    bool ok = false;
    const double factor = QInputDialog::getDouble(
        &m_window, "Radial exaggeration",
        "Draw radii this many times larger around the true path (1 to 1000):",
        m_session.look().radialExaggeration, 1.0, 1000.0, 1, &ok);
    if (ok)
        setExaggeration(factor);
    else
        showExaggeration();
}

void ViewMenu::buildHelp() {
    QMenu* help = m_window.menuBar()->addMenu("&Help");
    help->addAction("&Keyboard shortcuts", this, &ViewMenu::showShortcuts,
                    QKeySequence::HelpContents);
    help->addAction("&About caliper3d", this, [this] {
        QMessageBox::about(
            &m_window, "About caliper3d",
            QString("<b>caliper3d 0.1.0</b><p>Caliper logs as true-shape 3D boreholes: pick, "
                    "measure, colour and export them.</p><p>Qt %1, Coin %2, SoQt.</p><p>The user "
                    "guide is docs/user-guide.md; every verb's options: caliper3d help VERB.</p>")
                .arg(qVersion())
                .arg(SoDB::getVersion()));
    });
}

QString ViewMenu::shortcutsTable() const {
    QString rows;
    for (QAction* menu : m_window.menuBar()->actions()) {
        if (!menu->menu()) continue;
        for (QAction* action : menu->menu()->actions())
            if (!action->shortcut().isEmpty())
                rows += QString("<tr><td>%1</td><td>%2</td><td>%3</td></tr>")
                            .arg(menu->text().remove('&'), action->text().remove('&'),
                                 action->shortcut().toString(QKeySequence::NativeText));
    }
    rows +=
        "<tr><td>3D view</td><td>click the wall: its section becomes current</td><td>"
        "left click</td></tr><tr><td>3D view</td><td>turn, pan, zoom</td><td>left, middle "
        "drag, wheel</td></tr><tr><td>Status bar</td><td>cancel loading</td><td>Esc</td></tr>";
    return "<table cellspacing=6><tr><th align=left>Menu</th><th align=left>Action</th>"
           "<th align=left>Keys</th></tr>" +
           rows + "</table>";
}

void ViewMenu::showShortcuts() {
    QMessageBox box(QMessageBox::NoIcon, "Keyboard shortcuts", shortcutsTable(), QMessageBox::Close,
                    &m_window);
    box.setObjectName("shortcuts");
    box.exec();
}

void ViewMenu::goToDepth() {
    const DeskModel& model = m_session.model();
    const DeskWell* well = model.current();
    if (!well || !well->geometry) {
        emit status("No well loaded");
        return;
    }
    const auto& depth = well->geometry->table().depth_m;
    bool ok = false;
    const double md = QInputDialog::getDouble(
        &m_window, "Go to depth", QString("Measured depth of %1 (m):").arg(well->name),
        model.currentDepth_m(), depth.front(), depth.back(), 2, &ok);
    if (ok) m_session.model().setCurrentDepth(md);
}

}  // namespace caliper3d::app
