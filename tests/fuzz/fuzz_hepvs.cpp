// libFuzzer target: HateEngine .hepvs files (wld/hepvs/hepvs_file.h). An accepted file must
// describe its cells consistently (what cell() and the zone attachment rely on).
#include "tests/fuzz/fuzz_support.h"
#include "wld/hepvs/hepvs_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    using namespace pvs;
    fuzz::accepts([&] {
        const HepvsFile h = read_hepvs(fuzz::as_bytes(data, size), "fuzz.hepvs");
        fuzz::fuzz_check(h.cell_offsets.size() == h.cell_count() + 1, "one offset per cell + 1");
        fuzz::fuzz_check(h.cell_offsets.back() == h.cell_objects.size(), "offsets end at the list's end");
        for (uint64_t c = 0; c < h.cell_count(); ++c)
            for (uint16_t object : h.cell(uint32_t(c)))
                fuzz::fuzz_check(object < h.names.size(), "cell object exists");
    });
    return 0;
}
