#include "scenegraph/label_style.h"

#include <cstddef>
#include <cstdlib>

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

float labelWidth_px(std::size_t characters, float size_px) {
    // DejaVu Sans Bold's widest digits and letters are about 0.7 em.
    return 0.7f * size_px * static_cast<float>(characters);
}

}  // namespace caliper3d::scenegraph
