// A hand-made Doom map for the tests in tests/wld: WAD bytes written field by field from the
// tables of ../shared/formats/quake-doom-hepvs.md §4.2 (not by the code under test, except the
// WAD container, which glbsp then reads: an independent check of it too).
#pragma once

#include "wld/doom/wad_file.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

namespace pvs::doom_test {

using pvs::doom::WadLumpData;
using pvs::doom::write_wad;

// Five sectors (map units, y up):
//   C (0..256 x 384..512) -- E (256..272 x 448..512) -- B (272..512 x 0..512)
//   A (0..256 x 0..256)   -- D (256..272 x 0..64)    -- B
// A reaches B only through D at the bottom, C only through E at the top, both on B's west
// side x = 272: a line from A into B crosses x = 272 going east and would have to cross it
// again going west to reach E or C. So neither A nor D sees E or C (the
// sectors are convex: within a sector everything sees everything). `door_closed` gives E a
// ceiling at its floor: a closed door, which only --heights lets block sight.
enum Sec : uint16_t { kA, kD, kB, kE, kC };

struct Bytes {
    std::vector<uint8_t> b;
    void i16(int v) { b.push_back(uint8_t(v & 0xFF)), b.push_back(uint8_t((v >> 8) & 0xFF)); }
    void name(const char* n)
    {
        char buf[8] = {};
        std::memcpy(buf, n, std::min<size_t>(8, std::strlen(n)));
        b.insert(b.end(), buf, buf + 8);
    }
};

inline std::vector<uint8_t> hand_made_wad(bool door_closed)
{
    const int v[][2] = {{0, 0},     {256, 0},   {256, 64},  {256, 256}, {0, 256},   {272, 0},
                        {512, 0},   {512, 512}, {272, 512}, {272, 448}, {272, 64},  {256, 448},
                        {256, 512}, {0, 512},   {0, 384},   {256, 384}};
    // v1, v2, front sector, back sector (-1: one-sided); each walks its front sector clockwise.
    const int lines[][4] = {{0, 4, kA, -1},  {4, 3, kA, -1},   {3, 2, kA, -1},   {2, 1, kA, kD},   {1, 0, kA, -1},
                            {2, 10, kD, -1}, {10, 5, kD, kB},  {5, 1, kD, -1},   {10, 9, kB, -1},  {9, 8, kB, kE},
                            {8, 7, kB, -1},  {7, 6, kB, -1},   {6, 5, kB, -1},   {11, 12, kE, kC}, {12, 8, kE, -1},
                            {9, 11, kE, -1}, {14, 13, kC, -1}, {13, 12, kC, -1}, {11, 15, kC, -1}, {15, 14, kC, -1}};
    Bytes vertexes, linedefs, sidedefs, sectors, things;
    for (const auto& p : v)
        vertexes.i16(p[0]), vertexes.i16(p[1]);
    int side = 0;
    for (const auto& l : lines) {
        const bool two = l[3] >= 0;
        linedefs.i16(l[0]), linedefs.i16(l[1]), linedefs.i16(two ? 0x0004 : 0x0001), linedefs.i16(0), linedefs.i16(0);
        linedefs.i16(side++);
        linedefs.i16(two ? side++ : -1);
        for (int s = 0; s < (two ? 2 : 1); ++s) {
            sidedefs.i16(0), sidedefs.i16(0);
            sidedefs.name("-"), sidedefs.name("-"), sidedefs.name(two ? "-" : "STARTAN3");
            sidedefs.i16(l[2 + s]);
        }
    }
    for (int s = 0; s < 5; ++s) {
        sectors.i16(0), sectors.i16(s == kE && door_closed ? 0 : 128);
        sectors.name("FLOOR4_8"), sectors.name("CEIL3_5");
        sectors.i16(160), sectors.i16(0), sectors.i16(0);
    }
    things.i16(128), things.i16(128), things.i16(90), things.i16(1), things.i16(7);
    const std::vector<WadLumpData> lumps = {{"MAP01", {}},           {"THINGS", things.b},     {"LINEDEFS", linedefs.b},
                                            {"SIDEDEFS", sidedefs.b}, {"VERTEXES", vertexes.b}, {"SEGS", {}},
                                            {"SSECTORS", {}},         {"NODES", {}},            {"SECTORS", sectors.b},
                                            {"REJECT", {}},           {"BLOCKMAP", {}}};
    return write_wad(false, lumps);
}

} // namespace pvs::doom_test
