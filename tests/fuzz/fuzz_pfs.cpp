// libFuzzer target: EverQuest PFS archives (wld/eq/pfs_archive.h): the structure, then every
// member inflated (each member on its own: a bad member does not hide the others).
#include "tests/fuzz/fuzz_support.h"
#include "wld/eq/pfs_archive.h"

#include <optional>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    using namespace pvs;
    std::optional<eq::PfsArchive> archive;
    if (!fuzz::accepts([&] { archive.emplace(fuzz::as_bytes(data, size), "fuzz.s3d"); }))
        return 0;
    fuzz::fuzz_check(archive->members().size() == archive->entries().size(), "one entry per name");
    for (const eq::PfsEntry& entry : archive->entries())
        fuzz::accepts([&] {
            const std::vector<uint8_t> bytes = archive->read(entry.name);
            fuzz::fuzz_check(bytes.size() == entry.size, "a member inflates to its declared size");
        });
    return 0;
}
