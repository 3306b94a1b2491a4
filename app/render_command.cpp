#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <optional>

#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>
#include <glm/vec3.hpp>

#include "app/change_colouring.h"
#include "app/commands.h"
#include "app/each_input.h"
#include "app/input_options.h"
#include "app/input_summary.h"
#include "app/output_names.h"
#include "app/pick_output.h"
#include "app/scene_assembly.h"
#include "app/verb_parser.h"
#include "io/number_parsing.h"
#include "reconstruction/well_interval.h"
#include "scenegraph/main_thread.h"
#include "scenegraph/picture/picture.h"
#include "scenegraph/picture/png_file.h"
#include "scenegraph/picture_scale.h"
#include "scenegraph/render_caching.h"
#include "scenegraph/render_stats.h"

namespace caliper3d::app {

namespace {

// --depth TOP,BOTTOM: measured depths in metres.
struct DepthInterval {
    double top_m = 0.0;
    double bottom_m = 0.0;
};

std::optional<DepthInterval> parseDepthInterval(const VerbParser& verb) {
    if (!verb.isSet("depth")) return std::nullopt;
    const std::string text = verb.value("depth");
    const auto comma = text.find(',');
    DepthInterval interval;
    if (comma == std::string::npos || !io::parseNumber(text.substr(0, comma), interval.top_m) ||
        !io::parseNumber(text.substr(comma + 1), interval.bottom_m))
        throw UsageError("caliper3d render: --depth takes TOP,BOTTOM, measured depths in metres");
    if (!(interval.top_m < interval.bottom_m))
        throw UsageError("caliper3d render: --depth " + text + ": TOP must lie above BOTTOM");
    return interval;
}

std::string depthRange(double top_m, double bottom_m) {
    char range[96];
    std::snprintf(range, sizeof range, "%.2f to %.2f m", top_m, bottom_m);
    return range;
}

// What a picture draws of the wells loaded: the interval asked for (each well's whole
// log otherwise), at the radial exaggeration given or else chosen for the picture
// (scenegraph::chooseExaggeration, which the window opens with too). An interval replaces each
// well's geometry by its rows there; the exaggeration is applied as the wells are coloured
// (assembleScene).
struct PicturePlan {
    std::optional<DepthInterval> depth;
    std::string depthText;    // as given, for messages
    bool chooseExaggeration;  // no --exaggerate, and a view of the whole or of an interval
    int height;               // of the picture, pixels
    double exaggeration;      // as asked; then as drawn
    double top_m() const { return depth ? depth->top_m : 0.0; }
    double bottom_m() const {
        return depth ? depth->bottom_m : std::numeric_limits<double>::infinity();
    }

