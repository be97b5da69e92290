// Tests of the raster baker's GPU path (visibility/raster/gpu_cube.h) need a GPU driver: Mesa's
// llvmpipe in CI (setup-debian.sh installs it).
//
// GPU_DRIVER_OR_SKIP() skips the test with a visible message when no GPU answers through EGL,
// unless PVSCOPE_REQUIRE_GPU_DRIVER=1 is set (.ci/run sets it), in which case that is a failure.
#pragma once

#include "visibility/raster/gl_headless.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace pvs::test {

// Why no GPU answers, or "".
inline std::string gpu_unavailable()
{
    try {
        GlHeadless::open();
        return {};
    } catch (const GlUnavailable& e) {
        return e.what();
    }
}

inline bool gpu_driver_required()
{
    const char* required = std::getenv("PVSCOPE_REQUIRE_GPU_DRIVER");
    return required && std::string(required) == "1";
}

} // namespace pvs::test

#define GPU_DRIVER_OR_SKIP()                                                                 \
    do {                                                                                     \
        const std::string why_ = ::pvs::test::gpu_unavailable();                             \
        if (!why_.empty()) {                                                                 \
            if (::pvs::test::gpu_driver_required())                                          \
                FAIL() << "no GPU driver (PVSCOPE_REQUIRE_GPU_DRIVER=1): " << why_;          \
            GTEST_SKIP() << "SKIPPED: no GPU driver: " << why_;                              \
        }                                                                                    \
    } while (0)
