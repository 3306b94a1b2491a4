#pragma once

#include <memory>
#include <optional>

#include <QObject>
#include <QSize>
#include <QString>
#include <QStringList>

#include "app/desktop/desk_settings.h"
#include "app/desktop/open_choices.h"

class QMainWindow;
class QMenu;
class QProgressDialog;
class QTimer;
class SoQtExaminerViewer;

namespace caliper3d::app {

class ExportJob;
class WellSession;
class ReportJob;

// The window's File menu and what it does with files: Open and Add through the Open dialog
// (OpenWellDialog), Open recent, drag and drop (FileDrop), Export (a child `caliper3d export`,
// ExportJob, with a progress dialog and Cancel), Save picture (drawWindowPicture) and Save report
// (ReportJob on a worker); and the settings that outlive the window (DeskSettings). It opens
// wells through the session, pictures from the viewer, and uses the window as the dialogs'
// parent, for drops and for its layout.
class FileMenu : public QObject {
    Q_OBJECT

public:
    FileMenu(QMainWindow& window, WellSession& session, SoQtExaminerViewer& viewer, QMenu* menu);
    ~FileMenu() override;

    // File > Open (add false) or Add: a file chosen, then the Open dialog.
    void openDialog(bool add);
    // `paths` each through the Open dialog: the first replaces the wells shown unless `add`.
    void openFiles(const QStringList& paths, bool add);
    // One file through the Open dialog; false when cancelled.
    bool openFile(const QString& path, bool add);
    // A recent file, opened with the options it was opened with before (no dialog).
    void openRecent(const DeskSettings::Recent& recent);
    void exportDialog();
    // Exports the wells shown to `path` (its extension picks the format) on a child process;
    // false when there is nothing to export or one is running.
    bool exportTo(const QString& path);
    void savePicture();
    // Save picture without its dialogs: the window's view at `size`, as `caliper3d render`
    // draws it (drawWindowPicture). Throws std::runtime_error naming what failed.
    void writePicture(const QString& path, QSize size);
    void saveReport();

    // The window's layout (closeEvent) and its restoring (after the docks are built).
    void saveLayout();
    void restoreLayout();

    // The binary run for exports (default: this application's own file).
    void setExportProgram(const QString& program) { m_program = program; }
    const ExportJob* exportJob() const { return m_export.get(); }
    DeskSettings& settings() { return m_settings; }

signals:
    // An export ended (ok: the file is written; else the message shown).
    void exportFinished(bool ok, const QString& message);

private:
    void fillRecent();
    QString startFolder() const;
    void exportEnded(bool ok, const QString& message);
    void status(const QString& text);

    QMainWindow& m_window;
    WellSession& m_session;
    SoQtExaminerViewer& m_viewer;
    QMenu* m_recent = nullptr;
    DeskSettings m_settings;
    QString m_program;
    std::unique_ptr<ExportJob> m_export;
    QProgressDialog* m_progress = nullptr;
    QTimer* m_elapsed = nullptr;  // the elapsed time in the progress dialog
    std::unique_ptr<ReportJob> m_report;
};

}  // namespace caliper3d::app
