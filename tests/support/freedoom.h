// Freedoom (Debian's `freedoom` package: freedoom1.wad, freedoom2.wad, BSD licence) and GL
// nodes made for it by Debian's glbsp and zdbsp: real Doom maps made elsewhere.
//
// FREEDOOM_OR_SKIP(var, "freedoom2.wad") sets var to the IWAD's path, or skips the test with a
// visible message when it is absent (failing instead under PVSCOPE_REQUIRE_SHARED_DATA=1, as CI
// sets: setup-debian.sh installs freedoom, glbsp and zdbsp). The directory is
// /usr/share/games/doom unless PVSCOPE_FREEDOOM_DIR says otherwise.
//
// gl_nodes_file(wad, builder) runs the builder once per test binary and returns the file with
// the GL nodes: glbsp's .gwa (GlBuilder::glbsp_v2/v3/v5: `glbsp -vN WAD -o X.gwa`), or a WAD
// rebuilt by zdbsp with GL nodes (zdbsp_v2: `zdbsp -g`, zdbsp_v5: `zdbsp -g -5`), in a
// temporary directory; nullopt when the tool is missing or fails.
#pragma once

#include "tests/support/test_data.h"

#include <optional>
#include <string>

namespace pvs::test {

std::optional<std::string> find_freedoom(const std::string& name);

enum class GlBuilder { glbsp_v2, glbsp_v3, glbsp_v5, zdbsp_v2, zdbsp_v5 };
const char* gl_builder_name(GlBuilder builder);
std::optional<std::string> gl_nodes_file(const std::string& wad, GlBuilder builder);

} // namespace pvs::test

#define FREEDOOM_OR_SKIP(var, name)                                                                           \
    std::string var;                                                                                          \
    do {                                                                                                      \
        auto found_ = ::pvs::test::find_freedoom(name);                                                       \
        if (!found_) {                                                                                        \
            if (::pvs::test::shared_data_required())                                                          \
                FAIL() << "missing Freedoom's " << (name) << " (apt-get install freedoom; "                   \
                       << "PVSCOPE_REQUIRE_SHARED_DATA=1)";                                                   \
            GTEST_SKIP() << "SKIPPED: needs Freedoom's " << (name) << " (apt-get install freedoom)";         \
        }                                                                                                     \
        var = *found_;                                                                                        \
    } while (0)

// Sets var to the GL-node file glbsp/zdbsp made for `wad`, or skips / fails like FREEDOOM_OR_SKIP.
#define GL_NODES_OR_SKIP(var, wad, builder)                                                                   \
    std::string var;                                                                                          \
    do {                                                                                                      \
        auto made_ = ::pvs::test::gl_nodes_file(wad, builder);                                                \
        if (!made_) {                                                                                         \
            if (::pvs::test::shared_data_required())                                                          \
                FAIL() << ::pvs::test::gl_builder_name(builder) << " could not make GL nodes for " << (wad);  \
            GTEST_SKIP() << "SKIPPED: needs " << ::pvs::test::gl_builder_name(builder)                        \
                         << " (apt-get install glbsp zdbsp)";                                                 \
        }                                                                                                     \
        var = *made_;                                                                                         \
    } while (0)
