// The portal-vis baker before the speed work of issue 6: bench_vis's baseline (see the .cpp).
#pragma once

#include "visibility/portal/portal_vis.h"

namespace pvs::reference {

// As pvs::bake_portal_vis (portal_vis.h) before issue 6's speed work; kPruneLag = 32.
Pvs bake_portal_vis_reference(const PortalSet& portals, uint32_t region_count, const VisParams& params,
                              VisReport* report = nullptr);

} // namespace pvs::reference
