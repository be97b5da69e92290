#include "visibility/face_regions.h"

namespace pvs {

FaceRegions build_face_regions(const Zone& zone)
{
    FaceRegions out;
    const size_t faces = zone.mesh.faces.size();
    out.offsets.assign(faces + 1, 0);
    for (uint32_t f : zone.region_faces)
        if (f < faces)
            ++out.offsets[f + 1];
    for (size_t f = 0; f < faces; ++f)
        out.offsets[f + 1] += out.offsets[f];
    out.regions.resize(out.offsets[faces]);
    std::vector<uint32_t> cursor(out.offsets.begin(), out.offsets.end() - 1);
    for (uint32_t r = 0; r < zone.region_count(); ++r)
        for (uint32_t f : zone.faces_of_region(r))
            if (f < faces)
                out.regions[cursor[f]++] = r; // regions ascending within each face, as r ascends
    return out;
}

} // namespace pvs
