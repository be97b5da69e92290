// Quake 2's potentially hearable set, made from the PVS as Quake 2's vis makes it: a cluster
// hears every cluster that some cluster of its PVS sees - the OR of the PVS rows of every cluster
// in its own row (its own row included).
//
// Two rules, because the tools differ:
//  - PhsRule::Quake2 ORs the whole rows (id's qvis3, whose rows are padded to 64-bit words).
//  - PhsRule::EricwTools reproduces ericw-tools vis (the version whose output the project's test
//    data holds): its rows are not padded, and it ORs them a 64-bit word at a time for
//    floor(row bytes / 8) words, so the bits of the last, partial word come from the cluster's
//    own PVS only. With fewer than 64 clusters that leaves the PHS equal to the PVS. It writes
//    PHS rows that are subsets of Quake 2's.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace pvs::quake2 {

enum class PhsRule : uint8_t { Quake2, EricwTools };

// pvs_rows: `clusters` rows of words_for(clusters) words. Returns the PHS rows in the same layout.
std::vector<uint64_t> compute_phs(std::span<const uint64_t> pvs_rows, uint32_t clusters, PhsRule rule);

} // namespace pvs::quake2
