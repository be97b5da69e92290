// A headless OpenGL 4.5 core context through EGL, for the raster baker's GPU path (gpu_cube.h):
// no window, no display, no X server - a context made current with no surface, drawing only
// into framebuffer objects.
//
// Why EGL + OpenGL rather than Vulkan: the baker's work is one draw of the zone's triangles per
// cube face into an integer ID buffer plus one compute pass, which OpenGL 4.5 says in a page;
// EGL's surfaceless and device platforms give a context with no display on every Linux GPU
// driver (Mesa's, NVIDIA's) and on Mesa's llvmpipe, which CI runs the tests on.
//
// Like Embree (reference/embree_library.h), the libraries are opened at run time (libEGL.so.1,
// Debian's libegl1 through libglvnd), not linked: most runs never draw, and a machine without a
// driver gets a sentence, not a loader error. Every GL entry point comes from eglGetProcAddress.
//
// Contract: GlHeadless::open() tries, in order, each EGL device (the device platform: a real GPU
// first, a software device remembered as a fallback) and then Mesa's surfaceless platform, and
// returns a context current on the calling thread whose GL_VERSION is at least 4.5 core - or
// throws GlUnavailable with a sentence that says what is missing and what to do. The context
// belongs to the thread that opened it; the destructor releases and destroys it (the EGL display
// stays initialised for the life of the process: gl_headless.cpp says why). `gl()` is the
// table of every GL function the baker calls, all non-null.
#pragma once

#include <GL/glcorearb.h>

#include <memory>
#include <stdexcept>
#include <string>

