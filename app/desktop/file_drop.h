#pragma once

#include <functional>

#include <QObject>
#include <QStringList>

class QMimeData;

namespace caliper3d::app {

// Drag and drop of log files onto the window (an event filter on it; the window accepts
// drops). A plain drop opens the first file, replacing the wells shown; with Ctrl or Shift
// held every file dropped is added. Each file then goes through the Open dialog, one dialog
// per file (a dialog cancelled skips its file): each file has its own bit size, survey and
// wellhead, and a default from one file would be wrong for the next.
class FileDrop : public QObject {
    Q_OBJECT

public:
    using Open = std::function<void(const QStringList& paths, bool add)>;
    FileDrop(QObject* parent, Open open);

    // The local files of a drop (URLs that are not local files are left out).
    static QStringList localFiles(const QMimeData& data);
    // What a drop with `modifiers` held does with `paths`: the files opened, and whether added.
    static QStringList filesToOpen(const QStringList& paths, Qt::KeyboardModifiers modifiers,
                                   bool& add);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    Open m_open;
};

}  // namespace caliper3d::app
