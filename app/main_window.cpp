#include "app/main_window.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QFileInfo>
#include <QFontDatabase>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>
#include <QVBoxLayout>

#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <optional>

#include <glm/vec3.hpp>

#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include "app/desktop/analysis_job.h"
#include "app/desktop/breakouts_dock.h"
#include "app/desktop/desk_model.h"
#include "app/desktop/log_track_dock.h"
#include "app/scene_assembly.h"
#include "app/well_viewer.h"
#include "reconstruction/load/well_load_pipeline.h"
#include "scenegraph/camera_setup.h"
#include "scenegraph/detail_loader.h"
#include "scenegraph/iv_export.h"
#include "scenegraph/segment_feeder.h"
#include "scenegraph/view_overlay.h"
#include "scenegraph/well_annotations.h"
#include "scenegraph/well_scene.h"

namespace caliper3d::app {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setWindowTitle("caliper3d");
    resize(1200, 800);
    m_model = new DeskModel(this);
    auto* centre = new QWidget(this);
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
    buildMenus();
    buildDocks();
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
    QMenu* file = menuBar()->addMenu("&File");
    file->addAction(
        "&Open well...", this, [this] { openDialog(false); }, QKeySequence::Open);
    file->addAction("&Add well...", this, [this] { openDialog(true); });
    file->addAction("&Export scene (.iv)...", this, &MainWindow::exportDialog);
    file->addSeparator();
    file->addAction("&Quit", this, &QWidget::close, QKeySequence::Quit);
    QMenu* view = menuBar()->addMenu("&View");
    view->addAction("Well &warnings...", this, &MainWindow::showWarnings);
    view->addSeparator();
    view->addAction("View &all", this, [this] { viewAll(); });
    view->addAction("&Iso", this, [this] { setView(int(scenegraph::ViewDirection::Iso)); });
    view->addAction("Looking &north", this,
                    [this] { setView(int(scenegraph::ViewDirection::North)); });
    view->addAction("Looking &east", this,
                    [this] { setView(int(scenegraph::ViewDirection::East)); });
    view->addAction("From &top", this, [this] { setView(int(scenegraph::ViewDirection::Top)); });
    view->addSeparator();
    QMenu* exaggeration = view->addMenu("Radial e&xaggeration");
    for (double factor : {1.0, 10.0, 50.0, 200.0})
        exaggeration->addAction(QString("x%1").arg(factor), this,
                                [this, factor] { setExaggeration(factor); });
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
    std::vector<std::shared_ptr<const reconstruction::WellGeometry>> geometries;
    std::vector<const reconstruction::SectionValues*> values;
    QApplication::setOverrideCursor(Qt::WaitCursor);
    for (const auto& well : m_wells) {
        if (!well->geometry) continue;
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
        if (!well->geometry) continue;
        const std::size_t i = next++;
        well->geometry = std::make_shared<const reconstruction::WellGeometry>(
            well->geometry->restyled(radialExaggeration, colourings[i]));
        auto scene = std::make_unique<scenegraph::WellScene>();
        scene->buildAll(*well->geometry);
        m_sceneRoot->replaceChild(well->scene->root(), scene->root());
        well->scene = std::move(scene);
        well->options.radialExaggeration = radialExaggeration;
        well->options.colour = colour;
        annotate(*well);  // the tick marks stand off the wall as now drawn
        m_detail->addWell(*well->scene, well->geometry);
        publish(*well);
    }
    m_overlay->setCaption({scenegraph::exaggerationCaption(radialExaggeration)});
    m_lastOptions.radialExaggeration = radialExaggeration;
    m_lastOptions.colour = colour;
    m_legend.reset();
    if (!colourings.empty()) m_legend = colourings.front()->legend();
    m_viewer->setLegend(legend());
    fillColourBox();
    QApplication::restoreOverrideCursor();
    m_status->setText(QString("Coloured by %1, radii x%2 (%3 ms, nothing read again)")
                          .arg(QString::fromStdString(colour.quantity))
                          .arg(radialExaggeration)
                          .arg(clock.elapsed()));
    return true;
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

// A plain list for now: file, line and message of every warning kept.
void MainWindow::showWarnings() {
    QDialog dialog(this);
    dialog.setWindowTitle("Well warnings");
    dialog.resize(800, 400);
    auto* list = new QPlainTextEdit(&dialog);
    list->setReadOnly(true);
    list->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    list->setPlainText(warningCount() > 0 ? warningsText() : QString("No warnings."));
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, &dialog);
    connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    auto* layout = new QVBoxLayout(&dialog);
    layout->addWidget(list);
    layout->addWidget(buttons);
    dialog.exec();
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
    m_sceneRoot->addChild(w.scene->root());
    m_wells.push_back(std::move(well));
    m_lastOptions = options;
    {
        DeskWell record;
        record.name = QFileInfo(QString::fromStdString(source.path)).fileName();
        record.path = QString::fromStdString(source.path);
        record.options = options;
        w.modelIndex = m_model->addWell(std::move(record));
    }
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
}

void MainWindow::publish(Well& well) {
    DeskWell record = m_model->well(well.modelIndex);
    if (well.geometry && !well.geometry->table().wellName.empty())
        record.name = QString::fromStdString(well.geometry->table().wellName);
    record.options = well.options;
    record.geometry = well.geometry;
    record.analysis = well.analysis;
    record.diagnostics = well.diagnostics;
    record.error = well.error;
    m_model->updateWell(well.modelIndex, std::move(record));
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
    // The docks are views of m_model; each is a class of its own (app/desktop).
    QMenu* view = nullptr;
    for (QAction* menu : menuBar()->actions())
        if (menu->text() == "&View") view = menu->menu();
    auto* docks = view->findChild<QMenu*>("docksMenu");
    if (!docks) {
        docks = view->addMenu("&Docks");
        docks->setObjectName("docksMenu");
    }
    auto* logTrack = new LogTrackDock(*m_model, this);
    addDockWidget(Qt::LeftDockWidgetArea, logTrack);
    docks->addAction(logTrack->toggleViewAction());
    auto* breakouts = new BreakoutsDock(*m_model, this);
    addDockWidget(Qt::RightDockWidgetArea, breakouts);
    docks->addAction(breakouts->toggleViewAction());
}

void MainWindow::wellDone() {
    if (loading()) return;
    applyStyleAfterLoad();
    viewAll();
    emit allWellsLoaded();
}

void MainWindow::openDialog(bool add) {
    const QString path =
        QFileDialog::getOpenFileName(this, "Open caliper log", QString(),
                                     "Caliper logs (*.txt *.las *.LAS *.csv);;All files (*)");
    if (path.isEmpty()) return;
    if (add)
        addWell(path, m_lastOptions);
    else
        openWell(path, m_lastOptions);
}

void MainWindow::exportDialog() {
    const QString path =
        QFileDialog::getSaveFileName(this, "Export scene", "scene.iv", "Open Inventor (*.iv)");
    if (path.isEmpty()) return;
    try {
        scenegraph::writeIv(m_sceneRoot, path.toStdString());
        m_status->setText("Wrote " + path);
    } catch (const std::exception& e) {
        QMessageBox::warning(this, "Export failed", e.what());
    }
}

void MainWindow::setExaggeration(double factor) {
    restyle(factor, m_lastOptions.colour);
}

void MainWindow::annotate(Well& well) {
    SoSeparator* annotations =
        scenegraph::makeWholeWellAnnotations(*well.geometry, well.options.radialExaggeration);
    if (well.annotations)
        m_sceneRoot->replaceChild(well.annotations, annotations);
    else
        m_sceneRoot->addChild(annotations);
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
