#include "scenegraph/label_style.h"

#include <cstddef>
#include <cstdlib>
#include <string>
#include <string_view>

#include <Inventor/nodes/SoFont.h>

#include "scenegraph/main_thread.h"

namespace caliper3d::scenegraph {

void useRunTimeFontLibraries() {
    assertMainThread("useRunTimeFontLibraries");
    // setenv with overwrite 0 keeps what the user set.
    setenv("COIN_FREETYPE2_LIBNAME", "libfreetype.so.6", 0);
    setenv("COIN_FONTCONFIG_LIBNAME", "libfontconfig.so.1", 0);
}

SoFont* makeLabelFont(float size_px) {
    useRunTimeFontLibraries();
    auto* font = new SoFont;
    font->name = "DejaVu Sans:Bold";
    font->size = size_px;
    return font;
}

float textWidth_px(const std::string& text, float size_px) {
    float em = 0.0f;
    for (const char c : text) {
        if (std::string_view(" .,:;'|!ijl").find(c) != std::string_view::npos)
            em += 0.34f;
        else if (std::string_view("frt()[]/-").find(c) != std::string_view::npos)
            em += 0.43f;
        else if (std::string_view("mwMW").find(c) != std::string_view::npos)
            em += 1.0f;
        else if (c >= 'A' && c <= 'Z')
            em += 0.78f;
        else
            em += 0.64f;  // lower case and digits: 0.60 to 0.64 em
    }
    return em * size_px;
}

float boldTextWidth_px(const std::string& text, float size_px) {
    float em = 0.0f;
    for (const char c : text) {
        if (std::string_view(" .,:;'|!ijl").find(c) != std::string_view::npos)
            em += 0.40f;
        else if (std::string_view("frt()[]/-").find(c) != std::string_view::npos)
            em += 0.50f;
        else if (std::string_view("mwMW").find(c) != std::string_view::npos)
            em += 1.11f;
        else if (c >= 'A' && c <= 'Z')
            em += 0.86f;
        else
            em += 0.72f;  // lower case and digits: 0.59 to 0.72 em
    }
    return em * size_px;
}

ScreenBox labelBox(glm::vec2 baseline, const std::string& text, float size_px) {
    constexpr float kOutline_px = 1.0f;
    return {baseline.x - kOutline_px, baseline.y - kAscent_em * size_px - kOutline_px,
            baseline.x + boldTextWidth_px(text, size_px) + kOutline_px,
            baseline.y + kDescent_em * size_px + kOutline_px};
}

}  // namespace caliper3d::scenegraph
