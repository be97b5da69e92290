// libFuzzer target: Wavefront OBJ levels (wld/obj/obj_reader.h, tinyobjloader underneath).
// The path names a folder that does not exist, so no .mtl or texture beside it is read.
#include "tests/fuzz/fuzz_support.h"
#include "wld/obj/obj_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    using namespace pvs;
    fuzz::accepts([&] {
        fuzz::check_zone(read_obj_zone(fuzz::as_bytes(data, size), "/nonexistent-pvscope-fuzz/fuzz.obj"));
    });
    return 0;
}
