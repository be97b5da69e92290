// Access to the real levels in ../shared/data (made elsewhere, never copied into the project).
//
// SHARED_DATA_OR_SKIP(path_var, "quake/e1m1.bsp") sets path_var to the file's path, or skips the
// test with a visible message when the file is absent — unless PVSCOPE_REQUIRE_SHARED_DATA=1 is
// set (CI sets it), in which case the absence is a failure.
#pragma once

#include "visibility/zone.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pvs::test {

std::string shared_data_dir();
// The full path of a file under shared/data, or nullopt when it is not there.
std::optional<std::string> find_shared_data(const std::string& relative);
bool shared_data_required();
std::vector<uint8_t> read_bytes(const std::string& path);
// A shared-data zone, loaded once per test binary and kept; nullptr when the file is absent.
const Zone* shared_zone(const std::string& relative);
// A gtest parameter name from a data file path: its stem, every character but letters and digits
// made '_' (gtest allows no other): "quake/e1m1.bsp" -> "e1m1", "q1/lqdm2-bsp2.bsp" -> "lqdm2_bsp2".
std::string param_name(const std::string& relative_path);

} // namespace pvs::test

#define SHARED_DATA_OR_SKIP(var, relative)                                                                    \
    std::string var;                                                                                          \
    do {                                                                                                      \
        auto found_ = ::pvs::test::find_shared_data(relative);                                                \
        if (!found_) {                                                                                        \
            if (::pvs::test::shared_data_required())                                                          \
                FAIL() << "missing " << ::pvs::test::shared_data_dir() << "/" << (relative)                   \
                       << " (PVSCOPE_REQUIRE_SHARED_DATA=1)";                                                 \
            GTEST_SKIP() << "SKIPPED: needs ../shared/data/" << (relative) << " (not found at "               \
                         << ::pvs::test::shared_data_dir() << ")";                                            \
        }                                                                                                     \
        var = *found_;                                                                                        \
    } while (0)
