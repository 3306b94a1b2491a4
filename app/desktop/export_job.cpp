#include "app/desktop/export_job.h"

#include <QFile>
#include <QProcessEnvironment>
#include <QRegularExpression>

#include "io/atomic_output.h"

namespace caliper3d::app {

ExportJob::ExportJob(QString program, const std::vector<WellSource>& wells,
                     const LoadOptions& options, QString output, QObject* parent)
    : QObject(parent), m_program(std::move(program)), m_output(std::move(output)) {
    m_arguments = exportArguments(wells, options, m_output);
    connect(&m_process, &QProcess::readyReadStandardError, this, &ExportJob::readErrors);
    connect(&m_process, qOverload<int, QProcess::ExitStatus>(&QProcess::finished), this,
            &ExportJob::ended);
    connect(&m_process, &QProcess::errorOccurred, this, [this](QProcess::ProcessError error) {
        if (error == QProcess::FailedToStart)
            emit finished(false, m_output + ": could not start " + m_program + ": " +
                                     m_process.errorString());
    });
    // The child's summary lines are not shown; only stderr is read.
    m_process.setStandardOutputFile(QProcess::nullDevice());
    // An export writes a file and opens no window: without a display to name, the child cannot
    // connect to the window's X server (nor fail when that server refuses a connection).
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.remove("DISPLAY");
    environment.remove("WAYLAND_DISPLAY");
    m_process.setProcessEnvironment(environment);
}

ExportJob::~ExportJob() {
    if (running()) cancel();
}

void ExportJob::start() {
    m_clock.start();
    m_process.start(m_program, m_arguments);
    m_childPid = m_process.processId();  // set once forked, before it has started
}

bool ExportJob::running() const {
    return m_process.state() != QProcess::NotRunning;
}

void ExportJob::cancel() {
    if (!running()) return;
    m_cancelled = true;
    // SIGTERM lets the child remove its temporary file on its way out.
    m_process.terminate();
    if (m_process.waitForFinished(3000)) return;
    m_process.kill();
    m_process.waitForFinished(5000);
}

bool ExportJob::parseProgress(const QString& line, int& done, int& total) {
    static const QRegularExpression pattern(R"(^progress (\d+)/(\d+) \S+\s*$)");
    const QRegularExpressionMatch match = pattern.match(line);
    if (!match.hasMatch()) return false;
    done = match.captured(1).toInt();
    total = match.captured(2).toInt();
    return total > 0 && done <= total;
}

void ExportJob::readErrors() {
    m_pending += QString::fromLocal8Bit(m_process.readAllStandardError());
    int end = -1;
    while ((end = m_pending.indexOf('\n')) >= 0) {
        const QString line = m_pending.left(end);
        m_pending.remove(0, end + 1);
        int done = 0, total = 0;
        if (parseProgress(line, done, total))
            emit progress(done, total);
        else if (!line.trimmed().isEmpty())
            m_errors << line;
    }
}

void ExportJob::ended(int exitCode, QProcess::ExitStatus status) {
    readErrors();
    if (!m_pending.trimmed().isEmpty()) m_errors << m_pending.trimmed();
    const bool ok = !m_cancelled && status == QProcess::NormalExit && exitCode == 0;
    // A child killed or crashed could not remove its temporary; one that failed has.
    if (!ok && m_childPid > 0)
        io::removeTemporaries(QFile::encodeName(m_output).toStdString(), m_childPid);
    if (m_cancelled)
        emit finished(false, m_output + ": export cancelled; nothing written");
    else if (ok)
        emit finished(true, m_output);
    else
        emit finished(false, m_output + ": export failed" +
                                 (status == QProcess::CrashExit
                                      ? QString(" (the export process crashed)")
                                      : QString(" (exit status %1)").arg(exitCode)) +
                                 (m_errors.isEmpty() ? QString() : ":\n" + m_errors.join("\n")));
}

}  // namespace caliper3d::app
