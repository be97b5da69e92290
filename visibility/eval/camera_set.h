// Reproducible camera sets for measuring culling: seeded random cameras inside regions looking
// anywhere, and a path that visits every region. The same zone and seed give the same cameras
// on this platform (std::mt19937_64 is specified; the float distributions are the library's).
#pragma once

#include "visibility/camera.h"
#include "visibility/zone.h"

#include <cstdint>
#include <vector>

namespace pvs {

// A camera goes only where a player could be: in a region that is not sky (the inside of a
// Quake sky brush is a region but outside the playable space), with open space all around out to
// 1.5 times the distance of the near plane's corners, so the near plane never reaches through a
// wall (a renderer would show what lies behind it, which no PVS is meant to include).
//
// Zones without a tree (OBJ levels) have no regions to stand in: there a camera goes where the
// mesh says open space is (mesh_tracer.h), with no face nearer than the same clearance.
//
// `count` cameras at random points of the zone's bounds that qualify, yaw in [0, 360),
// pitch in [-60, 60]; lens fields (fov, aspect, near, far) are copied from `lens`. Gives up on a
// zone whose regions fill almost none of its bounds after 10 000 tries per camera (fewer cameras).
std::vector<Camera> random_cameras_in_regions(const Zone& zone, size_t count, uint64_t seed, const Camera& lens);

// One camera per region that has a qualifying point (its centre, else up to 200 random points
// of its bounds), in region order, with a random view direction: a path that visits every region
// a player can stand in. Sky regions and regions too thin for the clearance are skipped.
std::vector<Camera> cameras_visiting_every_region(const Zone& zone, uint64_t seed, const Camera& lens);

// A player's continuous walk: a depth-first tour of the portal graph from a seeded start region
// (not sky), each step from the region's middle (its bounds' centre when that lies in it, else the
// mean of its portals' centres: inside the convex region either way) to the centre of a portal and on to the next region's middle, and back the same
// way when a branch is done, so every leg stays in open space. A camera every `step` units along
// it, looking where it goes (pitch 0), at most max_cameras of them. Empty without portals.
std::vector<Camera> cameras_along_portals(const Zone& zone, const PortalSet& portals, float step, size_t max_cameras,
                                          uint64_t seed, const Camera& lens);

} // namespace pvs
