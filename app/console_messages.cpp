#include "app/console_messages.h"

#include <cstdio>

#include <QString>
#include <QtGlobal>

#include "scenegraph/coin_messages.h"

namespace caliper3d::app {

namespace {

void onQtMessage(QtMsgType type, const QMessageLogContext&, const QString& message) {
    const bool serious = type == QtCriticalMsg || type == QtFatalMsg;
    if (serious || scenegraph::debugMessagesWanted())
        std::fprintf(stderr, "caliper3d: Qt: %s\n", message.toLocal8Bit().constData());
}

}  // namespace

void installMessageFilter() {
    qInstallMessageHandler(&onQtMessage);
}

}  // namespace caliper3d::app
