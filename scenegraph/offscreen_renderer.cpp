#include "scenegraph/offscreen_renderer.h"

#include <algorithm>
#include <chrono>

#include <cstring>
#include <stdexcept>

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/elements/SoGLCacheContextElement.h>

#include "scenegraph/main_thread.h"

#ifndef EGL_PLATFORM_SURFACELESS_MESA
#define EGL_PLATFORM_SURFACELESS_MESA 0x31DD
#endif

namespace caliper3d::scenegraph {

std::size_t RenderedImage::nonBackgroundPixels() const {
    if (rgba.size() < 4) return 0;
    std::size_t count = 0;
    for (std::size_t i = 0; i + 3 < rgba.size(); i += 4)
        if (std::memcmp(&rgba[i], &rgba[0], 3) != 0) ++count;
    return count;
}

struct OffscreenRenderer::Context {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    uint32_t cacheContext = 0;
    PFNGLGENFRAMEBUFFERSPROC genFramebuffers = nullptr;
    PFNGLBINDFRAMEBUFFERPROC bindFramebuffer = nullptr;
    PFNGLDELETEFRAMEBUFFERSPROC deleteFramebuffers = nullptr;
    PFNGLGENRENDERBUFFERSPROC genRenderbuffers = nullptr;
    PFNGLBINDRENDERBUFFERPROC bindRenderbuffer = nullptr;
    PFNGLRENDERBUFFERSTORAGEPROC renderbufferStorage = nullptr;
    PFNGLFRAMEBUFFERRENDERBUFFERPROC framebufferRenderbuffer = nullptr;
    PFNGLCHECKFRAMEBUFFERSTATUSPROC checkFramebufferStatus = nullptr;
    PFNGLDELETERENDERBUFFERSPROC deleteRenderbuffers = nullptr;

