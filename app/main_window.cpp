#include "app/main_window.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QInputDialog>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QScreen>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>

#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <optional>

#include <glm/vec3.hpp>

#include <Inventor/SoDB.h>
#include <Inventor/SoSceneManager.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoSwitch.h>

#include "app/desktop/analysis_job.h"
#include "app/desktop/breakouts_dock.h"
#include "app/desktop/desk_model.h"
#include "app/desktop/file_menu.h"
#include "app/desktop/log_track_dock.h"
#include "app/desktop/retired_loads.h"
#include "app/desktop/section_inspector_dock.h"
#include "app/desktop/unrolled_image_dock.h"
#include "app/desktop/warnings_dock.h"
#include "app/desktop/well_navigator.h"
#include "app/desktop/wells_dock.h"
#include "app/scene_assembly.h"
#include "app/well_viewer.h"
#include "reconstruction/load/well_load_pipeline.h"
#include "scenegraph/camera_setup.h"
#include "scenegraph/detail_loader.h"
#include "scenegraph/section_pick.h"
#include "scenegraph/segment_feeder.h"
#include "scenegraph/view_overlay.h"
#include "scenegraph/well_annotations.h"
#include "scenegraph/well_scene.h"

namespace caliper3d::app {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setWindowTitle("caliper3d");
    resize(defaultSize());
    m_model = new DeskModel(this);
    m_retired = std::make_unique<RetiredLoads>();
    auto* centre = new QWidget(this);
    centre->setMinimumSize(kMinimumViewSize);  // the docks give way before the 3D view does
    setCentralWidget(centre);
    m_viewer = new WellViewer(centre);
    m_viewer->setBackgroundColor(SbColor(scenegraph::kBackgroundColour));
    m_viewer->setTransparencyType(SoGLRenderAction::SORTED_OBJECT_BLEND);
    m_sceneRoot = new SoSeparator;
    m_sceneRoot->ref();
    m_overlay = std::make_unique<scenegraph::ViewOverlay>();
    m_viewRoot = new SoSeparator;
    m_viewRoot->ref();
    m_viewRoot->addChild(m_sceneRoot);
    m_viewRoot->addChild(m_overlay->root());
    m_viewer->setSceneGraph(m_viewRoot);
    m_navigator = new WellNavigator(*m_model, *m_viewer, m_viewRoot, this);
    m_viewer->onClick([this](const SbVec2s& pixel) { pickAt(pixel); });
    // Full detail near the camera, built on a worker as the camera moves.
    m_detail = std::make_unique<scenegraph::DetailLoader>(
        [this]() -> std::optional<scenegraph::DetailView> {
            auto* camera = dynamic_cast<SoPerspectiveCamera*>(m_viewer->getCamera());
            if (!camera) return std::nullopt;
            const SbVec3f eye = camera->position.getValue();
            scenegraph::DetailView view;
            view.eye = glm::vec3(eye[0], eye[1], eye[2]);
            view.lod =
                scenegraph::lodViewFor(m_viewer->getViewportRegion().getViewportSizePixels()[1],
                                       camera->heightAngle.getValue());
            return view;
        });
    m_status = new QLabel("No well loaded", this);
    statusBar()->addWidget(m_status, 1);
    m_warningsButton = new QPushButton(this);
    m_warningsButton->setFlat(true);
    m_warningsButton->setToolTip("Show the warnings met while loading the wells");
    m_warningsButton->hide();
    connect(m_warningsButton, &QPushButton::clicked, this, &MainWindow::showWarnings);
    statusBar()->addPermanentWidget(m_warningsButton);
    buildProgress();
    buildMenus();
    buildViewMenu();
    buildDocks();
    m_files->restoreLayout();  // after the docks: they are found by their objectName
}

void MainWindow::closeEvent(QCloseEvent* event) {
    m_files->saveLayout();
    QMainWindow::closeEvent(event);
}

