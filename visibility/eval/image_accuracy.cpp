#include "visibility/eval/image_accuracy.h"

#include <algorithm>

namespace pvs {

ImageAccuracy measure_image_accuracy(const Zone& zone, const FaceRegions& face_regions,
                                     std::span<const int32_t> face_ids, std::span<const uint32_t> drawn_regions,
                                     std::span<const int32_t> behind_translucent)
{
    ImageAccuracy a;
    a.pixels = face_ids.size();
    const size_t faces = zone.mesh.faces.size();
    std::vector<uint8_t> region_drawn(zone.region_count(), 0);
    for (uint32_t r : drawn_regions)
        region_drawn[r] = 1;

    // Which faces are drawn: any listing region kept.
    std::vector<uint8_t> face_drawn(faces, 0);
    for (uint32_t r : drawn_regions)
        for (uint32_t f : zone.faces_of_region(r))
            face_drawn[f] = 1;

    std::vector<uint8_t> face_needed(faces, 0), face_popped(faces, 0);
    // Whether a face shown at a pixel pops (and marks it needed, popped).
    const auto pops = [&](int32_t id) {
        if (id < 0 || size_t(id) >= faces)
            return false;
        face_needed[size_t(id)] = 1;
        if (face_drawn[size_t(id)])
            return false;
        face_popped[size_t(id)] = 1;
        return true;
    };
    for (size_t pixel = 0; pixel < face_ids.size(); ++pixel) {
        const int32_t id = face_ids[pixel];
        if (id < 0 || size_t(id) >= faces)
            continue;
        ++a.covered_pixels;
        const bool front_pops = pops(id);
        const bool behind_pops = pixel < behind_translucent.size() && pops(behind_translucent[pixel]);
        a.popping_pixels += front_pops || behind_pops;
    }

    std::vector<uint8_t> region_needed(zone.region_count(), 0), region_popping(zone.region_count(), 0);
    for (uint32_t f = 0; f < faces; ++f) {
        if (face_drawn[f])
            a.drawn_triangles += zone.mesh.faces[f].triangle_count;
        if (!face_needed[f])
            continue;
        ++a.needed_faces;
        a.needed_triangles += zone.mesh.faces[f].triangle_count;
        for (uint32_t r : face_regions.of(f)) {
            region_needed[r] = 1;
            if (face_popped[f])
                region_popping[r] = 1;
        }
        if (face_popped[f])
            a.popping_faces.push_back(f);
    }
    for (uint32_t r = 0; r < zone.region_count(); ++r) {
        a.needed_regions += region_needed[r];
        if (region_popping[r])
            a.popping_regions.push_back(r);
    }
    a.drawn_regions = static_cast<uint32_t>(drawn_regions.size());
    return a;
}

} // namespace pvs
