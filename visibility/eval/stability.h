// How each visibility method holds up under transforms that change nothing a player could see
// (visibility/transform/zone_transform.h): the engine of `pvscope stability`.
//
// For each method of the registry asked for (methods/vis_method.h; portal-full at its default
// level), the zone is baked as given and after each transform, and the transformed rows are
// compared with the untransformed ones (regions keep their numbers): bits gained, bits lost, rows
// changed. And against the reference of the untransformed zone (baked once, reference_samples
// lines per region): missing bits, the sight lines the transformed bake would pop. A conservative
// method must stay at 0 missing under every transform; an exact transform should change nothing.
// Library code: no output; progress(stage, fraction) false cancels (the rows so far are kept).
#pragma once

#include "visibility/methods/vis_method.h"
#include "visibility/transform/zone_transform.h"
#include "visibility/zone.h"

#include <functional>
#include <string>
#include <vector>

namespace pvs {

struct StabilityOptions {
    std::vector<std::string> methods{"portal-fast", "portal-full", "clustered", "reference"};
    std::vector<ZoneTransform> transforms = stability_transforms();
    uint64_t reference_samples = 256; // the reference of the untransformed zone, and the reference method's
    SkyPortals sky = SkyPortals::SkyToSky;
    unsigned threads = 0;
    std::function<bool(const std::string& stage, double fraction)> progress;
};

struct StabilityRow {
    std::string method, params, transform;
    bool exact = false;          // the transform is exact in float (see zone_transform.h)
    uint64_t gained_bits = 0;    // in the transformed bake, not in the untransformed one
    uint64_t lost_bits = 0;      // the other way
    uint32_t changed_rows = 0;
    uint64_t missing_bits = 0;   // reference bits (untransformed zone) the transformed bake lacks
    double seconds = 0;          // the transformed bake
    uint64_t changed_bits() const { return gained_bits + lost_bits; }
};

struct StabilityResult {
    std::vector<StabilityRow> rows;
    uint64_t reference_bits = 0;
    bool cancelled = false;
};

// Throws std::invalid_argument for an unknown method, a method that bakes nothing (file, none),
// or a zone without a tree (the reference needs one).
StabilityResult run_stability(const Zone& zone, const StabilityOptions& options);

} // namespace pvs
