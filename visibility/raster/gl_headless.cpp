// The headless OpenGL context (gl_headless.h): EGL opened at run time, a device or Mesa's
// surfaceless platform, a 4.5 core context made current with no surface.
#include "visibility/raster/gl_headless.h"

#include "visibility/shared_library.h"

#define EGL_NO_X11 // no display server: keep X11's headers out of eglplatform.h
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <vector>

namespace pvs {

namespace {

constexpr const char* kEglSoname = "libEGL.so.1";
constexpr const char* kAdvice = "install Mesa's EGL driver (Debian: libegl1 libegl-mesa0 libgl1-mesa-dri) or "
                                "your GPU's, or bake with --device cpu";

// The EGL entry points used here, from libEGL.so.1.
struct EglApi {
    PFNEGLGETPROCADDRESSPROC get_proc = nullptr;
    PFNEGLQUERYSTRINGPROC query_string = nullptr;
    PFNEGLGETPLATFORMDISPLAYEXTPROC platform_display = nullptr;
    PFNEGLINITIALIZEPROC initialize = nullptr;
    PFNEGLBINDAPIPROC bind_api = nullptr;
    PFNEGLCREATECONTEXTPROC create_context = nullptr;
    PFNEGLDESTROYCONTEXTPROC destroy_context = nullptr;
    PFNEGLMAKECURRENTPROC make_current = nullptr;
    PFNEGLGETERRORPROC get_error = nullptr;
    PFNEGLQUERYDEVICESEXTPROC query_devices = nullptr;            // may be null
    PFNEGLQUERYDEVICESTRINGEXTPROC query_device_string = nullptr; // may be null
};

// libEGL's table, loaded once; throws GlUnavailable when the library or an entry is missing.
const EglApi& egl_api()
{
    static const EglApi api = [] {
        std::string error;
        void* library = open_shared_library(kEglSoname, "EGL", "libegl1", error);
        if (!library)
            throw GlUnavailable(error + "; " + kAdvice);
        EglApi a;
        const auto symbol = [&](const char* name) {
            void* s = shared_library_symbol(library, kEglSoname, "EGL", name, error);
            if (!s)
                throw GlUnavailable(error + "; " + kAdvice);
            return s;
        };
        a.get_proc = reinterpret_cast<PFNEGLGETPROCADDRESSPROC>(symbol("eglGetProcAddress"));
        a.query_string = reinterpret_cast<PFNEGLQUERYSTRINGPROC>(symbol("eglQueryString"));
        a.initialize = reinterpret_cast<PFNEGLINITIALIZEPROC>(symbol("eglInitialize"));
        a.bind_api = reinterpret_cast<PFNEGLBINDAPIPROC>(symbol("eglBindAPI"));
        a.create_context = reinterpret_cast<PFNEGLCREATECONTEXTPROC>(symbol("eglCreateContext"));
        a.destroy_context = reinterpret_cast<PFNEGLDESTROYCONTEXTPROC>(symbol("eglDestroyContext"));
        a.make_current = reinterpret_cast<PFNEGLMAKECURRENTPROC>(symbol("eglMakeCurrent"));
        a.get_error = reinterpret_cast<PFNEGLGETERRORPROC>(symbol("eglGetError"));
        a.platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(a.get_proc("eglGetPlatformDisplayEXT"));
        a.query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(a.get_proc("eglQueryDevicesEXT"));
        a.query_device_string = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(a.get_proc("eglQueryDeviceStringEXT"));
        if (!a.platform_display)
            throw GlUnavailable(std::string("EGL (") + kEglSoname + ") has no eglGetPlatformDisplayEXT; " + kAdvice);
        return a;
    }();
    return api;
}

bool has_extension(const char* list, const char* name)
{
    if (!list)
        return false;
    const size_t n = std::strlen(name);
    for (const char* p = std::strstr(list, name); p; p = std::strstr(p + n, name))
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
            return true;
    return false;
}

// A candidate display: where it came from, for the description and the error.
struct Candidate {
    EGLDisplay display;
    std::string platform;
    bool software_device;
};

std::vector<Candidate> candidates(const EglApi& egl)
{
    std::vector<Candidate> out;
    const char* client = egl.query_string(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (egl.query_devices && has_extension(client, "EGL_EXT_platform_device")) {
        EGLDeviceEXT devices[16];
        EGLint count = 0;
        if (egl.query_devices(16, devices, &count))
            for (EGLint i = 0; i < count; ++i) {
                const char* ext = egl.query_device_string ? egl.query_device_string(devices[i], EGL_EXTENSIONS) : "";
                const bool software = has_extension(ext, "EGL_MESA_device_software");
                if (EGLDisplay d = egl.platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr))
                    out.push_back({d, "EGL device " + std::to_string(i), software});
            }
    }
    if (has_extension(client, "EGL_MESA_platform_surfaceless"))
        if (EGLDisplay d = egl.platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr))
            out.push_back({d, "EGL surfaceless", false});
    return out;
}

// GL 4.5 core on `display`, current on this thread; null (and `why`) when not. The display is
// left initialised either way (see ~GlHeadless).
EGLContext make_context(const EglApi& egl, EGLDisplay display, std::string& why)
{
    EGLint major = 0, minor = 0;
    if (!egl.initialize(display, &major, &minor)) {
        why = "eglInitialize failed";
        return EGL_NO_CONTEXT;
    }
    const char* ext = egl.query_string(display, EGL_EXTENSIONS);
    if (!has_extension(ext, "EGL_KHR_surfaceless_context") || !has_extension(ext, "EGL_KHR_no_config_context")) {
        why = "no surfaceless, config-less contexts";
        return EGL_NO_CONTEXT;
    }
    if (!egl.bind_api(EGL_OPENGL_API)) {
        why = "no desktop OpenGL";
        return EGL_NO_CONTEXT;
    }
    const EGLint attributes[] = {
        EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, 5, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext context = egl.create_context(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
    if (context == EGL_NO_CONTEXT) {
        why = "no OpenGL 4.5 core context";
        return EGL_NO_CONTEXT;
    }
    if (!egl.make_current(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        why = "the context cannot be made current";
        egl.destroy_context(display, context);
        return EGL_NO_CONTEXT;
    }
    return context;
}

bool software_renderer(const char* renderer)
{
    return renderer &&
           (std::strstr(renderer, "llvmpipe") || std::strstr(renderer, "softpipe") || std::strstr(renderer, "swrast"));
}

} // namespace

std::unique_ptr<GlHeadless> GlHeadless::open()
{
    const EglApi& egl = egl_api();
    std::string tried;
    std::unique_ptr<GlHeadless> fallback; // a software device, used when no hardware one answers
    for (const Candidate& c : candidates(egl)) {
        if (fallback && (c.software_device || c.platform == "EGL surfaceless"))
            continue; // a software context is already open: only a GPU would be better
        std::string why;
        EGLContext context = make_context(egl, c.display, why);
        if (context == EGL_NO_CONTEXT) {
            tried += (tried.empty() ? "" : "; ") + c.platform + ": " + why;
            continue;
        }
        std::unique_ptr<GlHeadless> g(new GlHeadless);
        g->display_ = c.display;
        g->context_ = context;
        bool complete = true;
#define PVSCOPE_GL_LOAD(name, type)                                                                                    \
    g->gl_.name = reinterpret_cast<type>(egl.get_proc(#name));                                                         \
    complete = complete && g->gl_.name != nullptr;
        PVSCOPE_GL_FUNCTIONS(PVSCOPE_GL_LOAD)
#undef PVSCOPE_GL_LOAD
        if (!complete) {
            tried += (tried.empty() ? "" : "; ") + c.platform + ": a GL 4.5 function is missing";
            continue; // the destructor releases it
        }
        const auto* renderer = reinterpret_cast<const char*>(g->gl_.glGetString(GL_RENDERER));
        g->description_ = std::string(renderer ? renderer : "unknown renderer") + " via " + c.platform;
        g->software_ = c.software_device || software_renderer(renderer);
        if (!g->software_)
            return g;
        if (!fallback) {
            // Keep it, but not current: a hardware device later in the list gets its turn.
            egl.make_current(c.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            fallback = std::move(g);
        }
    }
    if (fallback) {
        egl.make_current(fallback->display_, EGL_NO_SURFACE, EGL_NO_SURFACE, fallback->context_);
        return fallback;
    }
    throw GlUnavailable("no GPU answered through EGL (" +
                        (tried.empty() ? std::string("no EGL device or platform") : tried) + "); " + kAdvice);
}

// The display stays initialised (no eglTerminate): Mesa loads its driver on eglInitialize and
// unloads it on eglTerminate, leaking a few hundred bytes each time (LeakSanitizer sees them,
// from a module already gone), and the next context would pay the driver's start-up again.
GlHeadless::~GlHeadless()
{
    const EglApi& egl = egl_api();
    egl.make_current(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    egl.destroy_context(display_, context_);
}

} // namespace pvs
