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
#include "reconstruction/synthetic/synthetic_field.h"
#include "reconstruction/synthetic/synthetic_well.h"

namespace caliper3d::app {

namespace {

// The field's first wellhead (WGS 84, in the North Sea: UTM zone 31N) and the radii of
// curvature of the WGS 84 ellipsoid there, which turn the grid's metres into degrees.
constexpr double kFieldLatitude_deg = 60.5;
constexpr double kFieldLongitude_deg = 2.5;
constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;

// The header items that place a synthetic well: latitude and longitude (degrees, 8
// decimals: about 1 mm), the datum, and the kelly bushing and its elevation.
std::vector<io::LasParameter> fieldLocation(double north_m, double east_m, double elevation_m) {
    const double a = 6378137.0, f = 1.0 / 298.257223563, e2 = f * (2.0 - f);
    const double phi = kFieldLatitude_deg * kRadiansPerDegree;
    const double w = std::sqrt(1.0 - e2 * std::sin(phi) * std::sin(phi));
    const double meridian = a * (1.0 - e2) / (w * w * w);  // M
    const double normal = a / w;                           // N
    const double lat = kFieldLatitude_deg + north_m / meridian / kRadiansPerDegree;
    const double lon = kFieldLongitude_deg + east_m / (normal * std::cos(phi)) / kRadiansPerDegree;
    char latText[40], lonText[40], elevation[40];
    std::snprintf(latText, sizeof latText, "%.8f", lat);
    std::snprintf(lonText, sizeof lonText, "%.8f", lon);
    std::snprintf(elevation, sizeof elevation, "%.2f", elevation_m);
    return {{"LATI", "DEG", latText, "Latitude"},
            {"LONG", "DEG", lonText, "Longitude"},
            {"GDAT", "", "WGS84", "Geodetic datum"},
            {"LMF", "", "KB", "Log measured from"},
            {"EKB", "M", elevation, "Elevation of the kelly bushing"}};
}

// synth --field N: N wells of `length` metres, named FIELD-000, FIELD-001, ... (as their
// files well-000.las, ...), laid out by reconstruction::syntheticFieldWell (the profiles in
// turn, wellheads 25 m apart on a ring, each drilled away from its centre: no two cross), their
// latitude, longitude and kelly bushing elevation in the header (the field opens at its
// places), and DIR/manifest.csv listing them for caliper3d batch.
void writeField(const std::string& folder, std::size_t wells, double length, double step,
                int arms) {
    namespace fs = std::filesystem;
    fs::create_directories(folder);
    const std::size_t digits = std::max<std::size_t>(3, std::to_string(wells - 1).size());
    const std::string manifestPath = (fs::path(folder) / "manifest.csv").string();
    io::AtomicOutput manifestFile(manifestPath);
    std::ostream& manifest = manifestFile.stream();
    manifest << "file,verb,wellhead\n";
    std::size_t sections = 0;
    for (std::size_t w = 0; w < wells; ++w) {
        reconstruction::SyntheticFieldWell well =
            reconstruction::syntheticFieldWell(w, wells, length, step);
        well.spec.armCount = arms;
        std::string number = std::to_string(w);
        number.insert(0, digits - number.size(), '0');
        const std::string name = "well-" + number + ".las";
        // Each well its own name in the header (WELL), numbered as its file.
        const std::string wellName = "FIELD-" + number;
        io::LasWriteOptions las;
        las.wellName = wellName;
        las.parameters = fieldLocation(well.north_m, well.east_m, well.elevation_m);
        const io::SectionTable table = reconstruction::makeSyntheticWell(well.spec);
        io::writeLasFile((fs::path(folder) / name).string(), table, las);
        sections += table.rowCount();
        // No wellhead column value: each well is placed from its header.
        manifest << name << ",report,\n";
    }
    manifestFile.commit();
    std::printf("wrote %zu wells (%zu sections, %.1f m each) and %s\n", wells, sections, length,
                manifestPath.c_str());
}

}  // namespace

namespace {

// A second run of the same hole (docs/analysis.md, "Two runs of one well").
void addRunOptions(QCommandLineParser& p) {
    p.addOption({"gamma-ray",
                 "Also write a gamma-ray curve GR of the formation (the same for every run of "
                 "one profile and length)."});
    p.addOption({"depth-offset",
                 "Write a run whose depth counter reads this many metres deeper than the hole "
                 "(every feature, the path and the tool as at the true depth).",
                 "M", "0"});
    p.addOption({"tool-azimuth",
                 "Pad 1's azimuth at the top, degrees (a tool that sits differently in another "
                 "pass; default 0).",
                 "DEG", "0"});
    p.addOption({"widen",
                 "Every breakout, washout or key seat this many millimetres wider (a later run "
                 "after the hole grew; default 0).",
                 "MM", "0"});
}

void applyRunOptions(VerbParser& verb, reconstruction::SyntheticWellSpec& spec) {
    const auto number = [&verb](const char* name) {
        double v = 0.0;
        if (!io::parseNumber(verb.value(name), v) || !std::isfinite(v))
            throw UsageError(std::string("caliper3d synth: --") + name + " takes a number");
        return v;
    };
    spec.gammaRay = verb.isSet("gamma-ray");
    spec.depthOffset_m = number("depth-offset");
    spec.initialToolAzimuth_deg = number("tool-azimuth");
    const double widen = number("widen");
    for (reconstruction::SyntheticFeature& f : spec.features)
        if (f.kind != reconstruction::SyntheticFeature::Kind::Undergauge) {
            f.dmax_mm += widen;
            if (f.kind == reconstruction::SyntheticFeature::Kind::Washout) f.dmin_mm += widen;
        }
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
        p.addOption(
            {"field",
             "Write N wells instead of one, into the folder -o names (well-000.las, ...: "
             "the profiles in turn, wellheads 25 m apart on a ring by their headers' latitude "
             "and longitude, each drilled away from the ring's centre), with "
             "a manifest.csv for caliper3d batch.",
             "N"});
        addRunOptions(p);
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
        applyRunOptions(verb, spec);
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
