// The PVS a command culls with, chosen by name on the command line (`--pvs`): any method of the
// registry (visibility/methods/vis_method.h) — `file` (the PVS stored in the zone file; `baked`
// is kept as its older name), `none` (the frustum only), or a method baked now (portal-fast,
// portal-full, clustered, reference) — so that `walk` and `render` measure any PVS on the same
// cameras. Baking uses every core; the note says what was used and how long it took.
#pragma once

#include "visibility/pvs.h"
#include "visibility/zone.h"

#include <optional>
#include <string>
#include <vector>

namespace pvs::app {

struct PvsSource {
    std::optional<Pvs> baked_now; // holds the PVS when this source baked it
    const Pvs* pvs = nullptr;     // what to cull with: the zone's, baked_now's, or null
    std::string note;             // one line for the user, e.g. "portal-full: 1206 regions, 0.9 s"
};

// The registry's names, and "baked".
const std::vector<std::string>& pvs_source_names();

// Throws std::invalid_argument for an unknown name, or from the method (the reference on a zone
// without a tree). The returned source may point into `zone`.
PvsSource make_pvs_source(const Zone& zone, const std::string& name);

} // namespace pvs::app
