#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/input_options.h"
#include "app/verb_parser.h"
#include "io/atomic_output.h"
#include "io/column_text_writer.h"
#include "io/las_writer.h"
#include "io/number_parsing.h"
#include "reconstruction/synthetic/synthetic_well.h"

namespace caliper3d::app {

namespace {

// synth --field N: N wells of `length` metres, named FIELD-000, FIELD-001, ... (as their
// files well-000.las, ...), each a profile in turn (their hole azimuths
// turned 37 degrees a well, so no two builds point alike), wellheads 25 m apart on a square
// grid, and DIR/manifest.csv listing them for caliper3d batch.
void writeField(const std::string& folder, std::size_t wells, double length, double step,
                int arms) {
    namespace fs = std::filesystem;
    fs::create_directories(folder);
    const std::vector<std::string> profiles = reconstruction::syntheticProfileNames();
    const std::size_t columns =
        std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(std::sqrt(double(wells)))));
    const int digits = std::max(3, static_cast<int>(std::to_string(wells - 1).size()));
    const std::string manifestPath = (fs::path(folder) / "manifest.csv").string();
    io::AtomicOutput manifestFile(manifestPath);
    std::ostream& manifest = manifestFile.stream();
    manifest << "file,verb,wellhead\n";
    std::size_t sections = 0;
    for (std::size_t w = 0; w < wells; ++w) {
        const std::string& profile = profiles[w % profiles.size()];
        reconstruction::SyntheticWellSpec spec =
            reconstruction::syntheticProfile(profile, length, step);
        spec.armCount = arms;
        spec.holeAzimuth_deg = std::fmod(spec.holeAzimuth_deg + 37.0 * double(w), 360.0);
        char name[64], wellName[64];
        std::snprintf(name, sizeof name, "well-%0*zu.las", digits, w);
        // Each well its own name in the header (WELL), numbered as its file.
        std::snprintf(wellName, sizeof wellName, "FIELD-%0*zu", digits, w);
        io::LasWriteOptions las;
        las.wellName = wellName;
        const io::SectionTable table = reconstruction::makeSyntheticWell(spec);
        io::writeLasFile((fs::path(folder) / name).string(), table, las);
        sections += table.rowCount();
        const std::size_t gridColumn = w % columns, gridRow = w / columns;
        char line[160];
        std::snprintf(line, sizeof line, "%s,report,\"%.1f,%.1f,0\"\n", name,
                      25.0 * static_cast<double>(gridColumn), 25.0 * static_cast<double>(gridRow));
        manifest << line;
    }
    manifestFile.commit();
    std::printf("wrote %zu wells (%zu sections, %.1f m each) and %s\n", wells, sections, length,
                manifestPath.c_str());
}

}  // namespace

int runSynth(const QStringList& args) {
    return guardedVerb("synth", [&]() -> int {
        VerbParser verb("synth", "-o OUT | --field N -o DIR/",
                        "Write a synthetic caliper log with known features, or a field of them.");
        QCommandLineParser& p = verb.parser();
        p.addOption({{"o", "output"},
                     "Output log: LAS 2.0 when the name ends in .las, otherwise named column text "
                     "(depth R1..RN P1AZ DEVI HAZI RB BS).",
                     "OUT"});
        p.addOption({"arms", "Caliper arms, 2 to 256 (default 6; 2 = one diameter).", "N", "6"});
        p.addOption({"length", "Well length in metres (default 300).", "M", "300"});
        p.addOption({"step", "Sampling step in metres (default 0.05).", "M", "0.05"});
        std::string names;
        for (const std::string& n : reconstruction::syntheticProfileNames())
            names += (names.empty() ? "" : ", ") + n;
        p.addOption({"profile",
                     QString::fromStdString("Profile, one of " + names +
                                            " (default example; their exact answers are listed "
                                            "in docs/analysis.md)."),
                     "NAME", "example"});
        p.addOption({"field",
                     "Write N wells instead of one, into the folder -o names (well-000.las, ...: "
                     "the profiles in turn, hole azimuths varied, wellheads 25 m apart), with "
                     "a manifest.csv for caliper3d batch.",
                     "N"});
        if (!verb.parse(args, 0)) return kExitOk;
        if (!verb.isSet("output")) throw UsageError("caliper3d synth: -o OUT is required");
        double length = 0, step = 0;
        if (!io::parseNumber(verb.value("length"), length) || !(length > 0))
            throw UsageError("caliper3d synth: --length takes a positive number of metres");
        if (!io::parseNumber(verb.value("step"), step) || !(step > 0) || step >= length)
            throw UsageError(
                "caliper3d synth: --step takes a positive number of metres below --length");
        if (length / step > 5e7)
            throw UsageError("caliper3d synth: more than 50 million sections asked for");
        double arms = 0;
        if (!io::parseNumber(verb.value("arms"), arms) || arms < io::kMinArms ||
            arms > io::kMaxArms || arms != std::floor(arms))
            throw UsageError("caliper3d synth: --arms takes a whole number from 2 to 256");
        if (verb.isSet("field")) {
            bool ok = false;
            const int wells = p.value("field").toInt(&ok);
            if (!ok || wells < 1 || wells > 100000)
                throw UsageError("caliper3d synth: --field takes a whole number from 1 to 100000");
            if (verb.isSet("profile"))
                throw UsageError(
                    "caliper3d synth: --field uses every profile in turn; drop "
                    "--profile");
            writeField(verb.value("output"), static_cast<std::size_t>(wells), length, step,
                       static_cast<int>(arms));
            return kExitOk;
        }
        reconstruction::SyntheticWellSpec spec;
        try {
            spec = reconstruction::syntheticProfile(verb.value("profile"), length, step);
        } catch (const std::invalid_argument& e) {
            throw UsageError(std::string("caliper3d synth: ") + e.what() + "; the profiles are " +
                             names);
        }
        spec.armCount = static_cast<int>(arms);
        const io::SectionTable table = reconstruction::makeSyntheticWell(spec);
        const std::string out = verb.value("output");
        const std::string ext = std::filesystem::path(out).extension().string();
        if (ext == ".las" || ext == ".LAS")
            io::writeLasFile(out, table);
        else
            io::writeColumnTextFile(out, table);
        std::printf("wrote %s (%zu sections, %.1f m, profile %s)\n", out.c_str(), table.rowCount(),
                    length, verb.value("profile").c_str());
        return kExitOk;
    });
}

}  // namespace caliper3d::app
