// libFuzzer target: Quake 2 maps, IBSP 38 (wld/quake2/ibsp38_file.h): the lump directory, the
// leaves and the visibility lump. An accepted file's rows have the sizes its cluster count says,
// both PHS rules run on them and only add bits to the PVS (wld/quake2/phs.h), and the file
// written again with its rows (ibsp38_writer.h) reads back with the same leaves and rows. The same
// bytes opened as a zone (ibsp38_zone.h) load consistent or throw FileError.
#include "tests/fuzz/fuzz_support.h"
#include "visibility/bit_row.h"
#include "wld/quake2/ibsp38_file.h"
#include "wld/quake2/ibsp38_writer.h"
#include "wld/quake2/ibsp38_zone.h"
#include "wld/quake2/phs.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    using namespace pvs;
    fuzz::accepts([&] {
        const quake2::Ibsp38File f = quake2::read_ibsp38({data, size}, "fuzz.bsp");
        const size_t words = bits::words_for(f.clusters);
        fuzz::fuzz_check(f.pvs_rows.size() == size_t(f.clusters) * words, "a PVS row per cluster");
        fuzz::fuzz_check(f.phs_rows.size() == size_t(f.clusters) * words, "a PHS row per cluster");
        for (const quake2::PhsRule rule : {quake2::PhsRule::Quake2, quake2::PhsRule::EricwTools}) {
            const std::vector<uint64_t> phs = quake2::compute_phs(f.pvs_rows, f.clusters, rule);
            fuzz::fuzz_check(phs.size() == f.pvs_rows.size(), "the PHS has the PVS's shape");
            for (size_t w = 0; w < phs.size(); ++w)
                fuzz::fuzz_check((phs[w] & f.pvs_rows[w]) == f.pvs_rows[w], "the PHS holds the PVS");
        }
        const std::vector<uint8_t> written = quake2::with_visibility_lump(
            {data, size}, quake2::encode_visibility_lump(f.pvs_rows, f.phs_rows, f.clusters), "fuzz.bsp");
        const quake2::Ibsp38File back = quake2::read_ibsp38(written, "written.bsp");
        fuzz::fuzz_check(back.clusters == f.clusters && back.pvs_rows == f.pvs_rows && back.phs_rows == f.phs_rows,
                         "the rows written read back");
        fuzz::fuzz_check(back.leaves.size() == f.leaves.size(), "the leaves written read back");
    });
    fuzz::accepts([&] { fuzz::check_zone(quake2::load_ibsp38({data, size}, "fuzz.bsp")); });
    return 0;
}