    ~Context() {
        if (display != EGL_NO_DISPLAY) {
            eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            if (context != EGL_NO_CONTEXT) eglDestroyContext(display, context);
            eglTerminate(display);
        }
    }
};

namespace {
template <typename F>
F load(const char* name) {
    auto f = reinterpret_cast<F>(eglGetProcAddress(name));
    if (!f) throw std::runtime_error(std::string("offscreen rendering: OpenGL lacks ") + name);
    return f;
}

// The framebuffer's pixels into `image`, top row first.
void readPixels(RenderedImage& image, int width, int height) {
    image.width = width;
    image.height = height;
    image.rgba.resize(static_cast<std::size_t>(width) * height * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    std::vector<std::uint8_t> bottomUp(image.rgba.size());
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottomUp.data());
    const std::size_t stride = static_cast<std::size_t>(width) * 4;
    for (int y = 0; y < height; ++y)
        std::memcpy(&image.rgba[static_cast<std::size_t>(y) * stride],
                    &bottomUp[static_cast<std::size_t>(height - 1 - y) * stride], stride);
}
}  // namespace

OffscreenRenderer::OffscreenRenderer() = default;
OffscreenRenderer::~OffscreenRenderer() = default;

RenderedImage OffscreenRenderer::render(SoNode* scene, int width, int height,
                                        const float background[3]) {
    return draw(scene, width, height, background, 0, nullptr);
}

double OffscreenRenderer::timeFrames(SoNode* scene, int width, int height,
                                     const float background[3], int frames) {
    double ms = 0.0;
    draw(scene, width, height, background, std::max(frames, 1), &ms);
    return ms;
}

RenderedImage OffscreenRenderer::draw(SoNode* scene, int width, int height,
                                      const float background[3], int timedFrames, double* frameMs) {
    assertMainThread("OffscreenRenderer::render");
    if (!m_context) {
        auto c = std::make_unique<Context>();
        auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
            eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (!getPlatformDisplay)
            throw std::runtime_error("offscreen rendering: EGL lacks eglGetPlatformDisplayEXT");
        c->display =
            getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (c->display == EGL_NO_DISPLAY || !eglInitialize(c->display, nullptr, nullptr))
            throw std::runtime_error(
                "offscreen rendering: no surfaceless EGL display (Mesa EGL needed)");
        if (!eglBindAPI(EGL_OPENGL_API))
            throw std::runtime_error("offscreen rendering: EGL cannot bind OpenGL");
        const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLConfig config = nullptr;
        EGLint configs = 0;
        eglChooseConfig(c->display, configAttributes, &config, 1, &configs);
        const EGLint contextAttributes[] = {EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                            EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT, EGL_NONE};
        c->context = eglCreateContext(c->display, configs > 0 ? config : EGL_NO_CONFIG_KHR,
                                      EGL_NO_CONTEXT, contextAttributes);
        if (c->context == EGL_NO_CONTEXT)
            throw std::runtime_error("offscreen rendering: cannot create an OpenGL context");
        if (!eglMakeCurrent(c->display, EGL_NO_SURFACE, EGL_NO_SURFACE, c->context))
            throw std::runtime_error("offscreen rendering: cannot make the context current");
        c->genFramebuffers = load<PFNGLGENFRAMEBUFFERSPROC>("glGenFramebuffers");
        c->bindFramebuffer = load<PFNGLBINDFRAMEBUFFERPROC>("glBindFramebuffer");
        c->deleteFramebuffers = load<PFNGLDELETEFRAMEBUFFERSPROC>("glDeleteFramebuffers");
        c->genRenderbuffers = load<PFNGLGENRENDERBUFFERSPROC>("glGenRenderbuffers");
        c->bindRenderbuffer = load<PFNGLBINDRENDERBUFFERPROC>("glBindRenderbuffer");
        c->renderbufferStorage = load<PFNGLRENDERBUFFERSTORAGEPROC>("glRenderbufferStorage");
        c->framebufferRenderbuffer =
            load<PFNGLFRAMEBUFFERRENDERBUFFERPROC>("glFramebufferRenderbuffer");
        c->checkFramebufferStatus =
            load<PFNGLCHECKFRAMEBUFFERSTATUSPROC>("glCheckFramebufferStatus");
        c->deleteRenderbuffers = load<PFNGLDELETERENDERBUFFERSPROC>("glDeleteRenderbuffers");
        c->cacheContext = SoGLCacheContextElement::getUniqueCacheContext();
        m_context = std::move(c);
    }
    Context& c = *m_context;
    eglMakeCurrent(c.display, EGL_NO_SURFACE, EGL_NO_SURFACE, c.context);

    GLuint fbo = 0, buffers[2] = {0, 0};
    c.genFramebuffers(1, &fbo);
    c.bindFramebuffer(GL_FRAMEBUFFER, fbo);
    c.genRenderbuffers(2, buffers);
    c.bindRenderbuffer(GL_RENDERBUFFER, buffers[0]);
    c.renderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    c.framebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, buffers[0]);
    c.bindRenderbuffer(GL_RENDERBUFFER, buffers[1]);
    c.renderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    c.framebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, buffers[1]);
    if (c.checkFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        c.deleteRenderbuffers(2, buffers);
        c.deleteFramebuffers(1, &fbo);
        throw std::runtime_error("offscreen rendering: framebuffer incomplete");
    }

    glViewport(0, 0, width, height);
    glClearColor(background[0], background[1], background[2], 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    SoGLRenderAction action(
        SbViewportRegion(static_cast<short>(width), static_cast<short>(height)));
    action.setCacheContext(c.cacheContext);
    action.setTransparencyType(SoGLRenderAction::SORTED_OBJECT_BLEND);
    RenderedImage image;
    action.setAbortCallback(
        [](void* visited) {
            ++*static_cast<std::size_t*>(visited);
            return SoGLRenderAction::CONTINUE;
        },
        &image.nodesVisited);
    action.apply(scene);
    glFinish();
    action.setAbortCallback(nullptr, nullptr);

    readPixels(image, width, height);

    if (frameMs && timedFrames > 0) {
        const auto start = std::chrono::steady_clock::now();
        for (int i = 0; i < timedFrames; ++i) {
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            action.apply(scene);
            glFinish();
        }
        *frameMs =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count() /
            timedFrames;
    }

    c.bindFramebuffer(GL_FRAMEBUFFER, 0);
    c.deleteRenderbuffers(2, buffers);
    c.deleteFramebuffers(1, &fbo);
    return image;
}

}  // namespace caliper3d::scenegraph
