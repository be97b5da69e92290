// What every libFuzzer target of pvscope shares (tests/fuzz/, built with PVSCOPE_FUZZ).
//
// Contract of a target: the parser under test gets the fuzzer's bytes. Bad input reported as the
// library documents it (pvs::FileError, or the parser's own error result) is normal and ends the
// run quietly. Anything else is a finding that libFuzzer records with the input: a crash, an
// AddressSanitizer or UBSan report, a hang or an out-of-memory, an exception of another type
// (it escapes LLVMFuzzerTestOneInput and aborts), or a broken invariant (fuzz_check aborts).
#pragma once

#include "visibility/file_error.h"
#include "visibility/zone.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <string>
#include <string_view>

namespace pvs::fuzz {

// Aborts with a message when an invariant does not hold: libFuzzer saves the input.
inline void fuzz_check(bool ok, const char* what)
{
    if (!ok) {
        std::fprintf(stderr, "fuzz invariant broken: %s\n", what);
        std::abort();
    }
}

inline std::span<const uint8_t> as_bytes(const uint8_t* data, size_t size) { return {data, size}; }
inline std::string_view as_text(const uint8_t* data, size_t size)
{
    return {reinterpret_cast<const char*>(data), size};
}

// Runs `parse`; a FileError (the documented report of bad input) is swallowed, everything else
// propagates. Returns whether the parse succeeded.
template <class F>
bool accepts(F&& parse)
{
    try {
        parse();
        return true;
    } catch (const FileError&) {
        return false;
    }
}

// The invariants a loaded zone promises its users (the culler, the bake, the inspector): every
// index in range, so that they can read it without checks.
void check_zone(const Zone& zone);

} // namespace pvs::fuzz
