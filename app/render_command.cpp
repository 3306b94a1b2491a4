#include <chrono>
#include <cstdio>
#include <exception>

#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <glm/vec3.hpp>

#include "app/commands.h"
#include "app/input_options.h"
#include "app/pick_output.h"
#include "app/png_output.h"
#include "app/scene_assembly.h"
#include "app/verb_parser.h"
#include "io/number_parsing.h"
#include "scenegraph/main_thread.h"
#include "scenegraph/render_stats.h"

namespace caliper3d::app {

int runRender(const QStringList& args) {
    return guardedVerb("render", [&]() -> int {
        VerbParser verb("render", "FILE... -o OUT.png",
                        "Render wells to a PNG picture without a window.");
        QCommandLineParser& p = verb.parser();
        p.addOption({{"o", "output"}, "Output picture (.png).", "OUT"});
        p.addOption({"width", "Picture width in pixels (default 1024).", "W", "1024"});
        p.addOption({"height", "Picture height in pixels (default 768).", "H", "768"});
        p.addOption({"view",
                     "iso, north, east, top, or hole (inside the first well, looking down it) "
                     "(default iso).",
                     "VIEW", "iso"});
        p.addOption(
            {"at",
             "With --view hole: measured depth of the eye in metres (default: top of the log).",
             "MD"});
        p.addOption({"pixel-tolerance",
                     QString("Level of detail: the shape error, in pixels, that may show "
                             "(default %1).")
                         .arg(double(scenegraph::kDefaultPixelTolerance)),
                     "PX", QString::number(double(scenegraph::kDefaultPixelTolerance))});
        p.addOption({"stats",
                     "After the picture, print one line: triangles_drawn frame_ms (the mean of "
                     "5 frames drawn after it) rss_mb (peak) first_picture_ms and load_ms "
                     "(from the start of reading)."});
        addPickOption(p);
        addInputOptions(p);
        addColourOptions(p);
        addWellSourceOptions(p);
        if (!verb.parse(args, 1)) return kExitOk;
        if (!verb.isSet("output")) throw UsageError("caliper3d render: -o OUT.png is required");
        bool okW = false, okH = false;
        const int width = p.value("width").toInt(&okW), height = p.value("height").toInt(&okH);
        if (!okW || !okH || width < 16 || height < 16 || width > 8192 || height > 8192)
            throw UsageError(
                "caliper3d render: --width and --height take whole numbers from 16 to 8192");
        const bool downHole = verb.value("view") == "hole";
        const auto view = scenegraph::parseViewDirection(verb.value("view"));
        if (!view && !downHole)
            throw UsageError("caliper3d render: --view takes iso, north, east, top or hole");
        double at = 0.0;
        if (verb.isSet("at") && !io::parseNumber(verb.value("at"), at))
            throw UsageError("caliper3d render: --at takes a measured depth in metres");
        if (verb.isSet("at") && !downHole)
            throw UsageError("caliper3d render: --at places the eye of --view hole; the " +
                             verb.value("view") + " view shows the whole scene and ignores it");
        const auto pick = pickPixelFrom(p, width, height, "caliper3d render");
        LoadOptions options = inputOptionsFrom(p);
        options.colour = colourRequestFrom(p);

        double tolerance = 2.0;
        if (!io::parseNumber(verb.value("pixel-tolerance"), tolerance) ||
            !(tolerance >= 0.1 && tolerance <= 100.0))
            throw UsageError("caliper3d render: --pixel-tolerance takes pixels from 0.1 to 100");

        const auto start = std::chrono::steady_clock::now();
        scenegraph::initCoin();
        AssembledScene scene = assembleScene(wellSourcesFrom(p, verb.positional()), options);
        if (scene.wells == 0) return kExitBadInput;
        const std::string out = verb.value("output");
        scenegraph::NodeRef<SoSeparator> root;
        if (downHole) {
            const auto& geometry = *scene.geometries.front();
            const double top = geometry.table().depth_m.front();
            const double bottom = geometry.table().depth_m.back();
            if (!verb.isSet("at")) at = top;
            if (at < top || at > bottom) {
                char range[96];
                std::snprintf(range, sizeof range, "%.2f to %.2f m", top, bottom);
                throw UsageError("caliper3d render: --at " + verb.value("at") +
                                 " is outside the logged depths of " + geometry.table().source +
                                 " (" + range + ")");
            }
            root = scenegraph::makeRef(
                scenegraph::makeRenderRoot(scene.root.get(), downHolePose(geometry, at)));
        } else {
            root = scenegraph::makeRef(
                scenegraph::makeRenderRoot(scene.root.get(), *view, width, height));
        }
        refineForCamera(scene, root.get(), height, static_cast<float>(tolerance));
        addColourLegend(root.get(), scene);
        scenegraph::OffscreenRenderer renderer;
        const scenegraph::RenderedImage image =
            renderer.render(root.get(), width, height, scenegraph::kBackgroundColour);
        const auto firstPicture = std::chrono::steady_clock::now();
        savePng(image, out);
        if (verb.isSet("stats")) {
            const double frameMs =
                renderer.timeFrames(root.get(), width, height, scenegraph::kBackgroundColour, 5);
            using Ms = std::chrono::duration<double, std::milli>;
            std::printf(
                "triangles_drawn=%zu frame_ms=%.1f rss_mb=%.0f first_picture_ms=%.0f "
                "load_ms=%.0f\n",
                scenegraph::trianglesDrawn(root.get(), width, height), frameMs,
                scenegraph::peakRss_mb(), Ms(firstPicture - start).count(), scene.load_ms);
        }
        std::printf("wrote %s (%dx%d)\n", out.c_str(), width, height);
        if (pick) std::fputs(describePick(scene, root.get(), width, height, *pick).c_str(), stdout);
        return scene.failures > 0 ? kExitBadInput : kExitOk;
    });
}

}  // namespace caliper3d::app
