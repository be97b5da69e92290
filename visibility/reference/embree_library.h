// Embree 3, opened on first use instead of linked.
//
// Why: Embree is 44 MB of code whose load-time relocations and initialisers cost a process about
// 4 MB of memory before main, and most pvscope runs (a portal-vis bake, info, stats) never trace
// a triangle. So the library is not a link dependency: the first MeshTracer opens it with
// dlopen (by its soname, as the linker would have) and reads the handful of entry points it
// uses. Later calls return the same table; the library stays open for the life of the process.
//
// Contract: embree_api() returns a table whose every entry is non-null, or throws
// std::runtime_error naming the library and what the dynamic loader said (not installed, a
// missing symbol) -- the same error on every call. Thread-safe. Only the mesh tracer and this
// file include Embree's header.
#pragma once

#include <embree3/rtcore.h>

namespace pvs {

// Every Embree function pvscope calls. rtcInitIntersectContext is inline in Embree's header.
#define PVSCOPE_EMBREE_FUNCTIONS(X) \
    X(rtcNewDevice)                 \
    X(rtcReleaseDevice)             \
    X(rtcNewScene)                  \
    X(rtcReleaseScene)              \
    X(rtcSetSceneFlags)             \
    X(rtcSetSceneBuildQuality)      \
    X(rtcCommitScene)               \
    X(rtcNewGeometry)               \
    X(rtcSetNewGeometryBuffer)      \
    X(rtcCommitGeometry)            \
    X(rtcAttachGeometry)            \
    X(rtcReleaseGeometry)           \
    X(rtcIntersect1)                \
    X(rtcIntersect8)                \
    X(rtcOccluded1)

struct EmbreeApi {
#define PVSCOPE_EMBREE_POINTER(name) decltype(&::name) name = nullptr;
    PVSCOPE_EMBREE_FUNCTIONS(PVSCOPE_EMBREE_POINTER)
#undef PVSCOPE_EMBREE_POINTER
};

const EmbreeApi& embree_api();

} // namespace pvs