std::vector<WellSource> MainWindow::wellSources() const {
    std::vector<WellSource> out;
    for (const auto& well : m_wells) out.push_back(well->source);
    return out;
}

QSize MainWindow::defaultSize() {
    // Room for the 3D view and the docks around it, within the screen (a saved layout
    // replaces it: FileMenu::restoreLayout).
    const QScreen* screen = QGuiApplication::primaryScreen();
    const QSize available = screen ? screen->availableGeometry().size() : QSize(1600, 1000);
    return QSize(std::min(1600, available.width() * 9 / 10),
                 std::min(1000, available.height() * 9 / 10));
}

MainWindow::~MainWindow() {
    // Stop the workers before the nodes and the viewer go.
    m_detail.reset();
    m_wells.clear();
    m_viewer->setSceneGraph(nullptr);
    m_viewRoot->unref();
    m_sceneRoot->unref();
    delete m_viewer;
}

void MainWindow::buildMenus() {
    m_files = new FileMenu(*this, menuBar()->addMenu("&File"));
    QToolBar* style = addToolBar("Style");
    style->setObjectName("style");
    style->addWidget(new QLabel(" Colour by ", style));
    m_colourBox = new QComboBox(style);
    m_colourBox->setObjectName("colourBy");
    m_colourBox->setToolTip("What the wall's colours show (the legend says how)");
    style->addWidget(m_colourBox);
    fillColourBox();
    connect(m_colourBox, QOverload<int>::of(&QComboBox::activated), this,
            &MainWindow::colourByChosen);
}

void MainWindow::buildViewMenu() {
    QMenu* view = menuBar()->addMenu("&View");
    view->setObjectName("viewMenu");
    view->addAction("Well &warnings...", this, &MainWindow::showWarnings);
    view->addSeparator();
    view->addAction(
        "View &all", this, [this] { viewAll(); }, QKeySequence("Ctrl+R"));
    view->addAction("&Iso", this, [this] { setView(int(scenegraph::ViewDirection::Iso)); });
    view->addAction("Looking &north", this,
                    [this] { setView(int(scenegraph::ViewDirection::North)); });
    view->addAction("Looking &east", this,
                    [this] { setView(int(scenegraph::ViewDirection::East)); });
    view->addAction("From &top", this, [this] { setView(int(scenegraph::ViewDirection::Top)); });
    view->addSeparator();
    view->addAction("&Go to depth...", this, &MainWindow::goToDepthDialog, QKeySequence("Ctrl+G"));
    view->addAction(
        "Ne&xt zone", this,
        [this] {
            if (!m_navigator->nextZone()) m_status->setText("No zone below the current depth");
        },
        QKeySequence("Ctrl+Down"));
    view->addAction(
        "&Previous zone", this,
        [this] {
            if (!m_navigator->previousZone()) m_status->setText("No zone above the current depth");
        },
        QKeySequence("Ctrl+Up"));
    QAction* inside = view->addAction("Inside the &hole");
    inside->setCheckable(true);
    inside->setShortcut(QKeySequence("Ctrl+I"));
    connect(inside, &QAction::toggled, this, [this](bool on) { m_navigator->setInside(on); });
    QAction* fly = view->addAction("&Fly along the well");
    fly->setCheckable(true);
    fly->setShortcut(QKeySequence("Ctrl+Shift+F"));
    connect(fly, &QAction::toggled, this, [this, inside](bool on) {
        if (on) {
            inside->setChecked(true);
            m_navigator->startFlight(kFlightSpeed_m_s);
        } else {
            m_navigator->stopFlight();
        }
    });
    connect(m_navigator, &WellNavigator::flightStopped, fly, [fly] { fly->setChecked(false); });
    view->addSeparator();
    QMenu* exaggeration = view->addMenu("Radial e&xaggeration");
    for (double factor : {1.0, 10.0, 50.0, 200.0})
        exaggeration->addAction(QString("x%1").arg(factor), this,
                                [this, factor] { setExaggeration(factor); });
    m_docksMenu = view->addMenu("&Docks");
    m_docksMenu->setObjectName("docksMenu");
    QMenu* help = menuBar()->addMenu("&Help");
    help->addAction("&Keyboard shortcuts", this, &MainWindow::showShortcuts,
                    QKeySequence::HelpContents);
    help->addAction("&About caliper3d", this, [this] {
        QMessageBox::about(
            this, "About caliper3d",
            QString("<b>caliper3d 0.1.0</b><p>Caliper logs as true-shape 3D boreholes: pick, "
                    "measure, colour and export them.</p><p>Qt %1, Coin %2, SoQt.</p><p>The user "
                    "guide is docs/user-guide.md; every verb's options: caliper3d help VERB.</p>")
                .arg(qVersion())
                .arg(SoDB::getVersion()));
    });
}

