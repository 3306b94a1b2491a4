#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <optional>

#include <QApplication>
#include <QTimer>

#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/nodes/SoCallback.h>
#include <Inventor/nodes/SoSeparator.h>

#include "app/batch_manifest.h"
#include "app/commands.h"
#include "app/desktop/desk_model.h"
#include "app/desktop/gui_session.h"
#include "app/desktop/main_window.h"
#include "app/desktop/well_session.h"
#include "app/input_options.h"
#include "app/manifest_wells.h"
#include "app/scene_assembly.h"
#include "app/verb_parser.h"
#include "io/number_parsing.h"
#include "scenegraph/camera_setup.h"
#include "scenegraph/colour_legend.h"
#include "scenegraph/iv_export.h"
#include "scenegraph/main_thread.h"
#include "scenegraph/node_ref.h"
#include "scenegraph/offscreen_renderer.h"
#include "scenegraph/picture/picture.h"
#include "scenegraph/picture/png_file.h"
#include "scenegraph/render_stats.h"
#include "scenegraph/well_scene.h"

namespace caliper3d::app {

namespace {

// A well the window opens, with its own options (a manifest's rows may differ).
struct WellToOpen {
    WellSource source;
    LoadOptions options;
};

// view --stats: when the window first drew a frame with a well in it, when every well was
// loaded and when it settled (WellSession::settled), from the start of the verb, the peak
// memory, and when the window asked for its wells (Qt and the main window made); printed on
// one line once all are known, then the window closes (a benchmark's run). The frame is caught by a
// callback node at the end of the scene, traversed by every render of the viewer.
class WindowTimings {
public:
    WindowTimings(const WellSession& session, std::chrono::steady_clock::time_point start)
        : m_session(session), m_start(start) {}

    // The window is about to open its wells: the open the first picture is timed from.
    void opening() { m_open_ms = msSinceStart(); }
    // Hangs the callback at the end of `root` (after the wells it shows are opened).
    void watch(SoSeparator* root) {
        auto* probe = new SoCallback;
        probe->setCallback(&WindowTimings::traversed, this);
        root->addChild(probe);
    }
    void loaded() {
        if (!m_complete_ms) m_complete_ms = msSinceStart();
        // The peak is read once the wells are analysed and those held lean have let go of
        // their rows (WellSession::settled), polled.
        m_settle.setInterval(20);
        QObject::connect(&m_settle, &QTimer::timeout, [this] {
            if (!m_session.settled()) return;
            m_settle.stop();
            m_settled_ms = msSinceStart();
            reportWhenKnown();
        });
        m_settle.start();
    }

private:
    static void traversed(void* self, SoAction* action) {
        if (action->isOfType(SoGLRenderAction::getClassTypeId()))
            static_cast<WindowTimings*>(self)->drawn();
    }
    void drawn() {
        if (!m_complete_ms) ++m_framesLoading;
        if (m_firstPicture_ms) return;
        for (std::size_t i = 0; i < m_session.wellCount(); ++i)
            if (const scenegraph::WellScene* scene = m_session.scene(i);
                scene && scene->segmentCount() > 0) {
                m_firstPicture_ms = msSinceStart();
                // Not from inside the render: once it has ended.
                QTimer::singleShot(0, [this] { reportWhenKnown(); });
                return;
            }
    }
    void reportWhenKnown() {
        if (!m_firstPicture_ms || !m_complete_ms || !m_settled_ms || m_reported) return;
        m_reported = true;
        std::printf(
            "first_picture_ms=%.0f complete_ms=%.0f settled_ms=%.0f rss_mb=%.0f "
            "frames_loading=%d open_ms=%.0f\n",
            *m_firstPicture_ms, *m_complete_ms, *m_settled_ms, scenegraph::peakRss_mb(),
            m_framesLoading, m_open_ms);
        std::fflush(stdout);
        QTimer::singleShot(0, [] { QApplication::quit(); });
    }
    double msSinceStart() const {
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - m_start)
            .count();
    }

