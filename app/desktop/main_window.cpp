#include "app/desktop/main_window.h"

#include <QFileInfo>
#include <QGuiApplication>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QScreen>
#include <QStatusBar>

#include <Inventor/SoSceneManager.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include "app/desktop/breakouts_dock.h"
#include "app/desktop/desk_model.h"
#include "app/desktop/file_menu.h"
#include "app/desktop/load_progress_bar.h"
#include "app/desktop/log_track_dock.h"
#include "app/desktop/section_inspector_dock.h"
#include "app/desktop/style_bar.h"
#include "app/desktop/unrolled_image_dock.h"
#include "app/desktop/view_menu.h"
#include "app/desktop/warnings_dock.h"
#include "app/desktop/well_navigator.h"
#include "app/desktop/well_session.h"
#include "app/desktop/well_viewer.h"
#include "app/desktop/wells_dock.h"
#include "scenegraph/camera_setup.h"
#include "scenegraph/colour_legend.h"
#include "scenegraph/render_caching.h"
#include "scenegraph/segment_node_builder.h"
#include "scenegraph/view_overlay.h"

namespace caliper3d::app {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setWindowTitle("caliper3d");
    resize(defaultSize());
    m_model = new DeskModel(this);
    auto* centre = new QWidget(this);
    centre->setMinimumSize(kMinimumViewSize);  // the docks give way before the 3D view does
    setCentralWidget(centre);
    m_viewer = new WellViewer(centre);
    m_viewer->setBackgroundColor(SbColor(scenegraph::kBackgroundColour));
    m_viewer->setTransparencyType(SoGLRenderAction::SORTED_OBJECT_BLEND);
    // Full detail near the camera, built on a worker as the camera moves.
    m_session = new WellSession(
        *m_model,
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
        },
        this);
    m_overlay = std::make_unique<scenegraph::ViewOverlay>();
    m_viewRoot = new SoSeparator;
    m_viewRoot->ref();
    // Notes the GL driver at the first frame: meshes built after it are render-cached on a
    // hardware driver (scenegraph/render_caching.h).
    m_viewRoot->addChild(scenegraph::makeRendererProbe());
    m_viewRoot->addChild(m_session->sceneRoot());
    m_viewRoot->addChild(m_overlay->root());
    m_viewer->setSceneGraph(m_viewRoot);
    m_navigator = new WellNavigator(*m_model, *m_viewer, m_viewRoot, m_session->sceneRoot(), this);
    m_viewer->onClick([this](const SbVec2s& pixel) { pickAt(pixel); });

    m_files = new FileMenu(*this, *m_session, *m_viewer, menuBar()->addMenu("&File"));
    addToolBar(new StyleBar(*m_session, this));
    m_views = new ViewMenu(*this, *m_session, *m_navigator);
    buildStatusBar();
    buildDocks();
    m_files->restoreLayout();  // after the docks: they are found by their objectName

    connect(m_session, &WellSession::status, m_status, &QLabel::setText);
    connect(m_views, &ViewMenu::status, m_status, &QLabel::setText);
    connect(m_views, &ViewMenu::warningsWanted, this, &MainWindow::showWarnings);
    connect(m_session, &WellSession::warningsChanged, this, &MainWindow::updateWarningsButton);
    connect(m_session, &WellSession::wellFailed, this, &MainWindow::showLoadError);
    connect(m_session, &WellSession::lookChanged, this, &MainWindow::updateLook);
    connect(m_model, &DeskModel::wellsChanged, this, &MainWindow::updateTitle);
    // The first segments of a load, then the logs once everything is in (as render frames
    // them; View all shows the paths from the wellheads too).
    connect(m_session, &WellSession::firstSegmentsShown, m_navigator, &WellNavigator::viewAll);
    // A field's load draws its first picture at once, then a frame a quarter second at most.
    auto limitFramesWhileAFieldLoads = [this] {
        if (m_session->loading() && m_session->wellCount() > 1)
            m_viewer->limitFrames(kFieldLoadFrame);
    };
    connect(m_session, &WellSession::firstSegmentsShown, this, limitFramesWhileAFieldLoads);
    connect(m_session, &WellSession::loadStarted, this, [this, limitFramesWhileAFieldLoads] {
        if (m_session->framed()) limitFramesWhileAFieldLoads();
    });
    for (auto ended : {&WellSession::allWellsLoaded, &WellSession::loadCancelled})
        connect(m_session, ended, this, [this] { m_viewer->limitFrames({}); });
    connect(m_session, &WellSession::allWellsLoaded, m_navigator,
            [this] { m_navigator->frameLogs([this] { return m_session->wellScenes(); }); });
    m_labelTimer.setInterval(kLabelPoll_ms);
    connect(&m_labelTimer, &QTimer::timeout, this, &MainWindow::placeLabelsWhenStill);
    m_labelTimer.start();
}

