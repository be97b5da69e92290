// What sees through what: the content rule every visibility computation shares (the portal
// builder's portals, the sampled reference's sight lines, the exact popping check), so that
// "A sees B" means the same thing to each of them (../shared/formats/quake-doom-hepvs.md §2.6).
//
// A region's medium comes from its flags: sky (kRegionSky), liquid (water, slime, lava, vwater)
// or air. Air and liquids see through each other (ericw -transwater, the default: liquids are
// translucent, also to each other). Sky is what SkyPortals says:
//  - SkyToSky (ericw's default): sky is opaque from outside; a sky region sees only sky regions.
//  - All (ericw -transsky): sky is translucent like a liquid.
//  - None: sky is opaque to vis; a sky region sees nothing but itself (id's shipped maps).
// Solid and outside leaves are not regions and see nothing; callers check that first.
// The rule is symmetric: sees_through(a, b) == sees_through(b, a).
//
// Quake 2 has its own rule (qbsp's Portal_VisFlood), on the contents of the leaves' clusters
// (Region::vis_contents): sight crosses between two leaves when their visible contents (window,
// aux, lava, slime, water, mist) are the same, or are the same once contents marked translucent
// or detail are counted as clear. So a plain water surface blocks vis (Quake 2 maps make water
// see-through by marking it translucent: SURF_TRANS33/66 gives CONTENTS_TRANSLUCENT), and glass
// (window + translucent) does not. regions_see_through applies it when both regions carry
// contents, the flags' rule otherwise.
#pragma once

#include "visibility/zone.h"

#include <cstdint>

namespace pvs {

enum class SkyPortals : uint8_t {
    SkyToSky, // ericw's default: sky is not translucent, a sky leaf has portals to sky leaves only
    All,      // ericw -transsky: sky sees through to air and liquids like a liquid
    None,     // no portal at a sky leaf: sky is opaque to vis. The PVS shipped in id's Quake maps
              // (e1m1, e2m1: compiled with Txqbsp and WVis) looks made this way: every sky leaf
              // sees only itself, even its sky neighbours (tests/wld/test_portalize.cpp).
};

enum class Medium : uint8_t { Air, Liquid, Sky };

constexpr Medium medium_of(uint32_t region_flags)
{
    if (region_flags & kRegionSky)
        return Medium::Sky;
    if (region_flags & (kRegionWater | kRegionSlime | kRegionLava | kRegionVWater))
        return Medium::Liquid;
    return Medium::Air;
}

// Whether a sight line may pass from a region of medium `a` straight into a neighbouring region
// of medium `b` (two leaves of one region always see each other; callers check that first).
constexpr bool sees_through(Medium a, Medium b, SkyPortals sky)
{
    if (a == Medium::Sky || b == Medium::Sky) {
        switch (sky) {
        case SkyPortals::SkyToSky: return a == b;
        case SkyPortals::All: return true;
        case SkyPortals::None: return false;
        }
        return false;
    }
    return true; // air <-> air, air <-> liquid, liquid <-> liquid: liquids are translucent
}

// Quake 2's rule on two leaves' vis_contents (above).
constexpr bool quake2_sight(uint16_t a, uint16_t b)
{
    return (a & 0xFF) == (b & 0xFF) || (a >> 8) == (b >> 8);
}

// Whether sight may pass from a region of medium `a` and vis contents `contents_a` (Region::
// vis_contents) straight into a neighbour of `b`, `contents_b`: Quake 2's rule when both carry
// contents, the flags' otherwise.
constexpr bool sees_through(Medium a, uint16_t contents_a, Medium b, uint16_t contents_b, SkyPortals sky)
{
    if (contents_a != kNoVisContents && contents_b != kNoVisContents)
        return quake2_sight(contents_a, contents_b);
    return sees_through(a, b, sky);
}

// The same for two regions (not the same region).
constexpr bool regions_see_through(const Region& a, const Region& b, SkyPortals sky)
{
    return sees_through(medium_of(a.flags), a.vis_contents, medium_of(b.flags), b.vis_contents, sky);
}

} // namespace pvs
