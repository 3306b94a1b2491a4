#include <cstdio>
#include <cstdlib>

#include <optional>
#include <string>

#include <QFileInfo>
#include <QString>
#include <QStringList>

#include "app/commands.h"
#include "app/console_messages.h"
#include "app/well_option_table.h"

namespace caliper3d::app {

namespace {
const char kVerbs[] = "view, info, export, render, report, compare, splice, synth, batch";
const char kUsageHead[] =
    "usage: caliper3d [VERB] [OPTIONS] FILE...\n"
    "  (no verb)                         GUI on the bundled example well; with no display,\n"
    "                                    renders it to out/example.png and out/example.iv\n"
    "  FILE...                           GUI on these wells (the same as 'view FILE...')\n"
    "  view FILE... | --manifest M       GUI on these wells (a manifest: every row's well)\n"
    "  info FILE...                      format, curves and their roles, units, depth range, "
    "warnings\n"
    "  export FILE... -o OUT             scene out as Open Inventor (.iv, .iv.gz) or mesh\n"
    "                                    (.glb, .ply, .stl, .obj; --detail shown|full)\n"
    "  render FILE... -o OUT.png         picture (--width W --height H\n"
    "                                    --view iso|north|east|top|map|hole --at MD)\n"
    "  report FILE... -o OUT.csv         per-section analysis (--step M, --zones Z.csv,\n"
    "                                    --las OUT.las, --casing-od L, --excess F, --rule N=V)\n"
    "  compare RUN1 RUN2 -o OUT.csv      two runs of one well: depth-matched, compared in the\n"
    "                                    earth frame (--match-curve, --max-shift, --shift)\n"
    "  splice RUN1 RUN2 ... -o OUT.las   runs of one well joined into one log (--at MD)\n"
    "  synth -o OUT [--length M --step M --profile NAME]   synthetic log with known features\n"
    "  synth --field N -o DIR/           N synthetic wells and a manifest for batch\n"
    "  batch MANIFEST [-o DIR/ -j N --row K]   one well a row (CSV or JSON), each in its own\n"
    "                                    process; batch --merge OUT.jsonl IN... joins summaries\n"
    "many files: -o DIR/ or -o 'out/{stem}.csv' writes one output per FILE (export and render\n"
    "        with one -o FILE draw them in one scene); --summary FILE.jsonl: a JSON line each\n";
const char kUsageTail[] =
    "Run 'caliper3d help VERB' (or 'caliper3d VERB --help') for a verb's options.\n";

// The well's options come from their table, so a new one is listed without an edit here.
std::string usage() {
    return kUsageHead + optionsUsage() + kUsageTail;
}
}  // namespace

namespace {

// Runs `verb` on `args`; returns nullopt when `verb` is not one.
std::optional<int> runVerb(const QString& verb, const QStringList& args, int argc, char** argv) {
    if (verb == "batch") return runBatch(args);
    if (verb == "compare") return runCompare(args);
    if (verb == "export") return runExport(args);
    if (verb == "info") return runInfo(args);
    if (verb == "render") return runRender(args);
    if (verb == "report") return runReport(args);
    if (verb == "splice") return runSplice(args);
    if (verb == "synth") return runSynth(args);
    if (verb == "view") return runView(argc, argv, args);
    return std::nullopt;
}

// A first argument that is no verb but names a file (or looks like a path:
// a folder or an extension) opens the window on it, as 'view' would.
bool looksLikeAFile(const QString& argument) {
    if (argument.startsWith('-')) return false;
    const QFileInfo info(argument);
    return info.exists() || argument.contains('/') || !info.suffix().isEmpty();
}

}  // namespace

int runCommandLine(int argc, char** argv) {
    installMessageFilter();
    QStringList args;
    for (int i = 1; i < argc; ++i) args << QString::fromLocal8Bit(argv[i]);
    if (args.isEmpty()) return runDefault(argc, argv);
    const QString verb = args.takeFirst();
    if (auto status = runVerb(verb, args, argc, argv)) return *status;
    if (verb == "-h" || verb == "--help" || verb == "help") {
        if (args.isEmpty()) {
            std::fputs(usage().c_str(), stdout);
            return kExitOk;
        }
        if (auto status = runVerb(args.front(), {"--help"}, argc, argv)) return *status;
        std::fprintf(stderr, "caliper3d help: unknown verb '%s'; the verbs are %s\n",
                     args.front().toLocal8Bit().constData(), kVerbs);
        return kExitUsage;
    }
    if (verb == "--version") {
        std::puts("caliper3d 0.1.0");
        return kExitOk;
    }
    if (looksLikeAFile(verb)) return runView(argc, argv, QStringList(verb) + args);
    std::fprintf(stderr, "caliper3d: unknown verb '%s' (the verbs are %s), and no such file\n%s",
                 verb.toLocal8Bit().constData(), kVerbs, usage().c_str());
    return kExitUsage;
}

}  // namespace caliper3d::app
