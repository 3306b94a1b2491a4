#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/change_colouring.h"
#include "app/commands.h"
#include "app/each_input.h"
#include "app/input_options.h"
#include "app/input_summary.h"
#include "app/output_names.h"
#include "app/scene_assembly.h"
#include "app/verb_parser.h"
#include "reconstruction/load/load_well.h"
#include "scenegraph/iv_export.h"
#include "scenegraph/main_thread.h"
#include "scenegraph/mesh_export.h"

namespace caliper3d::app {

namespace {

constexpr const char* kAcceptedExtensions = ".iv, .iv.gz, .glb, .ply, .stl or .obj";

using Seconds = std::chrono::duration<double>;

// --progress: "progress DONE/TOTAL steps" lines on stderr as the export goes, for the window's
// progress bar (a step: a well read, a well built, the file written). Off: prints nothing.
class ProgressLines {
public:
    ProgressLines(bool on, int total) : m_on(on), m_total(total) { step(0); }
    void step(int done) const {
        if (!m_on) return;
        std::fprintf(stderr, "progress %d/%d steps\n", done, m_total);
        std::fflush(stderr);
    }

private:
    bool m_on;
    int m_total;
};

bool endsWith(const std::string& text, const std::string& tail) {
    return text.size() > tail.size() &&
           text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

// The Open Inventor export: the scene the window builds, or every level streamed.
int exportIv(const std::vector<WellSource>& sources, const LoadOptions& options,
             const std::string& out, bool full, const scenegraph::IvExportOptions& ivOptions,
             bool progress, std::vector<InputSummary>& inputs) {
    scenegraph::initCoin();
    const auto start = std::chrono::steady_clock::now();
    // Steps: the wells read, the scene built, the file written.
    const ProgressLines steps(progress, 3);
    AssembledScene scene =
        assembleScene(sources, options,
                      [&steps](std::vector<std::shared_ptr<const reconstruction::WellGeometry>>&,
                               double&) { steps.step(1); });
    inputs = scene.inputs;
    if (scene.wells == 0) return kExitBadInput;
    steps.step(2);
    const auto built = std::chrono::steady_clock::now();
    if (full) {
        std::vector<const reconstruction::WellGeometry*> wells;
        for (const auto& geometry : scene.geometries) wells.push_back(geometry.get());
        scenegraph::writeIvFullDetail(wells, out, ivOptions);
    } else {
        scenegraph::writeIv(scene.root.get(), out, ivOptions);
    }
    steps.step(3);
    const auto written = std::chrono::steady_clock::now();
    std::printf("wrote %s (%d well%s): read and built in %.2f s, written in %.2f s\n", out.c_str(),
                scene.wells, scene.wells == 1 ? "" : "s", Seconds(built - start).count(),
                Seconds(written - built).count());
    return scene.failures > 0 ? kExitBadInput : kExitOk;
}

// A mesh export: no Coin nodes, each well read, its segments meshed at one level into the
// writer, and the well freed before the next is read.
int exportMesh(const std::vector<WellSource>& sources, const LoadOptions& options,
               const std::string& out, scenegraph::MeshFormat format, bool full, bool binary,
               bool progress, std::vector<InputSummary>& inputs) {
    const auto start = std::chrono::steady_clock::now();
    // Steps: each well read, each well meshed, the file written.
    const int total = 2 * static_cast<int>(sources.size()) + 1;
    const ProgressLines steps(progress, total);
    int done = 0;
    const reconstruction::Wellhead origin = reconstruction::sceneOrigin(sources);
    scenegraph::MeshFileWriter writer(format, binary);
    const scenegraph::MeshDetail detail =
        full ? scenegraph::MeshDetail::Full : scenegraph::MeshDetail::Shown;
    int wells = 0, failures = 0;
    // Colour by change: the other run read once, each well compared with it.
    std::optional<ChangeReference> reference;
    if (coloursByChange(options)) reference.emplace(options);
    for (const WellSource& source : sources) {
        InputSummary& input = inputs.emplace_back();
        input.file = source.path;
        try {
            const reconstruction::LoadedWell loaded =
                reconstruction::loadWell(source, options, origin);
            input.rows = loaded.table->rowCount();
            if (input.rows > 0) {
                input.top_m = loaded.table->depth_m.front();
                input.bottom_m = loaded.table->depth_m.back();
            }
            input.addWarnings(loaded.diagnostics);
            steps.step(++done);
            // Drawn as asked (--colour-by, --exaggerate); each well over its own colour range,
            // as it is freed before the next is read.
            std::shared_ptr<const reconstruction::WallColouring> colouring;
            if (reference) {
                const reconstruction::RunChange change = reference->against(*loaded.geometry);
                input.compared = comparedRuns(change, reference->path());
                colouring =
                    reconstruction::changeColouring(*loaded.geometry, change, options.colour.range);
            } else {
                colouring = reconstruction::makeWallColouring(*loaded.geometry, options.colour);
            }
            const reconstruction::WellGeometry styled =
                loaded.geometry->restyled(options.radialExaggeration, colouring);
            writer.addWell(styled, std::filesystem::path(source.path).stem().string(), detail);
            steps.step(++done);
            ++wells;
            std::printf("%s: %zu sections, %zu segments, %zu warnings\n", source.path.c_str(),
                        loaded.table->rowCount(), loaded.geometry->segmentCount(),
                        loaded.diagnostics.warningCount);
            printWarnings(loaded.diagnostics);
        } catch (const scenegraph::MeshTooLarge& e) {
            throw std::runtime_error(std::string(e.what()) +
                                     "; --detail shown, or .iv with --detail full (written "
                                     "segment by segment), need far less");
        } catch (const std::exception& e) {
            ++failures;
            done = 2 * (wells + failures);
            std::fprintf(stderr, "caliper3d: %s\n", e.what());
            input.error = inputErrorFrom(e, source.path);
        }
    }
    if (wells == 0) return kExitBadInput;
    const scenegraph::MeshExportCounts counts = writer.counts();
    const auto built = std::chrono::steady_clock::now();
    writer.write(out);
    steps.step(total);
    const auto written = std::chrono::steady_clock::now();
    std::printf(
        "wrote %s (%d well%s, %zu meshes, %zu vertices, %zu triangles): read and built in "
        "%.2f s, written in %.2f s\n",
        out.c_str(), wells, wells == 1 ? "" : "s", counts.meshes, counts.vertices, counts.triangles,
        Seconds(built - start).count(), Seconds(written - built).count());
    return failures > 0 ? kExitBadInput : kExitOk;
}

// How an export writes, from its options and the output's name.
struct ExportSettings {
    LoadOptions load;
    bool full = false;
    bool ascii = false;
    bool gzip = false;
    bool progress = false;
};

// Exports `sources` into `out` (its name says the format); each source's summary line goes to
// `inputs`, failed where the export as a whole failed.
int exportTo(const std::vector<WellSource>& sources, const ExportSettings& settings,
             const std::string& out, std::vector<InputSummary>& inputs) {
    const double start = steadySeconds();
    const std::size_t first = inputs.size();
    int status = kExitBadInput;
    try {
        if (const std::optional<scenegraph::MeshFormat> mesh = scenegraph::meshFormatFor(out))
            status = exportMesh(sources, settings.load, out, *mesh, settings.full, !settings.ascii,
                                settings.progress, inputs);
        else {
            scenegraph::IvExportOptions ivOptions;
            ivOptions.binary = !settings.ascii;
            ivOptions.gzip = settings.gzip || endsWith(out, ".iv.gz");
            status = exportIv(sources, settings.load, out, settings.full, ivOptions,
                              settings.progress, inputs);
        }
    } catch (const UsageError&) {
        throw;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "caliper3d export: %s\n", e.what());
        inputs.resize(std::max(inputs.size(), first));
        for (std::size_t i = first; i < inputs.size(); ++i)
            if (!inputs[i].error) inputs[i].error = InputError{out, 0, e.what()};
        status = kExitBadInput;
    }
    // A well read but written nowhere (no well could be) is no success either.
    for (std::size_t i = first; i < inputs.size(); ++i) {
        InputSummary& input = inputs[i];
        input.verb = "export";
        if (!input.error && status != kExitOk && inputs.size() - first == 1)
            input.error = InputError{out, 0, "not written"};
        if (!input.error) input.outputs = {out};
        stampCost(input, start);
    }
    return status;
}

// The output's name as a format: throws UsageError for an extension that is none.
void checkExportName(const std::string& out, const VerbParser& verb) {
    const bool iv = endsWith(out, ".iv") || endsWith(out, ".iv.gz");
    const std::optional<scenegraph::MeshFormat> mesh = scenegraph::meshFormatFor(out);
    if (!iv && !mesh)
        throw UsageError("caliper3d export: the output must end in " +
                         std::string(kAcceptedExtensions) + ", got '" + out + "'");
    if (mesh && verb.isSet("gzip"))
        throw UsageError("caliper3d export: --gzip applies to .iv only");
    if (mesh && *mesh != scenegraph::MeshFormat::Stl &&
        (verb.isSet("ascii") || verb.isSet("binary")))
        throw UsageError(
            "caliper3d export: --ascii and --binary apply to .iv and .stl (.glb is always "
            "binary, .ply and .obj always text)");
}

}  // namespace

int runExport(const QStringList& args) {
    return guardedVerb("export", [&]() -> int {
        VerbParser verb(
            "export", "FILE... -o OUT|DIR/|PATTERN",
            "Export wells for other tools; the extension of OUT chooses the format.\n"
            "-o OUT puts every FILE in one scene; -o DIR/ (DIR/STEM.iv) or a pattern with "
            "{stem}, {name} or {index} (out/{stem}.glb) writes one file per FILE, a bad one not "
            "stopping the others (exit status 1).\n"
            ".iv, .iv.gz: an Open Inventor scene, each well's path and, per segment, an SoLOD. "
            "By default (--detail shown) its levels are the coarse ones the window loads up "
            "front (sections kept by shape error, 12-point rings and the raw N-gon; see "
            "--shape-tolerance). --detail full writes every level, full detail first, one "
            "segment at a time (memory holds one segment's nodes; the file is large: 2.9 GB "
            "for 4 km at 2.5 mm). Binary unless --ascii is given: every Inventor reader takes "
            "both, and text takes 4-5 times as long to write.\n"
            ".glb (glTF 2.0 binary, a node and a mesh per segment, per-vertex colours), .ply "
            "(text, per-vertex colours), .stl (no colours), .obj (colours only as the common "
            "'v x y z r g b' extension): the wall as triangles, one level per segment, in "
            "metres in the scene frame (x east, y up, z south from the first wellhead: glTF's "
            "own axes). --detail shown writes the finest coarse level (what the window shows "
            "up front: sections kept by shape error, 12-point rings); --detail full every "
            "section with the full spline. Each mesh library holds the whole file in memory "
            "before it writes it: --detail full of 4 km at 2.5 mm (154 M triangles) takes "
            "6.7 GB as .glb (a 3.4 GB file), and as .ply, .stl or .obj would take 46-84 GB, "
            "so it is refused when the estimate passes the machine's memory (.iv --detail full "
            "is written segment by segment). .stl is binary unless --ascii is given. See "
            "docs/formats.md, \"Mesh exports\".");
        QCommandLineParser& p = verb.parser();
        p.addOption({{"o", "output"},
                     "Output file: .iv, .iv.gz (gzip-compressed Inventor, as --gzip), .glb, "
                     ".ply, .stl or .obj.",
                     "OUT"});
        p.addOption({"ascii",
                     "Write text: Open Inventor (3 times the size and 4-5 times the writing "
                     "time of binary) or STL."});
        p.addOption({"binary", "Write binary Open Inventor or STL (the default)."});
        p.addOption(
            {"gzip", "Compress Open Inventor with gzip (implied by a name ending .iv.gz)."});
        p.addOption({"detail",
                     "shown (default): the coarse levels the window shows up front (.iv: every "
                     "coarse level; mesh formats: the finest of them). full: every section at "
                     "full detail (.iv: every level, streamed segment by segment; mesh formats: "
                     "the full level only, the whole file held in memory).",
                     "LEVELS", "shown"});
        p.addOption({"progress",
                     "Print 'progress DONE/TOTAL steps' lines on stderr as the export goes (a "
                     "step: a well read, a well built, the file written): the window's progress "
                     "bar reads them."});
        addInputOptions(p);
        addColourOptions(p);
        addWellSourceOptions(p);
        addSummaryOption(p);
        if (!verb.parse(args, 1)) return kExitOk;
        if (!verb.isSet("output")) throw UsageError("caliper3d export: -o OUT is required");
        const OutputNames names(verb.value("output"), ".iv");
        const std::string detail = verb.value("detail");
        if (detail != "shown" && detail != "full")
            throw UsageError("caliper3d export: --detail takes shown or full, got '" + detail +
                             "'");
        if (verb.isSet("ascii") && verb.isSet("binary"))
            throw UsageError("caliper3d export: give --ascii or --binary, not both");
        ExportSettings settings;
        settings.load = inputOptionsFrom(p);
        settings.load.colour = colourRequestFrom(p);
        checkChangeOptions(settings.load, "export");
        settings.full = detail == "full";
        settings.ascii = verb.isSet("ascii");
        settings.gzip = verb.isSet("gzip");
        settings.progress = verb.isSet("progress");
        const std::vector<WellSource> sources = wellSourcesFrom(p, verb.positional());
        SummaryFile summaries(verb.value("summary"));
        std::vector<InputSummary> inputs;
        if (!names.perInput()) {
            checkExportName(names.spec(), verb);
            const int status = exportTo(sources, settings, names.spec(), inputs);
            for (const InputSummary& input : inputs) summaries.write(input);
            return status;
        }
        // One file per well: each well its own scene.
        std::vector<std::string> files;
        files.reserve(sources.size());
        for (const WellSource& source : sources) files.push_back(source.path);
        const std::vector<std::string> outs = names.forInputs(files, "-o");
        for (const std::string& out : outs) checkExportName(out, verb);
        return writeEachInput(sources, outs, summaries,
                              [&settings](const WellSource& source, const std::string& out,
                                          std::vector<InputSummary>& one) {
                                  return exportTo({source}, settings, out, one);
                              });
    });
}

}  // namespace caliper3d::app