// Every menu action with a shortcut, as the menus show them: what a new user looks for.
void MainWindow::showShortcuts() {
    QString rows;
    for (QAction* menu : menuBar()->actions()) {
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
    QMessageBox box(QMessageBox::NoIcon, "Keyboard shortcuts",
                    "<table cellspacing=6><tr><th align=left>Menu</th><th align=left>Action</th>"
                    "<th align=left>Keys</th></tr>" +
                        rows + "</table>",
                    QMessageBox::Close, this);
    box.setObjectName("shortcuts");
    box.exec();
}

void MainWindow::goToDepthDialog() {
    const DeskWell* well = m_model->current();
    if (!well || !well->geometry) {
        m_status->setText("No well loaded");
        return;
    }
    const auto& depth = well->geometry->table().depth_m;
    bool ok = false;
    const double md = QInputDialog::getDouble(
        this, "Go to depth", QString("Measured depth of %1 (m):").arg(well->name),
        m_model->currentDepth_m(), depth.front(), depth.back(), 2, &ok);
    if (ok) m_model->setCurrentDepth(md);
}

void MainWindow::fillColourBox() {
    const QSignalBlocker block(m_colourBox);
    m_colourBox->clear();
    std::vector<std::string> names{"departure", "diameter", "ellipticity", "class", "dls"};
    for (const auto& well : m_wells)
        if (well->geometry) {
            names = reconstruction::colourQuantities(well->geometry->table());
            break;
        }
    for (const std::string& name : names) m_colourBox->addItem(QString::fromStdString(name));
    const int current = m_colourBox->findText(QString::fromStdString(m_lastOptions.colour.quantity),
                                              Qt::MatchFixedString);
    m_colourBox->setCurrentIndex(std::max(current, 0));
}

void MainWindow::colourByChosen(int index) {
    reconstruction::ColourRequest colour;
    colour.quantity = m_colourBox->itemText(index).toStdString();
    if (!restyle(m_lastOptions.radialExaggeration, colour)) fillColourBox();
}

SoQtExaminerViewer* MainWindow::viewer() const {
    return m_viewer;
}

std::shared_ptr<const reconstruction::WellGeometry> MainWindow::geometry(std::size_t i) const {
    return i < m_wells.size() ? m_wells[i]->geometry : nullptr;
}

const reconstruction::ColourLegend* MainWindow::legend() const {
    return m_legend ? &*m_legend : nullptr;
}

bool MainWindow::restyle(double radialExaggeration, const reconstruction::ColourRequest& colour) {
    if (!restyleWells(radialExaggeration, colour, -1)) return false;
    m_lastOptions.radialExaggeration = radialExaggeration;
    m_lastOptions.colour = colour;
    fillColourBox();
    return true;
}

bool MainWindow::restyleWell(int well, const reconstruction::ColourRequest& colour) {
    const auto it = wellOf(well);
    if (it == m_wells.end()) return false;
    return restyleWells((*it)->options.radialExaggeration, colour, well);
}

bool MainWindow::restyleWells(double radialExaggeration,
                              const reconstruction::ColourRequest& colour, int only) {
    if (m_wells.empty()) return false;
    if (loading()) {
        m_status->setText("Wait for the wells to load before changing how they are drawn");
        return false;
    }
    QElapsedTimer clock;
    clock.start();
    static const std::vector<std::string> analysed{"diameter", "ellipticity", "class"};
    const bool needsValues =
        std::find(analysed.begin(), analysed.end(), colour.quantity) != analysed.end();
    const auto chosen = [only](const Well& well) {
        return well.geometry && (only < 0 || well.modelIndex == only);
    };
    std::vector<std::shared_ptr<const reconstruction::WellGeometry>> geometries;
    std::vector<const reconstruction::SectionValues*> values;
    QApplication::setOverrideCursor(Qt::WaitCursor);
    for (const auto& well : m_wells) {
        if (!chosen(*well)) continue;
        if (needsValues && !well->values)
            well->values = std::make_shared<const reconstruction::SectionValues>(
                well->analysis ? reconstruction::sectionValues(*well->analysis)
                               : reconstruction::sectionValues(*well->geometry));
        geometries.push_back(well->geometry);
        values.push_back(well->values.get());
    }
    std::vector<std::shared_ptr<const reconstruction::WallColouring>> colourings;
    try {
        colourings = wallColourings(geometries, colour, values);
    } catch (const std::exception& e) {
        QApplication::restoreOverrideCursor();
        m_status->setText(QString::fromStdString(e.what()));
        return false;
    }
    m_detail->removeAll();
    std::size_t next = 0;
    for (auto& well : m_wells) {
        if (!chosen(*well)) {
            if (well->geometry) m_detail->addWell(*well->scene, well->geometry);
            continue;
        }
        const std::size_t i = next++;
        well->geometry = std::make_shared<const reconstruction::WellGeometry>(
            well->geometry->restyled(radialExaggeration, colourings[i]));
        auto scene = std::make_unique<scenegraph::WellScene>();
        scene->buildAll(*well->geometry);
        well->shown->replaceChild(well->scene->root(), scene->root());
        well->scene = std::move(scene);
        well->options.radialExaggeration = radialExaggeration;
        well->options.colour = colour;
        annotate(*well);  // the tick marks stand off the wall as now drawn
        m_detail->addWell(*well->scene, well->geometry);
        publish(*well);
    }
    m_overlay->setCaption({scenegraph::exaggerationCaption(radialExaggeration)});
    m_legend.reset();
    if (!colourings.empty()) m_legend = colourings.front()->legend();
    m_viewer->setLegend(legend());
    QApplication::restoreOverrideCursor();
    m_status->setText(QString("Coloured by %1, radii x%2 (%3 ms, nothing read again)")
                          .arg(QString::fromStdString(colour.quantity))
                          .arg(radialExaggeration)
                          .arg(clock.elapsed()));
    return true;
}

std::vector<std::unique_ptr<MainWindow::Well>>::iterator MainWindow::wellOf(int modelIndex) {
    return std::find_if(m_wells.begin(), m_wells.end(),
                        [modelIndex](const auto& w) { return w->modelIndex == modelIndex; });
}

void MainWindow::setWellVisible(int well, bool visible) {
    const auto it = wellOf(well);
    if (it == m_wells.end()) return;
    (*it)->shown->whichChild = visible ? SO_SWITCH_ALL : SO_SWITCH_NONE;
    m_model->setVisible(well, visible);
}

void MainWindow::applyStyleAfterLoad() {
    std::vector<std::shared_ptr<const reconstruction::WellGeometry>> geometries;
    for (const auto& well : m_wells)
        if (well->geometry) geometries.push_back(well->geometry);
    if (geometries.empty()) return;
    const reconstruction::ColourRequest& colour = m_lastOptions.colour;
    bool rebuild = colour.quantity != "departure" || colour.range.has_value();
    for (const auto& g : geometries) {
        bool anyBit = false;
        for (std::size_t row = 0; row < g->table().rowCount() && !anyBit; ++row)
            anyBit = std::isfinite(g->bitRadius_mm(row));
        rebuild = rebuild || !anyBit;
    }
    const QString status = m_status->text();
    if (rebuild && restyle(m_lastOptions.radialExaggeration, colour)) {
        m_status->setText(status);
        return;
    }
    // The streamed segments are coloured as asked already: only the legend is new.
    try {
        m_legend = wallColourings({geometries.front()}, colour).front()->legend();
    } catch (const std::exception& e) {
        m_status->setText(QString::fromStdString(e.what()));
        m_legend.reset();
    }
    m_viewer->setLegend(legend());
    fillColourBox();
}

bool MainWindow::loading() const {
    for (const auto& well : m_wells)
        if (!well->done) return true;
    return false;
}

std::size_t MainWindow::warningCount() const {
    std::size_t count = 0;
    for (const auto& well : m_wells) count += well->diagnostics.warningCount;
    return count;
}

QString MainWindow::warningsText() const {
    QString text;
    for (const auto& well : m_wells)
        text += QString::fromStdString(formatWarnings(well->diagnostics));
    return text;
}

QString MainWindow::statusText() const {
    return m_status->text();
}

void MainWindow::updateWarningsButton() {
    const std::size_t count = warningCount();
    m_warningsButton->setText(QString("%1 warning%2").arg(count).arg(count == 1 ? "" : "s"));
    m_warningsButton->setVisible(count > 0);
}

void MainWindow::showWarnings() {
    m_warningsDock->show();
    m_warningsDock->raise();
}

void MainWindow::openWell(const QString& path, const LoadOptions& options) {
    openWell(WellSource{path.toStdString(), {}, {}}, options);
}

void MainWindow::openWell(const WellSource& source, const LoadOptions& options) {
    m_detail->removeAll();
    m_wells.clear();
    m_model->clearWells();
    m_sceneRoot->removeAllChildren();
    updateWarningsButton();
    m_viewedAll = false;
    m_origin = reconstruction::sceneOrigin({source});
    addWell(source, options);
}

void MainWindow::addWell(const QString& path, const LoadOptions& options) {
    addWell(WellSource{path.toStdString(), {}, {}}, options);
}

void MainWindow::addWell(const WellSource& source, const LoadOptions& options) {
    auto well = std::make_unique<Well>();
    Well& w = *well;
    w.source = source;
    w.options = options;
    w.scene = std::make_unique<scenegraph::WellScene>();
    w.shown = new SoSwitch;
    w.shown->whichChild = SO_SWITCH_ALL;
    w.shown->addChild(w.scene->root());
    m_sceneRoot->addChild(w.shown);
    m_wells.push_back(std::move(well));
    m_lastOptions = options;
    w.modelIndex = m_model->addWell(record(w));
    m_overlay->setCaption({scenegraph::exaggerationCaption(options.radialExaggeration)});

    const std::string file = source.path;
    const QString name = QFileInfo(QString::fromStdString(file)).fileName();
    // Survey, log and geometry are all read on the worker (loadWell).
    w.pipeline = std::make_unique<reconstruction::WellLoadPipeline>(source, options, m_origin);
    m_status->setText("Loading " + name + "...");
    setWindowTitle(m_wells.size() == 1 ? "caliper3d - " + name
                                       : QString("caliper3d - %1 wells").arg(m_wells.size()));
    scenegraph::SegmentFeeder::Callbacks callbacks;
    callbacks.geometry = [this, &w](std::shared_ptr<const reconstruction::WellGeometry> g) {
        w.geometry = g;
        annotate(w);
        m_detail->addWell(*w.scene, std::move(g));
        publish(w);
    };
    callbacks.warnings = [this, &w](const io::Diagnostics& diagnostics) {
        w.diagnostics = diagnostics;
        updateWarningsButton();
        publish(w);
    };
    callbacks.progress = [this, name](std::size_t attached) {
        if (!m_viewedAll) {
            viewAll();
            m_viewedAll = true;
        }
        m_status->setText(QString("Loading %1: %2 segments").arg(name).arg(attached));
    };
    callbacks.finished = [this, name, &w](std::size_t segments) {
        m_status->setText(
            QString("%1: %2 segments, %3 triangles at full detail, radii x%4, %5 warning%6")
                .arg(name)
                .arg(segments)
                .arg(w.scene->fullDetailTriangles())
                .arg(w.options.radialExaggeration)
                .arg(w.diagnostics.warningCount)
                .arg(w.diagnostics.warningCount == 1 ? "" : "s"));
        w.done = true;
        analyse(w);
        // Signalled from the event loop, not from inside the feeder's tick, so a
        // slot may open other wells (destroying this feeder) safely.
        QMetaObject::invokeMethod(
            this,
            [this, segments] {
                emit wellLoaded(static_cast<int>(segments));
                wellDone();
            },
            Qt::QueuedConnection);
    };
    callbacks.failed = [this, name, &w](const std::string& message) {
        m_status->setText(name + ": failed: " + QString::fromStdString(message));
        w.done = true;
        w.error = QString::fromStdString(message);
        publish(w);
        showLoadError(name, w.error);
        QMetaObject::invokeMethod(
            this,
            [this, message] {
                emit wellFailed(QString::fromStdString(message));
                wellDone();
            },
            Qt::QueuedConnection);
    };
    w.feeder = std::make_unique<scenegraph::SegmentFeeder>(*w.pipeline, *w.scene, callbacks);
    w.pipeline->start();
    m_progressTimer->start();
    updateProgress();
}

DeskWell MainWindow::record(const Well& well) const {
    DeskWell record;
    record.path = QString::fromStdString(well.source.path);
    record.name = QFileInfo(record.path).fileName();
    if (well.geometry && !well.geometry->table().wellName.empty())
        record.name = QString::fromStdString(well.geometry->table().wellName);
    record.options = well.options;
    record.geometry = well.geometry;
    record.analysis = well.analysis;
    record.diagnostics = well.diagnostics;
    record.error = well.error;
    record.visible = well.shown->whichChild.getValue() != SO_SWITCH_NONE;
    return record;
}

void MainWindow::publish(Well& well) {
    m_model->updateWell(well.modelIndex, record(well));
}

void MainWindow::buildProgress() {
    m_progress = new QProgressBar(this);
    m_progress->setRange(0, kProgressSteps);
    m_progress->setMaximumWidth(260);
    m_progress->setTextVisible(true);
    m_progress->hide();
    m_cancelButton = new QToolButton(this);
    m_cancelButton->setText("Cancel");
    m_cancelButton->setToolTip("Stop loading (Esc); the wells not loaded yet are removed");
    m_cancelButton->setShortcut(QKeySequence(Qt::Key_Escape));
    m_cancelButton->hide();
    connect(m_cancelButton, &QToolButton::clicked, this, &MainWindow::cancelLoading);
    statusBar()->addPermanentWidget(m_progress);
    statusBar()->addPermanentWidget(m_cancelButton);
    m_progressTimer = new QTimer(this);
    m_progressTimer->setInterval(kProgressInterval_ms);
    connect(m_progressTimer, &QTimer::timeout, this, &MainWindow::updateProgress);
}

// Reading is the first 70 % of a well's bar (the fraction of the log read), drawing the rest
// (the segments attached over the well's segments); the bar is the mean over loading wells.
void MainWindow::updateProgress() {
    double sum = 0.0;
    int count = 0;
    QString what;
    for (const auto& well : m_wells) {
        if (well->done || !well->pipeline) continue;
        ++count;
        const QString name = QFileInfo(QString::fromStdString(well->source.path)).fileName();
        if (!well->geometry) {
            sum += kReadShare * well->pipeline->readFraction();
            what = "Reading " + name;
        } else {
            const double segments = std::max<double>(1.0, double(well->geometry->segmentCount()));
            sum += kReadShare +
                   (1.0 - kReadShare) * std::min(1.0, double(well->feeder->attached()) / segments);
            what = "Drawing " + name;
        }
    }
    const bool busy = count > 0;
    m_progress->setVisible(busy);
    m_cancelButton->setVisible(busy);
    if (!busy) {
        m_progressTimer->stop();
        return;
    }
    if (count > 1) what = QString("Loading %1 wells").arg(count);
    m_progress->setValue(static_cast<int>(kProgressSteps * sum / count));
    m_progress->setFormat(what + " %p%");
}

void MainWindow::cancelLoading() {
    std::size_t stopped = 0;
    for (auto& well : m_wells)
        if (!well->done && well->pipeline) {
            well->pipeline->cancel();
            ++stopped;
        }
    if (stopped == 0) return;
    m_detail->removeAll();
    std::vector<std::unique_ptr<Well>> kept;
    for (auto& well : m_wells) {
        if (well->done) {
            kept.push_back(std::move(well));
            continue;
        }
        m_sceneRoot->removeChild(well->shown);
        well->feeder.reset();                          // its sensor, on this thread
        m_retired->retire(std::move(well->pipeline));  // joined off this thread
        well.reset();
    }
    m_wells = std::move(kept);
    m_model->clearWells();
    for (auto& well : m_wells) {
        well->modelIndex = m_model->addWell(record(*well));
        if (well->geometry) m_detail->addWell(*well->scene, well->geometry);
    }
    updateProgress();
    updateWarningsButton();
    m_status->setText(QString("Loading cancelled: %1 well%2 not loaded")
                          .arg(stopped)
                          .arg(stopped == 1 ? "" : "s"));
    emit loadCancelled();
}

int MainWindow::retiredLoadsRunning() const {
    return m_retired->running();
}

void MainWindow::showLoadError(const QString& name, const QString& message) {
    auto* box = new QMessageBox(QMessageBox::Critical, "Could not load " + name, message,
                                QMessageBox::Ok, this);
    box->setObjectName("loadError");
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();  // not modal to the loads still under way
}

bool MainWindow::pickAt(const SbVec2s& pixel) {
    std::vector<scenegraph::PickableWell> wells;
    std::vector<int> index;
    for (const auto& well : m_wells)
        if (well->geometry && well->analysis &&
            well->shown->whichChild.getValue() != SO_SWITCH_NONE) {
            wells.push_back({well->scene.get(), well->geometry.get(), well->analysis.get(),
                             m_model->well(well->modelIndex).name.toStdString()});
            index.push_back(well->modelIndex);
        }
    if (wells.empty()) return false;
    const std::optional<scenegraph::SectionPick> pick = scenegraph::pickSection(
        m_viewer->getSceneManager()->getSceneGraph(), m_viewer->getViewportRegion(), pixel, wells);
    if (!pick) return false;
    const int well = index[pick->well];
    if (well != m_model->currentWell() || pick->wall.row != m_model->currentRow())
        m_navigator->holdCameraOnce();  // the user looks where they clicked: stay
    m_model->setCurrentRow(well, pick->wall.row);
    m_model->setCurrentAzimuth(pick->wall.azimuth_deg);
    m_status->setText(QString("%1 at %2 m MD: radius %3 mm at azimuth %4")
                          .arg(QString::fromStdString(pick->wellName))
                          .arg(pick->section.md_m, 0, 'f', 2)
                          .arg(pick->wall.radius_mm, 0, 'f', 1)
                          .arg(pick->wall.azimuth_deg, 0, 'f', 0));
    return true;
}

void MainWindow::analyse(Well& well) {
    if (!well.geometry) return;
    reconstruction::AnalysisOptions options;
    options.rules.minValidArmFraction = well.options.minValidArmFraction;
    options.threads = 2;
    well.analysisJob = std::make_unique<AnalysisJob>(
        this, well.geometry, options,
        [this, &well](std::shared_ptr<const reconstruction::WellAnalysis> analysis) {
            well.analysis = std::move(analysis);
            publish(well);
            emit wellAnalysed(well.modelIndex);
        });
}

void MainWindow::buildDocks() {
    // The docks are views of m_model; each is a class of its own (app/desktop). Left, side
    // by side as on a log print: the log track and the unrolled image, both with depth down;
    // right: the section above the breakouts, with the wells and the warnings in tabs beside
    // the breakouts (the 3D view keeps the window's whole height).
    auto* logTrack = new LogTrackDock(*m_model, this);
    addDockWidget(Qt::LeftDockWidgetArea, logTrack);
    auto* unrolled = new UnrolledImageDock(m_model, this);
    splitDockWidget(logTrack, unrolled, Qt::Horizontal);
    auto* inspector = new SectionInspectorDock(m_model, this);
    addDockWidget(Qt::RightDockWidgetArea, inspector);
    auto* breakouts = new BreakoutsDock(*m_model, this);
    addDockWidget(Qt::RightDockWidgetArea, breakouts);
    auto* wells = new WellsDock(*m_model, this);
    tabifyDockWidget(breakouts, wells);
    connect(wells, &WellsDock::visibilityToggled, this, &MainWindow::setWellVisible);
    connect(wells, &WellsDock::colourChosen, this, [this](int well, const QString& quantity) {
        reconstruction::ColourRequest colour;
        colour.quantity = quantity.toStdString();
        restyleWell(well, colour);
    });
    m_warningsDock = new WarningsDock(*m_model, this);
    tabifyDockWidget(wells, m_warningsDock);
    breakouts->raise();
    for (QDockWidget* dock : std::initializer_list<QDockWidget*>{
             wells, logTrack, inspector, breakouts, unrolled, m_warningsDock})
        m_docksMenu->addAction(dock->toggleViewAction());
}

void MainWindow::wellDone() {
    if (loading()) return;
    applyStyleAfterLoad();
    viewAll();
    emit allWellsLoaded();
}

// Through the Open dialog: the file's own options, only the look taken from the wells shown.
void MainWindow::openDialog(bool add) {
    m_files->openDialog(add);
}

// On a child process (ExportJob): the window stays responsive, the graph is not touched.
void MainWindow::exportDialog() {
    m_files->exportDialog();
}

void MainWindow::setExaggeration(double factor) {
    restyle(factor, m_lastOptions.colour);
}

void MainWindow::annotate(Well& well) {
    SoSeparator* annotations =
        scenegraph::makeWholeWellAnnotations(*well.geometry, well.options.radialExaggeration);
    if (well.annotations)
        well.shown->replaceChild(well.annotations, annotations);
    else
        well.shown->addChild(annotations);
    well.annotations = annotations;
}

void MainWindow::viewAll() {
    SoCamera* camera = m_viewer->getCamera();
    if (!camera) return;
    camera->viewAll(m_sceneRoot, m_viewer->getViewportRegion());
    // SoCamera::viewAll puts the ends of a long well on the window's edges, a vertical
    // well's wellhead and its name half outside: back off along the view.
    SbVec3f look;
    camera->orientation.getValue().multVec(SbVec3f(0.0f, 0.0f, -1.0f), look);
    const float distance = camera->focalDistance.getValue();
    const SbVec3f focus = camera->position.getValue() + look * distance;
    camera->position = focus - look * (distance * kViewAllRoom);
    camera->focalDistance = distance * kViewAllRoom;
}

void MainWindow::setView(int direction) {
    SoCamera* camera = m_viewer->getCamera();
    if (!camera) return;
    SoGetBoundingBoxAction bbox(m_viewer->getViewportRegion());
    bbox.apply(m_sceneRoot);
    if (bbox.getBoundingBox().isEmpty()) return;
    scenegraph::aimCamera(camera, static_cast<scenegraph::ViewDirection>(direction),
                          bbox.getBoundingBox().getCenter());
    viewAll();
}

}  // namespace caliper3d::app
