#include <cstdio>
#include <cstdlib>

#include <QCoreApplication>
#include <QString>

#include "app/commands.h"

namespace caliper3d::app {

namespace {
const char kUsage[] =
    "usage: caliper3d [VERB] [OPTIONS] FILE...\n"
    "  (no verb)                         GUI on the bundled example well; with no display,\n"
    "                                    renders it to out/example.png and out/example.iv\n"
    "  view FILE...                      GUI on these wells\n"
    "  info FILE...                      format, curves and their roles, units, depth range, "
    "warnings\n"
    "  export FILE... -o OUT.iv          scene out as Open Inventor (--binary, --gzip)\n"
    "  render FILE... -o OUT.png         picture (--width W --height H --view iso|north|east|top)\n"
    "  report FILE -o OUT.csv            per-section analysis (--step M, --zones Z.csv,\n"
    "                                    --las OUT.las, --casing-od L, --excess F, --rule N=V)\n"
    "  synth -o OUT [--length M --step M --profile NAME]   synthetic log with known features\n"
    "common: --arms N --depth-unit m|ft --radius-unit in|mm|cm --bit-size VALUE[in|mm]\n"
    "        --radii MNEM,... --diameters MNEM,... --nulls declared|common --row-step METRES\n"
    "        --survey FILE --wellhead E,N,ELEV (once per FILE) --steep-inclination DEG\n"
    "        --tool-reach LENGTH --points M --segment-length METRES --exaggerate F\n"
    "Run 'caliper3d VERB --help' for a verb's options.\n";
}  // namespace

int runCommandLine(int argc, char** argv) {
    QStringList args;
    for (int i = 1; i < argc; ++i) args << QString::fromLocal8Bit(argv[i]);
    if (args.isEmpty()) return runDefault(argc, argv);
    const QString verb = args.takeFirst();
    if (verb == "export") return runExport(args);
    if (verb == "info") return runInfo(args);
    if (verb == "render") return runRender(args);
    if (verb == "report") return runReport(args);
    if (verb == "synth") return runSynth(args);
    if (verb == "view") return runView(argc, argv, args);
    if (verb == "-h" || verb == "--help" || verb == "help") {
        std::fputs(kUsage, stdout);
        return kExitOk;
    }
    if (verb == "--version") {
        std::puts("caliper3d 0.1.0");
        return kExitOk;
    }
    std::fprintf(stderr, "caliper3d: unknown verb '%s'\n%s", verb.toLocal8Bit().constData(),
                 kUsage);
    return kExitUsage;
}

}  // namespace caliper3d::app
