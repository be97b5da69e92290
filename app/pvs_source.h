// The PVS a command culls with, chosen by name on the command line (`--pvs`):
//   baked        the PVS stored in the zone file (none when the file has none)
//   none         no PVS: the culler falls back to the frustum
//   portal-fast  baked now: portals built from the zone's tree, base flow only
//   portal-full  baked now: portals built from the zone's tree, full flow (test level 4)
// so that `walk` and `render` can measure pvscope's own PVS against the file's on the same
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

const std::vector<std::string>& pvs_source_names();

// Throws std::invalid_argument for an unknown name. The returned source may point into `zone`.
PvsSource make_pvs_source(const Zone& zone, const std::string& name);

} // namespace pvs::app
