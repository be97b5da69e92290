// Face -> the regions whose face lists hold it: the inverse of Zone::faces_of_region, as
// compressed rows, regions ascending within each face. What a pixel's face id needs to say which
// regions must be drawn (image accuracy, the raster and mesh-ray bakers, the inspector's picking).
#pragma once

#include "visibility/zone.h"

#include <cstdint>
#include <span>
#include <vector>

namespace pvs {

struct FaceRegions {
    std::vector<uint32_t> offsets; // faces + 1
    std::vector<uint32_t> regions;

    // The regions listing `face`, ascending; empty for a face id outside the zone's faces.
    std::span<const uint32_t> of(uint32_t face) const
    {
        if (size_t(face) + 1 >= offsets.size())
            return {};
        return std::span<const uint32_t>(regions).subspan(offsets[face], offsets[face + 1] - offsets[face]);
    }
};

// Face ids in a region's list outside the zone's faces are left out.
FaceRegions build_face_regions(const Zone& zone);

} // namespace pvs