    const WellSession& m_session;
    std::chrono::steady_clock::time_point m_start;
    std::optional<double> m_firstPicture_ms, m_complete_ms, m_settled_ms;
    double m_open_ms = 0.0;
    bool m_reported = false;
    int m_framesLoading = 0;
    QTimer m_settle;
};

int showWindow(int argc, char** argv, const std::vector<WellToOpen>& wells,
               std::optional<double> at_m = std::nullopt, bool exaggerationGiven = false,
               int status = kExitOk, bool runs = false,
               std::optional<std::chrono::steady_clock::time_point> statsFrom = std::nullopt) {
    QApplication application(argc, argv);
    initGui();
    MainWindow window;
    window.show();
    WellSession& session = window.session();
    std::optional<WindowTimings> timings;
    if (statsFrom) {
        timings.emplace(session, *statsFrom);
        QObject::connect(&session, &WellSession::allWellsLoaded, [&timings] { timings->loaded(); });
    }
    if (exaggerationGiven) session.keepExaggeration();
    QObject::connect(&session, &WellSession::wellFailed,
                     [&](const QString&, const QString& message) {
                         std::fprintf(stderr, "caliper3d: %s\n", message.toLocal8Bit().constData());
                         status = kExitBadInput;
                     });
    if (at_m)  // once the first well is analysed, so that every view has it to show
        QObject::connect(&session, &WellSession::wellAnalysed, &window, [&window, at_m](int well) {
            if (well == 0) window.model().setCurrent(0, *at_m);
        });
    if (timings) timings->opening();
    const int first = session.openWell(wells.front().source, wells.front().options);
    for (std::size_t i = 1; i < wells.size(); ++i) {
        if (runs)
            session.addRun(wells[i].source, wells[i].options, first);
        else
            session.addWell(wells[i].source, wells[i].options);
    }
    if (timings) timings->watch(session.sceneRoot());
    // The first frame can stay black until something changes: redraw once shown.
    QTimer::singleShot(100, &window, [&window] { window.update(); });
    const int rc = application.exec();
    return rc != 0 ? rc : status;
}

// The bundled example well (written by 'caliper3d synth' at build time), or $CALIPER3D_EXAMPLE.
std::string exampleWellPath() {
    if (const char* env = std::getenv("CALIPER3D_EXAMPLE")) return env;
    return CALIPER3D_EXAMPLE_WELL;
}

constexpr double kExampleBreakout_m = 70.0;  // the middle of the example's breakout (60-80 m)

// The example's pictures with no display: the scene and its legend, no labels.
void writeBarePicture(SoSeparator* root, const reconstruction::ColourLegend* legend,
                      const std::string& path, int width, int height) {
    if (legend) root->addChild(scenegraph::makeColourLegend(*legend, height));
    scenegraph::OffscreenRenderer renderer;
    scenegraph::writePng(renderer.render(root, width, height, scenegraph::kBackgroundColour), path);
}

LoadOptions exampleOptions() {
    LoadOptions options;
    options.read.bitSize_mm = 215.9;  // the example is drilled with an 8.5 in bit
    return options;
}

}  // namespace

int runView(int argc, char** argv, const QStringList& args) {
    const auto start = std::chrono::steady_clock::now();
    return guardedVerb("view", [&]() -> int {
        VerbParser verb("view", "FILE... | --manifest MANIFEST [FILE...]",
                        "Open wells in the 3D viewer: the FILEs, and every row of a batch\n"
                        "manifest (each with its row's options over the command line's).");
        addInputOptions(verb.parser());
        addColourOptions(verb.parser());
        addWellSourceOptions(verb.parser());
        verb.parser().addOption(
            {"at", "Measured depth (m) the views open at in the first well (the nearest section).",
             "MD"});
        verb.parser().addOption(
            {"runs",
             "The FILEs are runs of one well (logged on different days or by different tools): "
             "they open as one well, the first its main run, the others grouped under it, "
             "depth-matched to it and shown beside it in the section inspector and the log "
             "track (--compare-with RUN: FILE and RUN so)."});
        verb.parser().addOption({"manifest",
                                 "A batch manifest (CSV or JSON, docs/formats.md): open the well "
                                 "of every row, after the FILEs.",
                                 "MANIFEST"});
        verb.parser().addOption(
            {"stats",
             "For benchmarks: print one line, first_picture_ms (the first frame drawn with a "
             "well in it) complete_ms (every well loaded), both from the start, settled_ms "
             "(every well analysed or held lean), rss_mb (peak), frames_loading (the frames "
             "drawn before complete_ms) and open_ms (when the window, once made, opened the "
             "wells), then close the window."});
        if (!verb.parse(args, 0)) return kExitOk;
        if (verb.positional().empty() && !verb.isSet("manifest"))
            throw UsageError("caliper3d view: give FILE... or --manifest MANIFEST");
        std::optional<double> at;
        if (verb.isSet("at")) {
            double md = 0.0;
            if (!io::parseNumber(verb.value("at"), md) || !std::isfinite(md))
                throw UsageError("caliper3d view: --at takes a measured depth in metres, not '" +
                                 verb.value("at") + "'");
            at = md;
        }
        LoadOptions options = inputOptionsFrom(verb.parser());
        options.colour = colourRequestFrom(verb.parser());
        // --compare-with RUN opens RUN as another run of the one FILE's well.
        bool runs = verb.isSet("runs");
        std::vector<std::string> files = verb.positional();
        if (!options.colour.compareWith.empty()) {
            if (files.size() != 1 || verb.isSet("manifest"))
                throw UsageError(
                    "caliper3d view: --compare-with RUN opens RUN as a run of FILE's well: give "
                    "one FILE (or FILE... --runs)");
            files.push_back(options.colour.compareWith);
            options.colour.compareWith.clear();
            runs = true;
        }
        if (runs && (files.size() < 2 || verb.isSet("manifest")))
            throw UsageError(
                "caliper3d view: --runs takes two or more FILEs, the runs of one well");
        if (options.colour.quantity == reconstruction::kChangeQuantity && !runs)
            throw UsageError(
                "caliper3d view: --colour-by change needs the well's runs: "
                "FILE... --runs, or --compare-with RUN");
        std::vector<WellToOpen> wells;
        if (!files.empty())
            for (const WellSource& source : wellSourcesFrom(verb.parser(), files))
                wells.push_back({source, options});
        int status = kExitOk;
        if (verb.isSet("manifest")) {
            const Manifest manifest = readManifest(verb.value("manifest"));
            // A row that cannot be opened is named and skipped; the others open.
            for (const ManifestWell& well : manifestWells(manifest, options)) {
                if (!well.problem.empty()) {
                    std::fprintf(stderr, "caliper3d view: %s: %s\n", manifest.path.c_str(),
                                 well.problem.c_str());
                    status = kExitBadInput;
                    continue;
                }
                for (const std::string& option : well.ignored)
                    std::fprintf(stderr,
                                 "caliper3d view: %s line %zu: %s is for the batch's verbs; the "
                                 "window does not use it\n",
                                 manifest.path.c_str(), well.line, option.c_str());
                wells.push_back({well.source, well.options});
            }
            if (wells.empty()) {
                std::fprintf(stderr, "caliper3d view: %s: no well to open\n",
                             manifest.path.c_str());
                return kExitBadInput;
            }
        }
        if (!haveDisplay()) {
            std::fprintf(
                stderr,
                "caliper3d view: no display; use 'caliper3d render' or 'caliper3d export'\n");
            return kExitUsage;
        }
        std::optional<std::chrono::steady_clock::time_point> statsFrom;
        if (verb.isSet("stats")) statsFrom = start;
        return showWindow(argc, argv, wells, at, verb.isSet("exaggerate"), status, runs, statsFrom);
    });
}

