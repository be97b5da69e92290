// Image-space accuracy of a culling result for one camera.
//
// Input: the face id seen at every pixel when the WHOLE zone is drawn (an exact ID buffer,
// -1 for background) and the regions the culler kept. A pixel "pops" when its face would not
// have been drawn: none of the regions that list the face was kept. Overdraw compares what was
// drawn with what was needed:
//   triangle overdraw = triangles drawn (each face once) / triangles of the faces on screen
//   region overdraw   = regions drawn / regions that list at least one face on screen
// Both are >= 1 for a conservative PVS that draws everything needed; 1 is the ideal.
// Pure computation on flat data: the renderer that makes the ID buffer lives in ui/.
#pragma once

#include "visibility/face_regions.h"
#include "visibility/zone.h"

#include <cstdint>
#include <span>
#include <vector>

namespace pvs {

struct ImageAccuracy {
    uint64_t pixels = 0;          // all pixels
    uint64_t covered_pixels = 0;  // pixels showing some face
    uint64_t popping_pixels = 0;  // covered pixels whose face was not drawn
    std::vector<uint32_t> popping_faces;   // distinct, ascending
    std::vector<uint32_t> popping_regions; // regions listing a popped face (should have been kept), ascending
    uint32_t needed_faces = 0;
    uint64_t needed_triangles = 0;
    uint32_t needed_regions = 0;
    uint64_t drawn_triangles = 0;
    uint32_t drawn_regions = 0;

    double triangle_overdraw() const { return needed_triangles ? double(drawn_triangles) / double(needed_triangles) : 0.0; }
    double region_overdraw() const { return needed_regions ? double(drawn_regions) / double(needed_regions) : 0.0; }
};

// `face_ids`: one entry per pixel, the face id or -1. `drawn_regions`: the culler's output,
// ascending. Face ids out of range count as background (they cannot come from this zone).
// `behind_translucent`: empty, or one entry per pixel: the face seen through the translucent
// face the pixel shows (Quake 2 glass hides nothing), else -1. Such a face is needed too, and
// a pixel pops when any face it shows was not drawn (counted once).
ImageAccuracy measure_image_accuracy(const Zone& zone, const FaceRegions& face_regions,
                                     std::span<const int32_t> face_ids, std::span<const uint32_t> drawn_regions,
                                     std::span<const int32_t> behind_translucent = {});

} // namespace pvs