MainWindow::LabelKey MainWindow::labelKey() const {
    const SoCamera* camera = m_viewer->getCamera();
    if (!camera) return {};
    const SbVec2s size = m_viewer->getViewportRegion().getViewportSizePixels();
    const SbVec3f eye = camera->position.getValue();
    const SbVec4f turn = camera->orientation.getValue().getValue();
    const auto* perspective = dynamic_cast<const SoPerspectiveCamera*>(camera);
    return {eye[0],
            eye[1],
            eye[2],
            turn[0],
            turn[1],
            turn[2],
            turn[3],
            perspective ? perspective->heightAngle.getValue() : -1.0,
            static_cast<double>(size[0]),
            static_cast<double>(size[1]),
            static_cast<double>(m_session->annotationGeneration()),
            m_navigator->inside() ? 1.0 : 0.0};
}

bool MainWindow::labelsPlaced() const {
    return m_viewer->getCamera() && labelKey() == m_labelsPlaced;
}

void MainWindow::placeLabelsWhenStill() {
    const SoCamera* camera = m_viewer->getCamera();
    if (!camera || m_session->wellCount() == 0) return;
    const LabelKey key = labelKey();
    const bool resting = key == m_labelsSeen;
    m_labelsSeen = key;
    if (!resting || key == m_labelsPlaced) return;  // moving, or placed for this already
    const SbVec2s size = m_viewer->getViewportRegion().getViewportSizePixels();
    const auto place = [&](const std::string& namesLine) {
        setCaption(namesLine);
        std::vector<scenegraph::ScreenBox> obstacles = m_overlay->occupied(size[1]);
        if (const std::optional<scenegraph::ScreenBox> legend = m_viewer->legendPanel())
            obstacles.push_back(*legend);
        return m_session->placeLabels(*camera, size[0], size[1], !m_navigator->inside(), obstacles);
    };
    m_namesLine = scenegraph::namesLeftOutCaption(
        scenegraph::placeClearOfNamesLine(m_session->wellCount(), place));
    setCaption(m_namesLine);
    m_labelsPlaced = key;
}

MainWindow::~MainWindow() {
    // The workers stop, then the nodes go, before the viewer does.
    delete m_navigator;
    delete m_session;
    m_viewer->setSceneGraph(nullptr);
    m_viewRoot->unref();
    delete m_viewer;
}

void MainWindow::closeEvent(QCloseEvent* event) {
    m_files->saveLayout();
    QMainWindow::closeEvent(event);
}

QSize MainWindow::defaultSize() {
    // Room for the 3D view and the docks around it, within the screen (a saved layout
    // replaces it: FileMenu::restoreLayout).
    const QScreen* screen = QGuiApplication::primaryScreen();
    const QSize available = screen ? screen->availableGeometry().size() : QSize(1600, 1000);
    return QSize(std::min(1600, available.width() * 9 / 10),
                 std::min(1000, available.height() * 9 / 10));
}

SoQtExaminerViewer* MainWindow::viewer() const {
    return m_viewer;
}

QProgressBar* MainWindow::loadProgress() const {
    return m_progress->bar();
}

QString MainWindow::statusText() const {
    return m_status->text();
}