    void operator()(std::vector<std::shared_ptr<const reconstruction::WellGeometry>>& wells,
                    double& radialExaggeration) {
        if (depth)
            for (auto& well : wells) {
                const std::vector<double>& md = well->table().depth_m;
                if (depth->top_m < md.front() || depth->bottom_m > md.back())
                    throw UsageError("caliper3d render: --depth " + depthText +
                                     " is outside the logged depths of " + well->table().source +
                                     " (" + depthRange(md.front(), md.back()) + ")");
                well = reconstruction::intervalGeometry(*well, depth->top_m, depth->bottom_m,
                                                        well->options());
            }
        if (chooseExaggeration)
            exaggeration = scenegraph::chooseExaggeration(wells, top_m(), bottom_m(), height);
        radialExaggeration = exaggeration;
    }
};

void addRenderOptions(QCommandLineParser& p) {
    p.addOption({{"o", "output"}, "Output picture (.png).", "OUT"});
    p.addOption({"width", "Picture width in pixels (default 1024).", "W", "1024"});
    p.addOption({"height", "Picture height in pixels (default 768).", "H", "768"});
    p.addOption({"view",
                 "iso, north, east, top, map (from above, the whole wells framed and each "
                 "named beside its wellhead), or hole (inside the first well, looking down "
                 "it) (default iso).",
                 "VIEW", "iso"});
    p.addOption({"at",
                 "With --view hole: measured depth of the eye in metres (default: top of the log).",
                 "MD"});
    p.addOption({"depth",
                 "Draw only the sections with measured depths from TOP to BOTTOM (metres, "
                 "within the logged depths) and frame them.",
                 "TOP,BOTTOM"});
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
}

// What every picture of one run is drawn with.
struct RenderSettings {
    int width = 0, height = 0;
    bool downHole = false;
    std::optional<scenegraph::ViewDirection> view;
    bool atSet = false;
    double at = 0.0;
    std::string atText;
    std::optional<PickPixel> pick;
    LoadOptions options;
    PicturePlan plan{};
    float tolerance = 2.0F;
    bool stats = false;
};

// Draws `sources` into the picture `out`.
int renderPicture(const std::vector<WellSource>& sources, const RenderSettings& r,
                  const std::string& out, std::vector<InputSummary>& inputs) {
    const auto start = std::chrono::steady_clock::now();
    scenegraph::initCoin();
    // What will draw the picture, before the meshes are built (render caching on a GPU).
    scenegraph::probeOffscreenRenderer();
    PicturePlan plan = r.plan;
    // One picture builds what its camera needs before it draws (refineForCamera): a field
    // needs only its coarsest segment level up front.
    const int firstLevel = sources.size() > 1 ? reconstruction::kFieldFirstCoarseLevel
                                              : reconstruction::kFirstCoarseLevel;
    // A large field is held lean unless every row is wanted: an interval cut from each well,
    // a pick (the analysis of every well), or colour by change (a field held lean reads each
    // well again; the comparison needs the whole log).
    FieldRows rows;
    if (!plan.depth && !r.pick) rows = {kFieldRowBudget, r.downHole};
    // Segments are made where the camera comes near (refineForCamera): a field or a long well
    // seen whole draws spans only.
    rows.segmentNodes = scenegraph::SegmentNodes::whenNear;
    AssembledScene scene = assembleScene(sources, r.options, std::ref(plan), firstLevel, rows);
    inputs = scene.inputs;
    if (scene.wells == 0) return kExitBadInput;
    scenegraph::PictureRequest request;
    request.width = r.width;
    request.height = r.height;
    request.top_m = plan.top_m();
    request.bottom_m = plan.bottom_m();
    request.radialExaggeration = plan.exaggeration;
    request.pixelTolerance = r.tolerance;
    request.legend = scene.legend();
    request.stats = r.stats;
    if (r.downHole) {
        const auto& geometry = *scene.geometries.front();
        const double top = geometry.table().depth_m.front();
        const double bottom = geometry.table().depth_m.back();
        const double at = r.atSet ? r.at : top;
        if (at < top || at > bottom)
            throw UsageError("caliper3d render: --at " + r.atText + " is outside " +
                             (plan.depth ? "--depth " + plan.depthText
                                         : "the logged depths of " + geometry.table().source) +
                             " (" + depthRange(top, bottom) + ")");
        request.pose = scenegraph::downHolePose(geometry, at);
        request.top_m = at;
        request.bottom_m = at + request.pose->fogVisibility_m;
        request.tickMarks = false;
        char eye[64];
        std::snprintf(eye, sizeof eye, "eye at MD %.2f m", at);
        request.caption.emplace_back(eye);
    } else {
        request.view = *r.view;
        // The path above each log, where it falls in the picture of the whole logs.
        request.unloggedPath = !plan.depth;
    }
    const double beforePicture_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const scenegraph::Picture picture = scenegraph::drawPicture(scene.pictureWells(), request);
    // Up to the first picture read back: the frames timed for --stats come after it.
    const double firstPicture_ms = beforePicture_ms + picture.render_ms;
    scenegraph::writePng(picture.image, out);
    if (r.stats)
        std::printf(
            "triangles_drawn=%zu nodes_traversed=%zu frame_ms=%.1f rss_mb=%.0f "
            "first_picture_ms=%.0f load_ms=%.0f\n",
            picture.trianglesDrawn, picture.nodesTraversed, picture.frame_ms,
            scenegraph::peakRss_mb(), firstPicture_ms, scene.load_ms);
    std::printf("wrote %s (%dx%d)\n", out.c_str(), r.width, r.height);
    if (r.pick)
        std::fputs(describePick(scene, picture.root.get(), r.width, r.height, *r.pick).c_str(),
                   stdout);
    return scene.failures > 0 ? kExitBadInput : kExitOk;
}

// renderPicture, each source's summary line to `inputs` (failed where the picture failed).
int renderTo(const std::vector<WellSource>& sources, const RenderSettings& r,
             const std::string& out, std::vector<InputSummary>& inputs) {
    const double start = steadySeconds();
    const std::size_t first = inputs.size();
    int status = kExitBadInput;
    try {
        status = renderPicture(sources, r, out, inputs);
    } catch (const UsageError&) {
        throw;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "caliper3d render: %s\n", e.what());
        for (std::size_t i = first; i < inputs.size(); ++i)
            if (!inputs[i].error) inputs[i].error = InputError{out, 0, e.what()};
    }
    for (std::size_t i = first; i < inputs.size(); ++i) {
        InputSummary& input = inputs[i];
        input.verb = "render";
        if (!input.error) input.outputs = {out};
        stampCost(input, start);
    }
    return status;
}

}  // namespace

