#pragma once

#include <optional>
#include <string>
#include <utility>

#include <QCommandLineParser>

#include "app/scene_assembly.h"

class SoNode;

namespace caliper3d::app {

// A pixel of a picture: x right, y down from the top left corner.
using PickPixel = std::pair<int, int>;

// Adds --pick X,Y to a verb that draws a picture.
void addPickOption(QCommandLineParser& parser);
// --pick's pixel, if given, within a width x height picture; throws UsageError (naming
// `verb`, e.g. "caliper3d render") when malformed or outside the picture.
std::optional<PickPixel> pickPixelFrom(const QCommandLineParser& parser, int width, int height,
                                       const std::string& verb);

// What --pick prints for `pixel` of the width x height picture of `renderRoot` (a root made
// by scenegraph::makeRenderRoot over scene.root, refined as drawn): "picked=X,Y" and
// scenegraph::formatSectionPick's lines, every well analysed as `caliper3d report` analyses it
// with its default rules; or "nothing picked at X,Y".
std::string describePick(const AssembledScene& scene, SoNode* renderRoot, int width, int height,
                         const PickPixel& pixel);

}  // namespace caliper3d::app