namespace pvs {

// No GPU context could be made (no libEGL, no driver, no GL 4.5): what() says what to install
// or set.
class GlUnavailable : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Every GL function the GPU path calls (name, then its PFN type).
#define PVSCOPE_GL_FUNCTIONS(X)                                                                                        \
    X(glGetString, PFNGLGETSTRINGPROC)                                                                                 \
    X(glGetIntegerv, PFNGLGETINTEGERVPROC)                                                                             \
    X(glGetError, PFNGLGETERRORPROC)                                                                                   \
    X(glCreateShader, PFNGLCREATESHADERPROC)                                                                           \
    X(glShaderSource, PFNGLSHADERSOURCEPROC)                                                                           \
    X(glCompileShader, PFNGLCOMPILESHADERPROC)                                                                         \
    X(glGetShaderiv, PFNGLGETSHADERIVPROC)                                                                             \
    X(glGetShaderInfoLog, PFNGLGETSHADERINFOLOGPROC)                                                                   \
    X(glDeleteShader, PFNGLDELETESHADERPROC)                                                                           \
    X(glCreateProgram, PFNGLCREATEPROGRAMPROC)                                                                         \
    X(glAttachShader, PFNGLATTACHSHADERPROC)                                                                           \
    X(glLinkProgram, PFNGLLINKPROGRAMPROC)                                                                             \
    X(glGetProgramiv, PFNGLGETPROGRAMIVPROC)                                                                           \
    X(glGetProgramInfoLog, PFNGLGETPROGRAMINFOLOGPROC)                                                                 \
    X(glDeleteProgram, PFNGLDELETEPROGRAMPROC)                                                                         \
    X(glUseProgram, PFNGLUSEPROGRAMPROC)                                                                               \
    X(glGetUniformLocation, PFNGLGETUNIFORMLOCATIONPROC)                                                               \
    X(glProgramUniform3f, PFNGLPROGRAMUNIFORM3FPROC)                                                                   \
    X(glProgramUniform1i, PFNGLPROGRAMUNIFORM1IPROC)                                                                   \
    X(glProgramUniform1f, PFNGLPROGRAMUNIFORM1FPROC)                                                                   \
    X(glCreateBuffers, PFNGLCREATEBUFFERSPROC)                                                                         \
    X(glNamedBufferStorage, PFNGLNAMEDBUFFERSTORAGEPROC)                                                               \
    X(glClearNamedBufferData, PFNGLCLEARNAMEDBUFFERDATAPROC)                                                           \
    X(glGetNamedBufferSubData, PFNGLGETNAMEDBUFFERSUBDATAPROC)                                                         \
    X(glDeleteBuffers, PFNGLDELETEBUFFERSPROC)                                                                         \
    X(glBindBufferBase, PFNGLBINDBUFFERBASEPROC)                                                                       \
    X(glCreateVertexArrays, PFNGLCREATEVERTEXARRAYSPROC)                                                               \
    X(glVertexArrayVertexBuffer, PFNGLVERTEXARRAYVERTEXBUFFERPROC)                                                     \
    X(glVertexArrayAttribFormat, PFNGLVERTEXARRAYATTRIBFORMATPROC)                                                     \
    X(glVertexArrayAttribIFormat, PFNGLVERTEXARRAYATTRIBIFORMATPROC)                                                   \
    X(glVertexArrayAttribBinding, PFNGLVERTEXARRAYATTRIBBINDINGPROC)                                                   \
    X(glEnableVertexArrayAttrib, PFNGLENABLEVERTEXARRAYATTRIBPROC)                                                     \
    X(glBindVertexArray, PFNGLBINDVERTEXARRAYPROC)                                                                     \
    X(glDeleteVertexArrays, PFNGLDELETEVERTEXARRAYSPROC)                                                               \
    X(glCreateTextures, PFNGLCREATETEXTURESPROC)                                                                       \
    X(glTextureStorage2D, PFNGLTEXTURESTORAGE2DPROC)                                                                   \
    X(glTextureStorage3D, PFNGLTEXTURESTORAGE3DPROC)                                                                   \
    X(glClearTexImage, PFNGLCLEARTEXIMAGEPROC)                                                                         \
    X(glDeleteTextures, PFNGLDELETETEXTURESPROC)                                                                       \
    X(glBindImageTexture, PFNGLBINDIMAGETEXTUREPROC)                                                                   \
    X(glCreateFramebuffers, PFNGLCREATEFRAMEBUFFERSPROC)                                                               \
    X(glNamedFramebufferTexture, PFNGLNAMEDFRAMEBUFFERTEXTUREPROC)                                                     \
    X(glNamedFramebufferTextureLayer, PFNGLNAMEDFRAMEBUFFERTEXTURELAYERPROC)                                           \
    X(glCheckNamedFramebufferStatus, PFNGLCHECKNAMEDFRAMEBUFFERSTATUSPROC)                                             \
    X(glClearNamedFramebufferfv, PFNGLCLEARNAMEDFRAMEBUFFERFVPROC)                                                     \
    X(glBindFramebuffer, PFNGLBINDFRAMEBUFFERPROC)                                                                     \
    X(glDeleteFramebuffers, PFNGLDELETEFRAMEBUFFERSPROC)                                                               \
    X(glViewport, PFNGLVIEWPORTPROC)                                                                                   \
    X(glEnable, PFNGLENABLEPROC)                                                                                       \
    X(glDisable, PFNGLDISABLEPROC)                                                                                     \
    X(glDepthFunc, PFNGLDEPTHFUNCPROC)                                                                                 \
    X(glDepthMask, PFNGLDEPTHMASKPROC)                                                                                 \
    X(glColorMask, PFNGLCOLORMASKPROC)                                                                                 \
    X(glFrontFace, PFNGLFRONTFACEPROC)                                                                                 \
    X(glCullFace, PFNGLCULLFACEPROC)                                                                                   \
    X(glClipControl, PFNGLCLIPCONTROLPROC)                                                                             \
    X(glDrawArrays, PFNGLDRAWARRAYSPROC)                                                                               \
    X(glDispatchCompute, PFNGLDISPATCHCOMPUTEPROC)                                                                     \
    X(glMemoryBarrier, PFNGLMEMORYBARRIERPROC)                                                                         \
    X(glGetTextureSubImage, PFNGLGETTEXTURESUBIMAGEPROC)                                                               \
    X(glFinish, PFNGLFINISHPROC)

struct GlApi {
#define PVSCOPE_GL_POINTER(name, type) type name = nullptr;
    PVSCOPE_GL_FUNCTIONS(PVSCOPE_GL_POINTER)
#undef PVSCOPE_GL_POINTER
};

class GlHeadless {
public:
    static std::unique_ptr<GlHeadless> open();
    ~GlHeadless();
    GlHeadless(const GlHeadless&) = delete;
    GlHeadless& operator=(const GlHeadless&) = delete;

    const GlApi& gl() const { return gl_; }
    // "llvmpipe (LLVM 15.0.6, 256 bits) via EGL surfaceless": GL_RENDERER and the platform.
    const std::string& description() const { return description_; }
    // Mesa's llvmpipe / softpipe / lavapipe, or a device EGL reports as software.
    bool software() const { return software_; }

private:
    GlHeadless() = default;

    GlApi gl_;
    std::string description_;
    bool software_ = false;
    void* display_ = nullptr; // EGLDisplay
    void* context_ = nullptr; // EGLContext
};

} // namespace pvs
