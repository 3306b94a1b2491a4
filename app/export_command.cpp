#include <chrono>
#include <cstdio>
#include <exception>
#include <vector>

#include "app/commands.h"
#include "app/input_options.h"
#include "app/scene_assembly.h"
#include "app/verb_parser.h"
#include "scenegraph/iv_export.h"
#include "scenegraph/main_thread.h"

namespace caliper3d::app {

int runExport(const QStringList& args) {
    return guardedVerb("export", [&]() -> int {
        VerbParser verb("export", "FILE... -o OUT.iv",
                        "Export wells as an Open Inventor scene: each well's path and, per "
                        "segment, an SoLOD. By default (--detail shown) its levels are the coarse "
                        "ones the window loads up front (sections kept by shape error, 12-point "
                        "rings and the raw N-gon; see --shape-tolerance). --detail full writes "
                        "every level, full detail first, one segment at a time (memory holds one "
                        "segment's nodes; the file is large: 2.9 GB for 4 km at 2.5 mm). The file "
                        "is binary Open Inventor unless --ascii is given: every Inventor reader "
                        "takes both, and text takes 4-5 times as long to write.");
        QCommandLineParser& p = verb.parser();
        p.addOption({{"o", "output"},
                     "Output file: .iv, or .iv.gz for a gzip-compressed scene (as --gzip).",
                     "OUT"});
        p.addOption({"ascii",
                     "Write Open Inventor as text (3 times the size and 4-5 times the writing "
                     "time of binary)."});
        p.addOption({"binary", "Write binary Open Inventor (the default)."});
        p.addOption({"gzip", "Compress the output with gzip (implied by a name ending .iv.gz)."});
        p.addOption({"detail",
                     "shown (the coarse levels, default) or full (every level, streamed).",
                     "LEVELS", "shown"});
        addInputOptions(p);
        addColourOptions(p);
        addWellSourceOptions(p);
        if (!verb.parse(args, 1)) return kExitOk;
        if (!verb.isSet("output")) throw UsageError("caliper3d export: -o OUT.iv is required");
        const std::string out = verb.value("output");
        const auto endsWith = [&out](const std::string& tail) {
            return out.size() > tail.size() &&
                   out.compare(out.size() - tail.size(), tail.size(), tail) == 0;
        };
        const bool gzipName = endsWith(".iv.gz");
        if (!endsWith(".iv") && !gzipName)
            throw UsageError("caliper3d export: the output must end in .iv or .iv.gz, got '" + out +
                             "'");
        const std::string detail = verb.value("detail");
        if (detail != "shown" && detail != "full")
            throw UsageError("caliper3d export: --detail takes shown or full, got '" + detail +
                             "'");
        if (verb.isSet("ascii") && verb.isSet("binary"))
            throw UsageError("caliper3d export: give --ascii or --binary, not both");
        LoadOptions options = inputOptionsFrom(p);
        options.colour = colourRequestFrom(p);

        scenegraph::initCoin();
        const auto start = std::chrono::steady_clock::now();
        AssembledScene scene = assembleScene(wellSourcesFrom(p, verb.positional()), options);
        if (scene.wells == 0) return kExitBadInput;
        scenegraph::IvExportOptions ivOptions;
        ivOptions.binary = !verb.isSet("ascii");
        ivOptions.gzip = verb.isSet("gzip") || gzipName;
        const auto built = std::chrono::steady_clock::now();
        if (detail == "full") {
            std::vector<const reconstruction::WellGeometry*> wells;
            for (const auto& geometry : scene.geometries) wells.push_back(geometry.get());
            scenegraph::writeIvFullDetail(wells, out, ivOptions);
        } else {
            scenegraph::writeIv(scene.root.get(), out, ivOptions);
        }
        const auto written = std::chrono::steady_clock::now();
        using Seconds = std::chrono::duration<double>;
        std::printf("wrote %s (%d well%s): read and built in %.2f s, written in %.2f s\n",
                    out.c_str(), scene.wells, scene.wells == 1 ? "" : "s",
                    Seconds(built - start).count(), Seconds(written - built).count());
        return scene.failures > 0 ? kExitBadInput : kExitOk;
    });
}

}  // namespace caliper3d::app
