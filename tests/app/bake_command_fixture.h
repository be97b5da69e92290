// What the `pvscope bake` command tests share: a scratch directory per test (removed after it),
// the command run through its function with its messages captured, a generated zone written
// there as .s3d with the options that bake it, and a PVS as plain rows to compare.
// Header-only, used by test_cmd_bake.cpp and test_cmd_bake_clusters.cpp.
#pragma once

#include "app/cmd_bake.h"
#include "tests/support/test_data.h"
#include "visibility/pvs.h"
#include "wld/convert.h"
#include "wld/eq/eq_zone_reader.h"
#include "gen/generate_zone.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace pvs::test {

using Rows = std::vector<std::vector<uint64_t>>;

inline Rows rows_of(const Pvs& pvs)
{
    Rows rows(pvs.region_count(), std::vector<uint64_t>(pvs.words_per_row()));
    for (uint32_t r = 0; r < pvs.region_count(); ++r)
        pvs.decode_row(r, rows[r]);
    return rows;
}

// An EverQuest zone read back from an .s3d file.
inline Zone load_s3d(const std::string& path)
{
    return eq::load_eq_zone(test::read_bytes(path), path);
}

// Everything written to a temporary file, which is then closed.
inline std::string read_and_close(std::FILE* file)
{
    std::rewind(file);
    std::string text;
    char buffer[4096];
    for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, file)) > 0;)
        text.append(buffer, n);
    std::fclose(file);
    return text;
}

inline std::string read_text(const std::filesystem::path& path)
{
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

class BakeCommand : public ::testing::Test {
protected:
    void SetUp() override
    {
        dir_ = std::filesystem::temp_directory_path() /
               ("pvscope_bake_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
                std::to_string(::getpid()));
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }

    // Runs the command with its messages captured in err_.
    int run(const app::BakeOptions& options, const std::atomic<bool>* cancel = nullptr)
    {
        std::FILE* err = std::tmpfile();
        const int code = app::run_bake(options, err, cancel);
        err_ = read_and_close(err);
        return code;
    }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    // Options that bake the zone `generation` makes, written first as zone.s3d, into `output`
    // (in the scratch directory) with one thread; the other options are the defaults.
    app::BakeOptions bake_generated(const gen::GenParams& generation, const std::string& output)
    {
        app::BakeOptions o;
        o.input = path("zone.s3d");
        write_zone(gen::generate_zone(generation), o.input, ZoneOutput::S3d);
        o.output = path(output);
        o.threads = 1;
        return o;
    }

    std::filesystem::path dir_;
    std::string err_;
};

} // namespace pvs::test
