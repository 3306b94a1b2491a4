#include "app/desktop/file_drop.h"

#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileInfo>
#include <QMimeData>
#include <QTimer>
#include <QUrl>

namespace caliper3d::app {

FileDrop::FileDrop(QObject* parent, Open open) : QObject(parent), m_open(std::move(open)) {}

QStringList FileDrop::localFiles(const QMimeData& data) {
    QStringList out;
    if (!data.hasUrls()) return out;
    for (const QUrl& url : data.urls())
        if (url.isLocalFile() && QFileInfo(url.toLocalFile()).isFile()) out << url.toLocalFile();
    return out;
}

QStringList FileDrop::filesToOpen(const QStringList& paths, Qt::KeyboardModifiers modifiers,
                                  bool& add) {
    add = (modifiers & (Qt::ControlModifier | Qt::ShiftModifier)) != 0;
    if (add || paths.isEmpty()) return paths;
    return {paths.front()};
}

bool FileDrop::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::DragEnter || event->type() == QEvent::DragMove) {
        auto* drag = static_cast<QDragMoveEvent*>(event);
        if (localFiles(*drag->mimeData()).isEmpty()) return QObject::eventFilter(watched, event);
        drag->acceptProposedAction();
        return true;
    }
    if (event->type() == QEvent::Drop) {
        auto* drop = static_cast<QDropEvent*>(event);
        const QStringList paths = localFiles(*drop->mimeData());
        if (paths.isEmpty()) return QObject::eventFilter(watched, event);
        bool add = false;
        const QStringList files = filesToOpen(paths, drop->keyboardModifiers(), add);
        drop->acceptProposedAction();
        // After the drop returns: the dialogs are modal, and the source waits for the drop.
        QTimer::singleShot(0, this, [this, files, add] { m_open(files, add); });
        return true;
    }
    return QObject::eventFilter(watched, event);
}

}  // namespace caliper3d::app
