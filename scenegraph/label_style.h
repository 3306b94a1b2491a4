#pragma once

#include <cstddef>
#include <string>

#include <glm/vec2.hpp>

#include "scenegraph/label_placement.h"

class SoFont;

namespace caliper3d::scenegraph {

// How text drawn into the scene looks: labels of depth ticks and wells, and the overlay's
// caption. SoText2 draws at a fixed size in pixels, on screen and in pictures alike.
constexpr float kLabelSize_px = 14.0f;
constexpr float kNameSize_px = 16.0f;
// Light text on the dark background (camera_setup.h, kBackgroundColour).
constexpr float kLabelColour[3] = {0.92f, 0.92f, 0.86f};
constexpr float kNameColour[3] = {1.0f, 0.82f, 0.35f};
constexpr float kTickColour[3] = {0.78f, 0.80f, 0.84f};
// The leader from a well to its name placed apart: the name's colour, dimmed.
constexpr float kLeaderColour[3] = {0.72f, 0.59f, 0.25f};

// A bold sans-serif label font. Coin draws SoFont's default font from a thin built-in
// bitmap; a named font goes through FreeType and fontconfig, which Coin loads at run time
// (docs/architecture.md, "Annotations"), and falls back to the built-in one without them.
SoFont* makeLabelFont(float size_px = kLabelSize_px);

// Coin opens FreeType and fontconfig by the development symlinks' names (libfreetype.so,
// libfontconfig.so), which a machine without their -dev packages lacks: it is pointed at
// the run-time libraries instead, unless the user named others
// (COIN_FREETYPE2_LIBNAME, COIN_FONTCONFIG_LIBNAME). Coin reads these when it draws its first
// text; makeLabelFont calls this. Main thread only.
void useRunTimeFontLibraries();

// Pixels `text` takes across in DejaVu Sans (what "Sans" finds) at `size_px`: its advance
// widths by class of character, rounded up (narrow punctuation, i and l; f, r, t and
// brackets; m, w, M and W; other capitals; the rest), for laying out panels of text.
float textWidth_px(const std::string& text, float size_px);

// The same in DejaVu Sans Bold (what the labels' font finds), the widest of each class.
float boldTextWidth_px(const std::string& text, float size_px);

// DejaVu Sans, in em: capitals and digits stand this high on the baseline, ascenders (b, d,
// l) a little higher, descenders (g, p, y) reach this far below it.
constexpr float kCapHeight_em = 0.73f;
constexpr float kAscent_em = 0.76f;
constexpr float kDescent_em = 0.24f;
// The pixels a label covers when SoText2 draws `text` (as drawn, leading space included) at
// `size_px` from `baseline` (the left end of its baseline, pixels from the picture's top-left
// corner): boldTextWidth_px across, ascenders to descenders up and down, and the pixel of
// outline a picture draws round it.
ScreenBox labelBox(glm::vec2 baseline, const std::string& text, float size_px);

}  // namespace caliper3d::scenegraph
