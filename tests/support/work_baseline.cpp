#include "tests/support/work_baseline.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <sstream>

namespace pvs::test {

namespace {

constexpr double kRiseAllowed = 1.05; // a count may rise 5 % over its baseline
constexpr double kFallNoted = 0.95;

using Baseline = std::map<std::string, WorkCounts>; // key -> counter -> value

Baseline read_baseline(const std::string& path)
{
    Baseline b;
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#')
            continue;
        std::istringstream fields(line);
        std::string key, counter;
        uint64_t value = 0;
        if (std::getline(fields, key, '\t') && std::getline(fields, counter, '\t') && fields >> value)
            b[key][counter] = value;
    }
    return b;
}

const Baseline& baseline(const std::string& name)
{
    static std::mutex mutex;
    static std::map<std::string, Baseline> read;
    std::lock_guard lock(mutex);
    auto [slot, fresh] = read.try_emplace(name);
    if (fresh)
        slot->second = read_baseline(baseline_path(name));
    return slot->second;
}

} // namespace

std::string baseline_path(const std::string& name) { return std::string(PVSCOPE_SOURCE_DIR) + "/tests/baselines/" + name; }

void check_work(const std::string& baseline_name, const std::string& key, const WorkCounts& measured)
{
    ASSERT_FALSE(measured.empty()) << key << ": no work counters were measured";
    if (const char* out = std::getenv("PVSCOPE_WORK_BASELINE_OUT")) {
        std::ofstream file(out, std::ios::app);
        for (const auto& [counter, value] : measured)
            file << key << '\t' << counter << '\t' << value << '\n';
    }
    const Baseline& b = baseline(baseline_name);
    const auto entry = b.find(key);
    ASSERT_NE(entry, b.end()) << key << " has no line in " << baseline_path(baseline_name)
                              << " (add it with PVSCOPE_WORK_BASELINE_OUT: tests/support/work_baseline.h)";
    for (const auto& [counter, value] : measured) {
        const auto base = entry->second.find(counter);
        if (base == entry->second.end()) {
            ADD_FAILURE() << key << ": counter " << counter << " = " << value << " has no baseline";
            continue;
        }
        EXPECT_LE(double(value), kRiseAllowed * double(base->second))
            << key << ": " << counter << " rose from " << base->second << " (baseline) to " << value << " (+"
            << 100.0 * (double(value) / double(base->second) - 1.0) << " %)";
        if (double(value) < kFallNoted * double(base->second))
            std::printf("NOTE %s: %s fell from %llu (baseline) to %llu: tighten the baseline\n", key.c_str(),
                        counter.c_str(), static_cast<unsigned long long>(base->second),
                        static_cast<unsigned long long>(value));
    }
    for (const auto& [counter, value] : entry->second)
        EXPECT_TRUE(measured.contains(counter)) << key << ": counter " << counter << " is no longer reported";
}

} // namespace pvs::test
