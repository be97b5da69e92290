// A pair's explanation (visibility/eval/pair_explanation.h) as JSON, the shape `pvscope why
// --json` prints. Field names are stable: scripts read them.
//   { "file", "a", "b", "pvs", "grid" (a is a view cell, b an object), "in_pvs", "in_reference",
//     "verdict", "summary",
//     "witness": {"from": [x,y,z], "to": [x,y,z], "tries"} | null,
//     "camera": {"position": [x,y,z], "yaw", "pitch", "argument": "x,y,z,yaw,pitch"} | null,
//     "witness_tries", "witness_regions": [a, ..., b] (the regions the witness crosses),
//     "flow_cut": the first of them portal-full's row of A lacks | null,
//     "chain_method": "portal-full" | "portal-full (2-D)", "flow_holds",
//     "portal_chain": [a, r1, ..., b] | null,
//     "chain_steps": [ {"region", "portal", "portal_regions": [front, back], "portal_size",
//                       "window_size", "window_fraction", "separators",
//                       "separator_planes": [[nx,ny,nz,d], ...] (the window in front of each),
//                       "window": [[x,y,z], ...]} ],
//     "size_unit": "area" | "width" }
// in_reference is "a sight line was found" (the reference's proof for this pair).
#pragma once

#include "visibility/eval/pair_explanation.h"

#include <nlohmann/json.hpp>
#include <string>

namespace pvs {

nlohmann::json pair_explanation_json(const std::string& file, const std::string& pvs_name, const PairExplanation& e);

// "x,y,z,yaw,pitch" for --camera (render, inspect).
std::string camera_argument(const WitnessCamera& camera);

} // namespace pvs