int runDefault(int argc, char** argv) {
    const std::string example = exampleWellPath();
    if (!std::filesystem::exists(example)) {
        std::fprintf(stderr,
                     "caliper3d: the bundled example %s is missing; rebuild, or run 'caliper3d "
                     "synth -o FILE'\n",
                     example.c_str());
        return kExitBadInput;
    }
    if (haveDisplay())  // at the example's breakout, where every view has something to show
        return showWindow(argc, argv, {{WellSource{example, {}, {}, {}}, exampleOptions()}},
                          kExampleBreakout_m);
    try {
        scenegraph::initCoin();
        std::filesystem::create_directories("out");
        AssembledScene scene = assembleScene({example}, exampleOptions());
        if (scene.wells == 0) return kExitBadInput;
        scenegraph::writeIv(scene.root.get(), "out/example.iv");
        // Looking down the hole from just above the example's breakout (60-80 m):
        // the elongated lobes show in colour; a whole-well view is a thin line.
        auto hole = scenegraph::makeRef(scenegraph::makeRenderRoot(
            scene.root.get(), scenegraph::downHolePose(*scene.geometries.front(), 59.0)));
        scenegraph::refineForCamera(scene.pictureWells(), hole.get(), 768);  // detail near the eye
        writeBarePicture(hole.get(), scene.legend(), "out/example.png", 1024, 768);
        // And the whole well, sections drawn 50 times larger so it is more than a line: the
        // same geometry restyled, not the file read again.
        const reconstruction::WellGeometry& loaded = *scene.geometries.front();
        const reconstruction::WellGeometry whole =
            loaded.restyled(50.0, loaded.options().colouring);
        scenegraph::WellScene overview;
        overview.buildAll(whole);
        auto overviewRoot = scenegraph::makeRef(
            scenegraph::makeRenderRoot(overview.root(), scenegraph::ViewDirection::Iso, 600, 900));
        writeBarePicture(overviewRoot.get(), scene.legend(), "out/example-overview.png", 600, 900);
        const auto here = std::filesystem::current_path();
        std::printf(
            "No display: rendered the example well instead of opening a window.\n"
            "  scene:    %s\n  picture:  %s\n  overview: %s\n",
            (here / "out/example.iv").c_str(), (here / "out/example.png").c_str(),
            (here / "out/example-overview.png").c_str());
        return kExitOk;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "caliper3d: %s\n", e.what());
        return kExitBadInput;
    }
}

}  // namespace caliper3d::app
