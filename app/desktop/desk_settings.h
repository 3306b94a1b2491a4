#pragma once

#include <memory>

#include <QList>
#include <QString>

#include "app/well_option_table.h"

class QMainWindow;
class QSettings;

namespace caliper3d::app {

// What the window remembers between runs, in QSettings (organisation and application
// "caliper3d"): the recent files with the options each was opened with, the last folder a
// file was opened from, and the window's geometry and dock layout. Tests point QSettings at a
// scratch folder (QSettings::setPath) before making one.
class DeskSettings {
public:
    static constexpr int kMaxRecent = 10;

    // A file opened, and the options it was opened with (the Open dialog's texts by option
    // name, app/well_option_table.h).
    struct Recent {
        QString path;
        OptionTexts options;
    };

    DeskSettings();
    ~DeskSettings();
    DeskSettings(const DeskSettings&) = delete;
    DeskSettings& operator=(const DeskSettings&) = delete;

    // Most recent first, at most kMaxRecent, one per path.
    QList<Recent> recentFiles() const;
    // Puts `recent` first (replacing an entry of the same path) and keeps kMaxRecent.
    void addRecent(const Recent& recent);
    void removeRecent(const QString& path);

    // The folder the last file was opened from (empty at first).
    QString lastFolder() const;
    void setLastFolder(const QString& folder);

    // QMainWindow::saveGeometry and saveState; restore after the docks are built (they are
    // found by objectName). Returns false when nothing was saved yet.
    void saveLayout(const QMainWindow& window);
    bool restoreLayout(QMainWindow& window) const;

    // Where the settings are written (tests check it is their scratch folder).
    QString fileName() const;

private:
    void writeRecent(const QList<Recent>& list);
    std::unique_ptr<QSettings> m_settings;
};

}  // namespace caliper3d::app
