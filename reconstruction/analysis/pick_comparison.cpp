#include "reconstruction/analysis/pick_comparison.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "io/text.h"

namespace caliper3d::reconstruction {

bool isBreakoutPick(const std::string& type) {
    const std::string t = io::upper(io::trim(type));
    return t.empty() || t.find("BREAKOUT") != std::string::npos || t == "BO" || t == "BK";
}

namespace {

// The section nearest `md` (sections in depth order).
std::size_t nearestSection(const WellAnalysis& a, double md) {
    const std::size_t n = a.sections.size();
    std::size_t lo = 0, hi = n;
    while (lo < hi) {
        const std::size_t mid = (lo + hi) / 2;
        if (a.sections[mid].md_m < md)
            lo = mid + 1;
        else
            hi = mid;
    }
    if (lo == n) return n - 1;
    if (lo > 0 && md - a.sections[lo - 1].md_m < a.sections[lo].md_m - md) return lo - 1;
    return lo;
}

}  // namespace

PicksComparison comparePicks(const std::vector<io::Pick>& picks, const WellAnalysis& a) {
    PicksComparison out;
    std::vector<bool> zonePicked(a.zones.size(), false);
    for (const Zone& z : a.zones) out.caliperBreakoutZones += z.kind == BoreholeClass::Breakout;
    double sum = 0.0;
    for (const io::Pick& p : picks) {
        PickAgreement r;
        r.pick = p;
        r.breakout = isBreakoutPick(p.type);
        r.inLog = a.sections.size() > 0 && p.bottom_m >= a.sections[0].md_m &&
                  p.top_m <= a.sections[a.sections.size() - 1].md_m;
        if (!r.inLog) {
            ++out.outsideLog;
            out.picks.push_back(std::move(r));
            continue;
        }
        const SectionResult& s = a.sections[nearestSection(a, (p.top_m + p.bottom_m) / 2.0)];
        r.caliperClass = s.cls;
        r.caliperAzimuth_deg = s.majorAzimuth_deg;
        for (std::size_t z = 0; z < a.zones.size(); ++z) {
            const Zone& zone = a.zones[z];
            if (zone.top_m > p.bottom_m || zone.bottom_m < p.top_m) continue;
            r.zone = static_cast<int>(z);
            if (std::isfinite(zone.meanAzimuth_deg)) r.caliperAzimuth_deg = zone.meanAzimuth_deg;
            if (r.breakout && zone.kind == BoreholeClass::Breakout) zonePicked[z] = true;
            break;
        }
        if (r.breakout) {
            ++out.breakoutPicks;
            if (r.zone >= 0 &&
                a.zones[static_cast<std::size_t>(r.zone)].kind == BoreholeClass::Breakout)
                ++out.inCaliperBreakout;
            if (std::isfinite(r.caliperAzimuth_deg)) {
                r.difference_deg = io::axialDifference_deg(p.azimuth_deg, r.caliperAzimuth_deg);
                ++out.compared;
                sum += r.difference_deg;
                out.within20 += r.difference_deg <= 20.0;
            }
        }
        out.picks.push_back(std::move(r));
    }
    if (out.compared > 0) out.meanDifference_deg = sum / static_cast<double>(out.compared);
    out.caliperZonesPicked =
        static_cast<std::size_t>(std::count(zonePicked.begin(), zonePicked.end(), true));
    return out;
}

std::string formatPicksComparison(const PicksComparison& c, std::size_t lines) {
    std::string out;
    char line[320];
    std::snprintf(line, sizeof line,
                  "picks: %zu (%zu breakouts in the log, %zu outside it); %zu of the breakouts "
                  "lie in a caliper breakout zone; %zu of %zu caliper breakout zones picked\n",
                  c.picks.size(), c.breakoutPicks, c.outsideLog, c.inCaliperBreakout,
                  c.caliperZonesPicked, c.caliperBreakoutZones);
    out += line;
    if (c.compared > 0)
        std::snprintf(line, sizeof line,
                      "picks vs caliper azimuth: mean difference %.1f deg over %zu picks, %zu "
                      "within 20 deg\n",
                      c.meanDifference_deg, c.compared, c.within20);
    else
        std::snprintf(line, sizeof line,
                      "picks vs caliper azimuth: none compared (no caliper major-axis azimuth "
                      "at the picks' depths)\n");
    out += line;
    std::size_t shown = 0;
    for (const PickAgreement& r : c.picks) {
        if (shown++ == lines) {
            std::snprintf(line, sizeof line, "  (%zu more picks)\n", c.picks.size() - lines);
            out += line;
            break;
        }
        const std::string type = r.pick.type.empty() ? "pick" : r.pick.type;
        if (!r.inLog) {
            std::snprintf(line, sizeof line, "  %.2f-%.2f m %s %.0f deg: outside the log\n",
                          r.pick.top_m, r.pick.bottom_m, type.c_str(), r.pick.azimuth_deg);
        } else if (std::isfinite(r.difference_deg)) {
            std::snprintf(line, sizeof line,
                          "  %.2f-%.2f m %s %.0f deg: caliper %s, axis %.0f deg, difference "
                          "%.0f deg\n",
                          r.pick.top_m, r.pick.bottom_m, type.c_str(), r.pick.azimuth_deg,
                          std::string(className(r.caliperClass)).c_str(), r.caliperAzimuth_deg,
                          r.difference_deg);
        } else {
            std::snprintf(line, sizeof line, "  %.2f-%.2f m %s %.0f deg: caliper %s, %s\n",
                          r.pick.top_m, r.pick.bottom_m, type.c_str(), r.pick.azimuth_deg,
                          std::string(className(r.caliperClass)).c_str(),
                          r.breakout ? "no caliper azimuth" : "not a breakout: not compared");
        }
        out += line;
    }
    return out;
}

}  // namespace caliper3d::reconstruction
