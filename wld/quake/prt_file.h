// Quake portal files, PRT1 (../shared/formats/quake-doom-hepvs.md §2): the text file qbsp writes
// for vis, listing every portal between two see-through leaves as a convex planar polygon.
//
// Numbering: PRT leaf k = BSP leaf k+1 = pvscope region k, so Portal::regions holds the file's
// leaf numbers unchanged. regions[0] is the file's leaf0, the leaf the polygon's computed normal
// points into (§2.5, see portal_plane). Portals and their points keep the file's order.
//
// Reading is tolerant of layout and strict about meaning:
//  - any whitespace (spaces, tabs, CR/LF, line breaks anywhere) separates tokens; "(x y z)" and
//    "( x y z )" both read; numbers may be integers, decimals or exponent notation (ericw);
//  - the magic must be PRT1, PRT2 or PRT1-AM (§2.2, §2.3). Quake 3 files (an extra number per
//    portal line) are recognised and rejected with a message that names them;
//  - PRT1: leaf numbers must lie in [0, leaf_count). PRT2 ("PRT2, leafs, clusters, portals,
//    portal lines, then one line per cluster listing its leaves and ending with -1") and
//    PRT1-AM ("PRT1-AM, clusters, portals, leafs, portal lines, then the cluster of each leaf"):
//    portal endpoints are cluster numbers in [0, cluster_count), and the cluster map must give
//    every leaf exactly one cluster in range (PRT2: a leaf listed twice, or in no cluster, is an
//    error); PrtFile::cluster_of_leaf holds it;
//  - a portal has 3..64 points, counts are non-negative, coordinates are finite floats, the
//    file must not end early and only whitespace may follow the last portal (PRT1) or the
//    cluster map (PRT2, PRT1-AM).
// Every problem throws pvs::FileError with the byte offset of the offending token and
// "line N: ..." in the reason. Declared counts never drive an allocation larger than the text
// could hold, so a hostile header cannot allocate gigabytes.
//
// Writing produces id-style text ("4 0 1 (880 -224 -8 ) ... \n") with numbers that read back
// to the identical float: integral values without a decimal point, others in the shortest
// round-trip form: PRT1 for PrtVersion::Prt1, PRT2 (each cluster's leaves in increasing order)
// for a file with clusters (PRT1-AM is read only, as in ericw vis: it is written as PRT2).
// format_prt(parse_prt(x)) is stable, and parse_prt(format_prt(p)) == p (but for that version).
#pragma once

#include "visibility/math/plane.h"
#include "visibility/zone.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace pvs::quake {

inline constexpr uint32_t kPrtMinPoints = 3;
inline constexpr uint32_t kPrtMaxPoints = 64; // ericw vis refuses more (MAX_POINTS_ON_WINDING)

enum class PrtVersion : uint8_t { Prt1, Prt2, Prt1Am };

struct PrtFile {
    uint32_t leaf_count = 0; // the header's numleafs (= models[0].visleafs of the BSP)
    PortalSet portals;       // PRT1: regions[] are leaf numbers; PRT2, PRT1-AM: cluster numbers
    PrtVersion version = PrtVersion::Prt1;
    // PRT2, PRT1-AM: the number of clusters and the cluster of each leaf (leaf_count entries).
    uint32_t cluster_count = 0;
    std::vector<uint32_t> cluster_of_leaf = {};

    bool has_clusters() const { return version != PrtVersion::Prt1; }
};

PrtFile parse_prt(std::string_view text, const std::string& file_name_for_errors);
PrtFile load_prt(const std::string& path); // read_whole_file + parse_prt

// Throws std::invalid_argument for a PrtFile that parse_prt would refuse (a point range outside
// PortalSet::points, a leaf or cluster out of range, fewer than 3 or more than 64 points, a
// non-finite coordinate, a cluster map that is not one cluster in range per leaf), so that
// whatever is written can be read back.
std::string format_prt(const PrtFile& prt);
void save_prt(const std::string& path, const PrtFile& prt); // format_prt + write_whole_file

// The portal's plane from its first three points (§2.5): normal = normalize((p0 - p1) x (p2 - p1)),
// dist = dot(normal, p0). The normal points into regions[0]. Computed in double precision.
// If the first three points are collinear (a degenerate polygon) the normal is (0, 0, 0) and
// dist is 0. Requires point_count >= 3 and the point range inside set.points.
Plane portal_plane(const PortalSet& set, const Portal& portal);

} // namespace pvs::quake
