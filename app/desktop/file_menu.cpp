#include "app/desktop/file_menu.h"

#include <QCoreApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGLWidget>
#include <QMainWindow>
#include <QMenu>
#include <QMessageBox>
#include <QProgressDialog>
#include <QSpinBox>
#include <QStatusBar>
#include <QTimer>

#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>

#include "app/desktop/desk_model.h"
#include "app/desktop/export_job.h"
#include "app/desktop/file_drop.h"
#include "app/desktop/open_well_dialog.h"
#include "app/desktop/picture_renderer.h"
#include "app/desktop/report_job.h"
#include "app/desktop/well_session.h"
#include "scenegraph/picture/png_file.h"

namespace caliper3d::app {

namespace {

constexpr int kStatus_ms = 10000;

const char* const kExportFilters =
    "Open Inventor (*.iv);;Open Inventor, gzip (*.iv.gz);;glTF binary (*.glb);;PLY (*.ply);;"
    "STL (*.stl);;Wavefront OBJ (*.obj)";

// The name as typed, or with the chosen filter's extension when it has none of ours.
QString withExtension(const QString& path, const QString& filter) {
    for (const char* ext : {".iv", ".iv.gz", ".glb", ".ply", ".stl", ".obj"})
        if (path.endsWith(ext, Qt::CaseInsensitive)) return path;
    const int star = filter.indexOf("*.");
    const int close = filter.indexOf(')', star);
    return star < 0 ? path + ".iv" : path + filter.mid(star + 1, close - star - 1);
}

// The picture's size, starting from the view's; nullopt when cancelled.
std::optional<QSize> askPictureSize(QWidget* parent, QSize initial) {
    QDialog dialog(parent);
    dialog.setWindowTitle("Picture size");
    auto* form = new QFormLayout(&dialog);
    auto* width = new QSpinBox(&dialog);
    auto* height = new QSpinBox(&dialog);
    for (QSpinBox* box : {width, height}) {
        box->setRange(16, 8192);
        box->setSuffix(" px");
    }
    width->setValue(initial.width());
    height->setValue(initial.height());
    form->addRow("Width", width);
    form->addRow("Height", height);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
    QObject::connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    QObject::connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    form->addRow(buttons);
    if (dialog.exec() != QDialog::Accepted) return std::nullopt;
    return QSize(width->value(), height->value());
}

}  // namespace

FileMenu::FileMenu(QMainWindow& window, WellSession& session, SoQtExaminerViewer& viewer,
                   QMenu* menu)
    : QObject(&window),
      m_window(window),
      m_session(session),
      m_viewer(viewer),
      m_program(QCoreApplication::applicationFilePath()) {
    menu->addAction(
        "&Open well...", this, [this] { openDialog(false); }, QKeySequence::Open);
    menu->addAction("&Add well...", this, [this] { openDialog(true); });
    m_recent = menu->addMenu("Open &recent");
    fillRecent();
    menu->addSeparator();
    menu->addAction("&Export scene...", this, &FileMenu::exportDialog, QKeySequence("Ctrl+E"));
    menu->addAction("Save &picture...", this, &FileMenu::savePicture, QKeySequence("Ctrl+Shift+P"));
    menu->addAction("Save &report...", this, &FileMenu::saveReport);
    menu->addSeparator();
    menu->addAction("&Quit", &window, &QWidget::close, QKeySequence::Quit);
    window.setAcceptDrops(true);
    window.installEventFilter(
        new FileDrop(this, [this](const QStringList& paths, bool add) { openFiles(paths, add); }));
}

FileMenu::~FileMenu() = default;

void FileMenu::status(const QString& text) {
    m_window.statusBar()->showMessage(text, kStatus_ms);
}

QString FileMenu::startFolder() const {
    const QString folder = m_settings.lastFolder();
    return QFileInfo(folder).isDir() ? folder : QString();
}

void FileMenu::openDialog(bool add) {
    const QString path = QFileDialog::getOpenFileName(
        &m_window, add ? "Add caliper log" : "Open caliper log", startFolder(),
        "Caliper logs (*.txt *.las *.LAS *.csv *.dlis *.DLIS);;All files (*)");
    if (!path.isEmpty()) openFile(path, add);
}

void FileMenu::openFiles(const QStringList& paths, bool add) {
    // After the first, each file is added (openFile opens it when no well is shown yet).
    for (int i = 0; i < paths.size(); ++i) openFile(paths[i], add || i > 0);
}

bool FileMenu::openFile(const QString& path, bool add) {
    OpenWellDialog dialog(path, m_session.look(), &m_window);
    if (dialog.exec() != QDialog::Accepted) return false;
    const ParsedWells& chosen = dialog.request();
    if (add && m_session.wellCount() > 0)
        m_session.addWell(chosen.wells.front(), chosen.options);
    else
        m_session.openWell(chosen.wells.front(), chosen.options);
    m_settings.addRecent({path, dialog.choices().options});
    m_settings.setLastFolder(QFileInfo(path).absolutePath());
    fillRecent();
    return true;
}

void FileMenu::openRecent(const DeskSettings::Recent& recent) {
    if (!QFileInfo(recent.path).isFile()) {
        QMessageBox::warning(&m_window, "Open recent", recent.path + ": no such file any more");
        m_settings.removeRecent(recent.path);
        fillRecent();
        return;
    }
    try {
        const ParsedWells parsed = openRequestFrom({recent.path, recent.options}, m_session.look());
        m_session.openWell(parsed.wells.front(), parsed.options);
        m_settings.addRecent(recent);
    } catch (const std::exception& e) {
        // Remembered by another version, or edited: open it as a new file instead.
        status(recent.path + ": " + QString::fromStdString(e.what()));
        openFile(recent.path, false);
    }
    fillRecent();
}

void FileMenu::fillRecent() {
    m_recent->clear();
    const QList<DeskSettings::Recent> recent = m_settings.recentFiles();
    for (int i = 0; i < recent.size(); ++i) {
        QAction* action = m_recent->addAction(
            QString("&%1 %2").arg((i + 1) % 10).arg(QFileInfo(recent[i].path).fileName()), this,
            [this, entry = recent[i]] { openRecent(entry); });
        action->setToolTip(recent[i].path);
        action->setStatusTip(recent[i].path);
    }
    m_recent->addSeparator();
    m_recent->addAction("&Clear the list", this, [this] {
        for (const DeskSettings::Recent& r : m_settings.recentFiles())
            m_settings.removeRecent(r.path);
        fillRecent();
    });
    m_recent->setEnabled(!recent.isEmpty());
}

void FileMenu::exportDialog() {
    QString filter;
    const QString chosen = QFileDialog::getSaveFileName(&m_window, "Export scene",
                                                        QDir(startFolder()).filePath("scene.iv"),
                                                        kExportFilters, &filter);
    if (!chosen.isEmpty()) exportTo(withExtension(chosen, filter));
}

bool FileMenu::exportTo(const QString& path) {
    if (m_export || m_session.wellCount() == 0 || m_session.loading()) {
        status(m_export ? "An export is running" : "No well loaded to export");
        return false;
    }
    // The command line takes one set of options for every file: wells opened with different
    // ones (or only some with a survey) are exported one at a time, the current well here.
    std::vector<WellSource> wells = m_session.wellSources();
    const DeskModel& model = m_session.model();
    LoadOptions options = model.well(0).options;
    bool same = true;
    for (int i = 1; i < model.wellCount(); ++i) same = same && model.well(i).options == options;
    try {
        if (!same) throw std::invalid_argument("the wells were opened with different options");
        m_export = std::make_unique<ExportJob>(m_program, wells, options, path);
    } catch (const std::invalid_argument& e) {
        const int current = std::max(0, model.currentWell());
        options = model.well(current).options;
        wells = {wells.at(static_cast<std::size_t>(current))};
        m_export = std::make_unique<ExportJob>(m_program, wells, options, path);
        status(QString("Exporting %1 only: %2").arg(model.well(current).name, e.what()));
    }
    m_progress = new QProgressDialog("Exporting " + QFileInfo(path).fileName() + "...", "Cancel", 0,
                                     0, &m_window);
    m_progress->setWindowTitle("Export");
    m_progress->setAutoClose(false);
    m_progress->setAutoReset(false);
    m_progress->setMinimumDuration(0);
    m_progress->setAttribute(Qt::WA_DeleteOnClose);
    connect(m_progress, &QProgressDialog::canceled, m_export.get(), &ExportJob::cancel);
    connect(m_export.get(), &ExportJob::progress, m_progress, [this](int done, int total) {
        m_progress->setMaximum(total);
        m_progress->setValue(done);
    });
    connect(m_export.get(), &ExportJob::finished, this, &FileMenu::exportEnded,
            Qt::QueuedConnection);
    m_elapsed = new QTimer(m_progress);
    connect(m_elapsed, &QTimer::timeout, m_progress, [this, path] {
        m_progress->setLabelText(
            QString("Exporting %1... %2 s")
                .arg(QFileInfo(path).fileName())
                .arg(m_export ? m_export->elapsed_ms() / 1000.0 : 0.0, 0, 'f', 1));
    });
    m_elapsed->start(200);
    m_progress->show();
    m_export->start();
    return true;
}

void FileMenu::exportEnded(bool ok, const QString& message) {
    if (m_progress) m_progress->close();
    m_progress = nullptr;
    const double seconds = m_export ? m_export->elapsed_ms() / 1000.0 : 0.0;
    m_export.reset();
    if (ok)
        status(QString("Wrote %1 (%2 s)").arg(message).arg(seconds, 0, 'f', 1));
    else if (message.contains("cancelled"))
        status(message);
    else
        QMessageBox::warning(&m_window, "Export failed", message);
    emit exportFinished(ok, message);
}

void FileMenu::savePicture() {
    SoQtExaminerViewer* viewer = &m_viewer;
    if (m_session.wellCount() == 0 || !viewer->getCamera()) {
        status("No well to picture");
        return;
    }
    const QString path = QFileDialog::getSaveFileName(
        &m_window, "Save picture", QDir(startFolder()).filePath("caliper3d.png"), "PNG (*.png)");
    if (path.isEmpty()) return;
    const std::optional<QSize> size = askPictureSize(&m_window, viewer->getGLWidget()->size());
    if (!size) return;
    try {
        writePicture(path, *size);
        status(QString("Wrote %1 (%2 x %3)").arg(path).arg(size->width()).arg(size->height()));
    } catch (const std::exception& e) {
        QMessageBox::warning(&m_window, "Save picture failed", QString::fromLocal8Bit(e.what()));
    }
}

void FileMenu::writePicture(const QString& path, QSize size) {
    // The offscreen renderer's EGL context cannot be made current on this thread while the
    // viewer's GLX context is: release it (the viewer makes it current again to draw).
    if (auto* gl = qobject_cast<QGLWidget*>(m_viewer.getGLWidget())) gl->doneCurrent();
    const std::string file = QFile::encodeName(path).toStdString();
    scenegraph::Picture picture;
    try {
        picture = drawWindowPicture(m_session, *m_viewer.getCamera(), size.width(), size.height());
    } catch (const std::exception& e) {
        throw std::runtime_error(file + ": " + e.what());
    }
    scenegraph::writePng(picture.image, file);  // whole or not at all; its message names the file
}

void FileMenu::saveReport() {
    const DeskWell* well = m_session.model().current();
    if (!well || !well->analysis) {
        status(well ? "The analysis of " + well->name + " is not ready yet" : "No well loaded");
        return;
    }
    if (m_report) m_report.reset();  // waits for the previous one
    const QString path = QFileDialog::getSaveFileName(
        &m_window, "Save report", QDir(startFolder()).filePath(well->name + "-report.csv"),
        "CSV (*.csv)");
    if (path.isEmpty()) return;
    const std::string sections = path.toStdString();
    const std::string zones = ReportJob::zonesPathFor(sections);
    status("Writing " + path + "...");
    m_report = std::make_unique<ReportJob>(
        this, well->analysis, sections, zones, [this](bool ok, const std::string& message) {
            if (ok)
                status("Wrote " + QString::fromStdString(message));
            else
                QMessageBox::warning(&m_window, "Save report failed",
                                     QString::fromStdString(message));
        });
}

void FileMenu::saveLayout() {
    m_settings.saveLayout(m_window);
}

void FileMenu::restoreLayout() {
    m_settings.restoreLayout(m_window);
}

}  // namespace caliper3d::app
