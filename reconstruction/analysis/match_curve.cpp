#include "reconstruction/analysis/match_curve.h"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace caliper3d::reconstruction {

namespace {

std::string upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

const io::ExtraCurve* findCurve(const io::SectionTable& t, const std::string& name) {
    for (const io::ExtraCurve& c : t.extraCurves)
        if (upper(c.mnemonic) == upper(name)) return &c;
    return nullptr;
}

const io::ExtraCurve* gammaRay(const io::SectionTable& t) {
    if (const io::ExtraCurve* exact = findCurve(t, "GR")) return exact;
    for (const io::ExtraCurve& c : t.extraCurves)
        if (upper(c.mnemonic).rfind("GR", 0) == 0) return &c;
    return nullptr;
}

bool isEquivalentDiameter(const std::string& name) {
    return upper(name) == upper(kEquivalentDiameterCurve);
}

}  // namespace

std::string chooseMatchCurve(const io::SectionTable& a, const io::SectionTable& b,
                             const std::string& asked) {
    if (!asked.empty()) {
        if (isEquivalentDiameter(asked)) return kEquivalentDiameterCurve;
        for (const io::SectionTable* t : {&a, &b})
            if (!findCurve(*t, asked))
                throw std::runtime_error(t->source + ": no curve '" + asked +
                                         "' to match depths on (--match-curve takes a curve both "
                                         "logs carry, or deq)");
        return findCurve(a, asked)->mnemonic;
    }
    const io::ExtraCurve* ga = gammaRay(a);
    const io::ExtraCurve* gb = gammaRay(b);
    if (ga && gb) return ga->mnemonic;
    return kEquivalentDiameterCurve;
}

DepthCurve matchCurveOf(const io::SectionTable& t, const WellAnalysis& analysis,
                        const std::string& name) {
    DepthCurve c;
    c.depth_m = t.depth_m;
    if (isEquivalentDiameter(name)) {
        c.values.reserve(analysis.sections.size());
        for (const SectionResult& s : analysis.sections)
            c.values.push_back(s.cls == BoreholeClass::Cased ? io::kNaN : s.equivalentDiameter_mm);
        return c;
    }
    const io::ExtraCurve* curve = findCurve(t, name);
    if (!curve && upper(name).rfind("GR", 0) == 0) curve = gammaRay(t);
    if (!curve) throw std::runtime_error(t.source + ": no curve '" + name + "'");
    c.values = curve->values;
    return c;
}

}  // namespace caliper3d::reconstruction
