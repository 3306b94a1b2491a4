#pragma once

#include <string>

class SoNode;

namespace caliper3d::scenegraph {

// Whether the static meshes built from now on go under separators whose render cache Coin
// compiles (segment_node_builder.h, cacheableShape). CALIPER3D_RENDER_CACHING=on or off says
// so outright; unset (or auto), it is on once an OpenGL context of a hardware driver has been
// seen and off until then or on a software one. Measured (docs/benchmarks.md, "Render
// caching"): on an NVIDIA H200 the cached meshes draw 1.5-2.5 x faster; on llvmpipe no faster,
// and they hold a second copy of the geometry.
bool renderCachingWanted();

// Whether `glRenderer` (GL_RENDERER) names a software rasteriser: Mesa's llvmpipe, softpipe
// or swrast, or any renderer that calls itself software.
bool isSoftwareRenderer(const std::string& glRenderer);

// How many render caches each SoSeparator may compile (SoSeparator::setNumRenderCaches) with
// `glRenderer` drawing: Coin's own 2, but none on a software rasteriser (CALIPER3D_RENDER_CACHING
// =on or off says so outright). Coin caches a separator by itself once it has drawn it
// unchanged (renderCaching AUTO); on llvmpipe the frame that compiles the caches took 39-44 ms
// against 27-28 ms for every other frame, cached or not (docs/benchmarks.md, "Render caching").
int separatorRenderCaches(const std::string& glRenderer);

// Notes the GL_RENDERER of the context current on this thread (main thread, a context
// current); the first noted renderer decides renderCachingWanted() and
// separatorRenderCaches(), which it applies.
void noteCurrentGlRenderer();
// The GL_RENDERER noted first, empty when none yet.
std::string notedGlRenderer();

// A node for the top of a window's scene that notes the renderer the first time it is drawn,
// before the wells' meshes are built (they are handed over after the window shows).
SoNode* makeRendererProbe();

// Makes an offscreen context once and notes its renderer, so that `render` builds its meshes
// knowing what will draw them. Does nothing when CALIPER3D_RENDER_CACHING says on or off, or
// when no offscreen context can be made (the picture says why later).
void probeOffscreenRenderer();

}  // namespace caliper3d::scenegraph