int runRender(const QStringList& args) {
    return guardedVerb("render", [&]() -> int {
        VerbParser verb("render", "FILE... -o OUT.png|DIR/|PATTERN",
                        "Render wells to a PNG picture without a window.\n"
                        "-o OUT.png draws every FILE in one picture; -o DIR/ (DIR/STEM.png) or a\n"
                        "pattern with {stem}, {name} or {index} (pics/{stem}.png) one picture\n"
                        "per FILE, a bad one not stopping the others (exit status 1).\n"
                        "The picture frames every well's log (or --depth TOP,BOTTOM of it) with\n"
                        "depth ticks labelled in metres of measured depth, each well's name at\n"
                        "the top of its log, the path above the log dashed where it is in view,\n"
                        "a north arrow and the radial exaggeration. Unless --exaggerate is given, "
                        "radii are drawn\n"
                        "large enough that the hole reads as a tube (at least 1.5 % of the\n"
                        "picture's height across), never so large that two wells' tubes touch;\n"
                        "looking down the hole, as logged.");
        QCommandLineParser& p = verb.parser();
        addRenderOptions(p);
        addSummaryOption(p);
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
            throw UsageError("caliper3d render: --view takes iso, north, east, top, map or hole");
        double at = 0.0;
        if (verb.isSet("at") && !io::parseNumber(verb.value("at"), at))
            throw UsageError("caliper3d render: --at takes a measured depth in metres");
        if (verb.isSet("at") && !downHole)
            throw UsageError("caliper3d render: --at places the eye of --view hole; the " +
                             verb.value("view") + " view shows the whole scene and ignores it");
        const auto pick = pickPixelFrom(p, width, height, "caliper3d render");
        LoadOptions options = inputOptionsFrom(p);
        options.colour = colourRequestFrom(p);
        checkChangeOptions(options, "render");
        PicturePlan plan{parseDepthInterval(verb), verb.value("depth"),
                         !downHole && !p.isSet("exaggerate"), height, options.radialExaggeration};

        double tolerance = 2.0;
        if (!io::parseNumber(verb.value("pixel-tolerance"), tolerance) ||
            !(tolerance >= 0.1 && tolerance <= 100.0))
            throw UsageError("caliper3d render: --pixel-tolerance takes pixels from 0.1 to 100");

        RenderSettings settings;
        settings.width = width;
        settings.height = height;
        settings.downHole = downHole;
        settings.view = view;
        settings.atSet = verb.isSet("at");
        settings.at = at;
        settings.atText = verb.value("at");
        settings.pick = pick;
        settings.options = options;
        settings.plan = plan;
        settings.tolerance = static_cast<float>(tolerance);
        settings.stats = verb.isSet("stats");
        const std::vector<WellSource> sources = wellSourcesFrom(p, verb.positional());
        const OutputNames names(verb.value("output"), ".png");
        SummaryFile summaries(verb.value("summary"));
        if (!names.perInput()) {
            std::vector<InputSummary> inputs;
            const int status = renderTo(sources, settings, names.spec(), inputs);
            for (const InputSummary& input : inputs) summaries.write(input);
            return status;
        }
        // One picture per well.
        std::vector<std::string> files;
        files.reserve(sources.size());
        for (const WellSource& source : sources) files.push_back(source.path);
        const std::vector<std::string> outs = names.forInputs(files, "-o");
        return writeEachInput(sources, outs, summaries,
                              [&settings](const WellSource& source, const std::string& out,
                                          std::vector<InputSummary>& one) {
                                  return renderTo({source}, settings, out, one);
                              });
    });
}

}  // namespace caliper3d::app