void MainWindow::buildStatusBar() {
    m_status = new QLabel("No well loaded", this);
    statusBar()->addWidget(m_status, 1);
    m_warningsButton = new QPushButton(this);
    m_warningsButton->setFlat(true);
    m_warningsButton->setToolTip("Show the warnings met while loading the wells");
    m_warningsButton->hide();
    connect(m_warningsButton, &QPushButton::clicked, this, &MainWindow::showWarnings);
    statusBar()->addPermanentWidget(m_warningsButton);
    m_progress = new LoadProgressBar(*m_session, this);
    statusBar()->addPermanentWidget(m_progress);
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
    connect(wells, &WellsDock::visibilityToggled, m_session, &WellSession::setWellVisible);
    connect(wells, &WellsDock::colourChosen, this, [this](int well, const QString& quantity) {
        reconstruction::ColourRequest colour;
        colour.quantity = quantity.toStdString();
        m_session->restyleWell(well, colour);
    });
    m_warningsDock = new WarningsDock(*m_model, this);
    tabifyDockWidget(wells, m_warningsDock);
    breakouts->raise();
    for (QDockWidget* dock : std::initializer_list<QDockWidget*>{
             wells, logTrack, inspector, breakouts, unrolled, m_warningsDock})
        m_views->docksMenu()->addAction(dock->toggleViewAction());
}

bool MainWindow::pickAt(const SbVec2s& pixel) {
    const std::optional<WellPick> pick = m_session->pick(
        m_viewer->getSceneManager()->getSceneGraph(), m_viewer->getViewportRegion(), pixel);
    if (!pick) return false;
    m_navigator->showPicked(pick->well, pick->row, pick->azimuth_deg);
    m_status->setText(pick->text);
    return true;
}

void MainWindow::showLoadError(const QString& name, const QString& message) {
    auto* box = new QMessageBox(QMessageBox::Critical, "Could not load " + name, message,
                                QMessageBox::Ok, this);
    box->setObjectName("loadError");
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();  // not modal to the loads still under way
}

void MainWindow::updateWarningsButton() {
    const std::size_t count = m_session->warningCount();
    m_warningsButton->setText(QString("%1 warning%2").arg(count).arg(count == 1 ? "" : "s"));
    m_warningsButton->setVisible(count > 0);
}

void MainWindow::showWarnings() {
    m_warningsDock->show();
    m_warningsDock->raise();
}

void MainWindow::updateTitle() {
    const int count = m_model->wellCount();
    if (count == 1)
        setWindowTitle("caliper3d - " + QFileInfo(m_model->well(0).path).fileName());
    else if (count > 1)
        setWindowTitle(QString("caliper3d - %1 wells").arg(count));
}

std::vector<std::string> MainWindow::caption() const {
    return m_overlay->caption();
}

void MainWindow::setCaption(const std::string& namesLine) {
    // While a field loads its wells may be drawn at two exaggerations (WellSession::
    // drawnExaggerations): the caption says both.
    const std::vector<double> drawn = m_session->drawnExaggerations();
    std::vector<std::string> lines{scenegraph::exaggerationCaption(drawn.back())};
    if (drawn.size() > 1)
        lines.front() = QString("radii x %1 to x %2 while the wells load")
                            .arg(drawn.front())
                            .arg(drawn.back())
                            .toStdString();
    if (!namesLine.empty()) lines.push_back(namesLine);
    m_overlay->setCaption(lines);
}

// The caption says the radial exaggeration the wells are drawn with (and the names the last
// placement left out); the legend what the wall's colours mean.
void MainWindow::updateLook() {
    setCaption(m_namesLine);
    m_viewer->setLegend(m_session->legend());
    // The legend's panel, in the view's lower half, and the depth labels right of the wells
    // beside it (the names are at the top).
    m_navigator->setRightMargin(
        m_session->legend() ? scenegraph::legendWidth_px(*m_session->legend()) + kLabelRoom_px
                            : 0.0f);
}

}  // namespace caliper3d::app
