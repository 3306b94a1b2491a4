#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>

#include "app/commands.h"
#include "app/input_options.h"
#include "app/verb_parser.h"
#include "io/column_text_writer.h"
#include "io/las_writer.h"
#include "io/number_parsing.h"
#include "reconstruction/synthetic/synthetic_well.h"

namespace caliper3d::app {

int runSynth(const QStringList& args) {
    return guardedVerb("synth", [&]() -> int {
        VerbParser verb("synth", "-o OUT", "Write a synthetic caliper log with known features.");
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
        reconstruction::SyntheticWellSpec spec;
        try {
            spec = reconstruction::syntheticProfile(verb.value("profile"), length, step);
        } catch (const std::invalid_argument& e) {
            throw UsageError(std::string("caliper3d synth: ") + e.what() + "; the profiles are " +
                             names);
        }
        double arms = 0;
        if (!io::parseNumber(verb.value("arms"), arms) || arms < io::kMinArms ||
            arms > io::kMaxArms || arms != std::floor(arms))
            throw UsageError("caliper3d synth: --arms takes a whole number from 2 to 256");
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
