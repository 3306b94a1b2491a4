#pragma once

#include <QStringList>

namespace caliper3d::app {

// Exit status of every verb: 0 success, 1 bad input, 2 bad usage.
enum ExitStatus { kExitOk = 0, kExitBadInput = 1, kExitUsage = 2 };

// Each verb is one function over its own arguments (without the verb itself);
// all of them are thin shells over io/, reconstruction/ and scenegraph/.
int runBatch(const QStringList& args);
int runCompare(const QStringList& args);
int runExport(const QStringList& args);
int runInfo(const QStringList& args);
int runRender(const QStringList& args);
int runReport(const QStringList& args);
int runSplice(const QStringList& args);
int runSynth(const QStringList& args);
int runView(int argc, char** argv, const QStringList& args);
// No verb: the GUI on the bundled example, or with no display, the example
// rendered to out/example.png and out/example.iv.
int runDefault(int argc, char** argv);

// Dispatches argv[1] to a verb.
int runCommandLine(int argc, char** argv);

}  // namespace caliper3d::app
