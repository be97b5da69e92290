// The process's memory, where the process (not the libraries) decides: glibc's heap tuning and
// the peak resident set. Library code touches no process-wide state; main() and the commands
// call these, and hand the peak probe to the compare (ui/method_compare.h) as an option.
//
//  - use_malloc_arenas(n): glibc gives each thread that allocates an arena of its own, whose
//    pages are touched apart from the main heap's; with a bake's workers that was 1-3 MB more at
//    the peak on e1m1 (14.6-17.0 MB against 13.7-13.8 MB with one arena). The bakes allocate per
//    portal or per region, not per element, so one arena does not make the threads contend.
//    pvscope's main() asks for one (`pvscope --malloc-arenas N`, 0 = glibc's own limit).
//  - return_freed_memory(): freed pages in the middle of the heap stay resident until trimmed
//    (a bake that drops a zone's mesh first trims, so its peak starts from the floor).
//  - peak_rss_bytes(): the whole process's peak resident set so far (getrusage).
//  - peak_memory_probe(): the rise of the peak over one bake, reset through
//    /proc/self/clear_refs ("5") to the current resident set first; where Linux refuses the
//    reset, rise_mib() is negative and the compare reports the bakers' own estimates.
#pragma once

#include "render/method_compare.h"

#include <cstddef>

namespace pvs::app {

void use_malloc_arenas(int arenas);
void return_freed_memory();
size_t peak_rss_bytes();
ui::PeakMemoryProbe peak_memory_probe();

} // namespace pvs::app
