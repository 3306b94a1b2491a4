#pragma once

#include <QElapsedTimer>
#include <QObject>
#include <QProcess>
#include <QString>
#include <QStringList>

#include "app/desktop/command_arguments.h"

namespace caliper3d::app {

// One export run by a child `caliper3d export ... --progress` (the same binary), so the
// window's Coin graph is never touched off the main thread and the window stays responsive:
// the child reads the well and writes the file on its own. Its "progress DONE/TOTAL steps"
// lines on stderr become progress(); cancel() stops it. The child writes the output as every
// verb does (io/atomic_output.h): into a temporary beside it, renamed over it once complete, so
// a cancelled or failed export leaves an existing file as it was, and no temporary.
class ExportJob : public QObject {
    Q_OBJECT

public:
    // `program`: the caliper3d binary (the window passes QCoreApplication::applicationFilePath).
    // Throws std::invalid_argument as wellArguments does.
    ExportJob(QString program, const std::vector<WellSource>& wells, const LoadOptions& options,
              QString output, QObject* parent = nullptr);
    ~ExportJob() override;

    void start();
    // Stops the child (SIGTERM, which removes its temporary; SIGKILL if it does not end within
    // seconds, its temporary then removed here); finished(false, "cancelled") follows.
    void cancel();
    bool running() const;
    const QString& output() const { return m_output; }
    const QStringList& arguments() const { return m_arguments; }
    qint64 elapsed_ms() const { return m_clock.isValid() ? m_clock.elapsed() : 0; }

    // "progress 12/340 segments" -> 12, 340; false for any other line.
    static bool parseProgress(const QString& line, int& done, int& total);

signals:
    void progress(int done, int total);
    // ok: the file is written. Else `message` says why, naming the file (the child's own
    // error lines, or how it ended).
    void finished(bool ok, const QString& message);

private:
    void readErrors();
    void ended(int exitCode, QProcess::ExitStatus status);

    QString m_program;
    QStringList m_arguments;
    QString m_output;
    QProcess m_process;
    qint64 m_childPid = 0;  // names the child's temporary file
    QElapsedTimer m_clock;
    QString m_pending;     // a stderr line not ended yet
    QStringList m_errors;  // the child's stderr, progress lines left out
    bool m_cancelled = false;
};

}  // namespace caliper3d::app
