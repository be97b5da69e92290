#include "app/process_memory.h"

#include <algorithm>
#include <fstream>
#include <malloc.h>
#include <memory>
#include <string>
#include <sys/resource.h>

namespace pvs::app {
namespace {

// A field of /proc/self/status in KiB ("VmRSS", "VmHWM"); -1 when it cannot be read.
double status_kib(const std::string& field)
{
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind(field + ":", 0) == 0)
            return std::stod(line.substr(field.size() + 1));
    return -1.0;
}

} // namespace

void use_malloc_arenas(int arenas)
{
    mallopt(M_ARENA_MAX, arenas < 0 ? 0 : arenas); // 0: glibc's own limit (its default)
}

void return_freed_memory() { malloc_trim(0); }

size_t peak_rss_bytes()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return size_t(usage.ru_maxrss) * 1024; // Linux reports ru_maxrss in KiB
}

ui::PeakMemoryProbe peak_memory_probe()
{
    auto before_kib = std::make_shared<double>(-1.0);
    ui::PeakMemoryProbe probe;
    probe.begin = [before_kib] {
        malloc_trim(0); // what the previous bake freed goes back: the RSS before is this bake's floor
        std::ofstream clear("/proc/self/clear_refs");
        clear << "5";
        clear.flush();
        *before_kib = clear ? status_kib("VmRSS") : -1.0;
    };
    probe.rise_mib = [before_kib] {
        if (*before_kib < 0.0)
            return -1.0;
        const double peak = status_kib("VmHWM");
        return peak < 0.0 ? -1.0 : std::max(0.0, peak - *before_kib) / 1024.0;
    };
    return probe;
}

} // namespace pvs::app
