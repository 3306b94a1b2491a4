#include "scenegraph/render_caching.h"

#include <cstdlib>
#include <cstring>
#include <mutex>
#include <stdexcept>

#include <GL/gl.h>

#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/nodes/SoCallback.h>
#include <Inventor/nodes/SoSeparator.h>

#include "io/text.h"
#include "scenegraph/offscreen_renderer.h"

namespace caliper3d::scenegraph {

namespace {

enum class Setting { Auto, On, Off };

Setting setting() {
    static const Setting value = [] {
        const char* text = std::getenv("CALIPER3D_RENDER_CACHING");
        if (text && std::strcmp(text, "on") == 0) return Setting::On;
        if (text && std::strcmp(text, "off") == 0) return Setting::Off;
        return Setting::Auto;
    }();
    return value;
}

std::mutex g_mutex;
std::string g_renderer;  // the first GL_RENDERER noted

void noteRenderer(void*, SoAction* action) {
    if (action->isOfType(SoGLRenderAction::getClassTypeId())) noteCurrentGlRenderer();
}

}  // namespace

bool isSoftwareRenderer(const std::string& glRenderer) {
    const std::string lower = io::lower(glRenderer);
    for (const char* name : {"llvmpipe", "softpipe", "swrast", "software"})
        if (lower.find(name) != std::string::npos) return true;
    return false;
}

bool renderCachingWanted() {
    switch (setting()) {
        case Setting::On:
            return true;
        case Setting::Off:
            return false;
        case Setting::Auto:
            break;
    }
    const std::lock_guard<std::mutex> lock(g_mutex);
    return !g_renderer.empty() && !isSoftwareRenderer(g_renderer);
}

int separatorRenderCaches(const std::string& glRenderer) {
    constexpr int kCoinsOwn = 2;  // SoSeparator's default
    switch (setting()) {
        case Setting::On:
            return kCoinsOwn;
        case Setting::Off:
            return 0;
        case Setting::Auto:
            break;
    }
    return isSoftwareRenderer(glRenderer) ? 0 : kCoinsOwn;
}

void noteCurrentGlRenderer() {
    std::string noted;
    {
        const std::lock_guard<std::mutex> lock(g_mutex);
        if (!g_renderer.empty()) return;
        const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
        if (!name || !*name) return;
        g_renderer = noted = name;
    }
    SoSeparator::setNumRenderCaches(separatorRenderCaches(noted));
}

std::string notedGlRenderer() {
    const std::lock_guard<std::mutex> lock(g_mutex);
    return g_renderer;
}

SoNode* makeRendererProbe() {
    auto* probe = new SoCallback;
    probe->setName("renderer_probe");
    probe->setCallback(noteRenderer, nullptr);
    return probe;
}

void probeOffscreenRenderer() {
    if (setting() == Setting::Off) SoSeparator::setNumRenderCaches(0);
    if (setting() != Setting::Auto || !notedGlRenderer().empty()) return;
    try {
        OffscreenRenderer renderer;
        auto* scene = new SoSeparator;
        scene->ref();
        scene->addChild(makeRendererProbe());
        const float black[3] = {0.0f, 0.0f, 0.0f};
        renderer.render(scene, 1, 1, black);
        scene->unref();
    } catch (const std::runtime_error&) {
        // No offscreen context here: the meshes stay uncached and the picture says why.
    }
}

}  // namespace caliper3d::scenegraph
