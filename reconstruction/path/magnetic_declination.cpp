#include "reconstruction/path/magnetic_declination.h"

#include <GeographicLib/MagneticModel.hpp>

#include <cmath>
#include <cstdlib>
#include <exception>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#ifndef CALIPER3D_MAGNETIC_DIR
#define CALIPER3D_MAGNETIC_DIR "data/magnetic"
#endif

namespace caliper3d::reconstruction {

namespace {

struct ModelFile {
    const char* file;  // data/magnetic/FILE.wmm
    const char* name;  // as shown
    double from, to;   // years covered
};
constexpr ModelFile kModels[] = {
    {"wmm2015v2", "WMM2015v2", 2015.0, 2020.0},
    {"wmm2020", "WMM2020", 2020.0, 2025.0},
    {"wmm2025", "WMM2025", 2025.0, 2030.0},
};

// Each model read once per process (a few kilobytes), shared by every thread.
const GeographicLib::MagneticModel& loadedModel(const ModelFile& m) {
    static std::mutex mutex;
    static std::map<std::string, std::unique_ptr<GeographicLib::MagneticModel>> models;
    const std::lock_guard<std::mutex> lock(mutex);
    std::unique_ptr<GeographicLib::MagneticModel>& model = models[m.file];
    if (!model)
        model = std::make_unique<GeographicLib::MagneticModel>(m.file, magneticModelDirectory());
    return *model;
}

std::string fixed(double v, int decimals) {
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
    return buffer;
}

}  // namespace

std::string magneticModelDirectory() {
    if (const char* dir = std::getenv("CALIPER3D_MAGNETIC_DIR"); dir && *dir) return dir;
    return CALIPER3D_MAGNETIC_DIR;
}

ModelDeclination modelDeclination(double latitude_deg, double longitude_deg, double year,
                                  double height_m) {
    ModelDeclination out;
    out.deg = std::nan("");
    if (!std::isfinite(latitude_deg) || !std::isfinite(longitude_deg)) {
        out.why = "no latitude and longitude in the header";
        return out;
    }
    if (!std::isfinite(year)) {
        out.why = "no log date in the header";
        return out;
    }
    if (std::fabs(latitude_deg) > 90.0 || std::fabs(longitude_deg) > 360.0) {
        out.why = "latitude " + fixed(latitude_deg, 4) + ", longitude " + fixed(longitude_deg, 4) +
                  " lie off the globe";
        return out;
    }
    const ModelFile* chosen = nullptr;
    for (const ModelFile& m : kModels)
        if (year >= m.from && (year < m.to || (year == m.to && &m == std::end(kModels) - 1)))
            chosen = &m;
    if (!chosen) {
        out.why = "the log's date (" + fixed(year, 2) +
                  ") lies outside the World Magnetic Models shipped (2015.0 to 2030.0)";
        return out;
    }
    try {
        const GeographicLib::MagneticModel& model = loadedModel(*chosen);
        double bx = 0.0, by = 0.0, bz = 0.0, h = 0.0, f = 0.0, d = 0.0, i = 0.0;
        model(year, latitude_deg, longitude_deg, height_m, bx, by, bz);
        GeographicLib::MagneticModel::FieldComponents(bx, by, bz, h, f, d, i);
        out.deg = d;
        out.model = chosen->name;
    } catch (const std::exception& e) {
        out.why = std::string("the magnetic model could not be read: ") + e.what();
    }
    return out;
}

}  // namespace caliper3d::reconstruction
