// libFuzzer target: Quake portal files, PRT1, PRT2 and PRT1-AM (wld/quake/prt_file.h). An
// accepted file must also be one the writer can write (format_prt throws nothing).
#include "tests/fuzz/fuzz_support.h"
#include "wld/quake/prt_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    using namespace pvs;
    fuzz::accepts([&] {
        const quake::PrtFile prt = quake::parse_prt(fuzz::as_text(data, size), "fuzz.prt");
        for (const Portal& p : prt.portals.portals) {
            fuzz::fuzz_check(uint64_t(p.first_point) + p.point_count <= prt.portals.points.size(), "portal points exist");
            (void)quake::portal_plane(prt.portals, p);
        }
        (void)quake::format_prt(prt);
    });
    return 0;
}
