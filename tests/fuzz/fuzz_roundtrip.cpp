// libFuzzer target: the writers. Any file the readers accept, written and read back, gives the
// same thing; the format is chosen by the input's magic:
//  - Quake BSP 29 with a PVS: write_bsp29_vis(file, its own PVS) reads back with the same PVS
//    rows, tree, regions and mesh (bsp29_vis_writer.h);
//  - Doom WAD: write_wad(lumps) parses back to the same lumps, and every map to the same map;
//  - PRT1 / PRT2 / PRT1-AM text: parse(format(p)) == p (PRT1-AM comes back as PRT2);
//  - PFS archive: its members through write_pfs come back with the same (lowercased) names and
//    bytes; as an EverQuest zone, write -> read -> write is byte-identical (eq_zone_writer.h);
//  - anything else as a .hepvs: write(read(f)) == f, byte for byte.
// A writer may refuse with std::invalid_argument only what its header says it refuses (names
// no PFS reader could use, zones the WLD form cannot express); a read-back that throws anything,
// or that differs, is a finding.
#include "tests/fuzz/fuzz_support.h"
#include "visibility/bit_row.h"
#include "wld/doom/doom_map.h"
#include "wld/eq/eq_zone_reader.h"
#include "wld/eq/eq_zone_writer.h"
#include "wld/eq/pfs_archive.h"
#include "wld/hepvs/hepvs_file.h"
#include "wld/quake/bsp29_reader.h"
#include "wld/quake/bsp29_vis_writer.h"
#include "wld/quake/prt_file.h"

#include <cstring>
#include <optional>
#include <stdexcept>

namespace pvs::fuzz {
namespace {

// Reads what a writer produced: a FileError here is a finding, not bad input.
template <class F>
auto read_back(F&& read)
{
    try {
        return read();
    } catch (const FileError& e) {
        std::fprintf(stderr, "read-back refused the writer's output: %s\n", e.what());
        std::abort();
    }
}

bool same_pvs(const Pvs& a, const Pvs& b)
{
    if (a.row_count() != b.row_count() || a.region_count() != b.region_count())
        return false;
    std::vector<uint64_t> ra(a.words_per_row()), rb(b.words_per_row());
    for (uint32_t r = 0; r < a.row_count(); ++r) {
        if (a.row_missing(r) != b.row_missing(r))
            return false;
        a.decode_row(r, ra);
        b.decode_row(r, rb);
        if (ra != rb)
            return false;
    }
    return true;
}

bool same_tree(const BspTree& a, const BspTree& b)
{
    if (a.root != b.root || a.leaf_region != b.leaf_region || a.nodes.size() != b.nodes.size())
        return false;
    for (size_t i = 0; i < a.nodes.size(); ++i)
        if (std::memcmp(&a.nodes[i], &b.nodes[i], sizeof(BspNode)) != 0)
            return false;
    return true;
}

void bsp29(std::span<const uint8_t> bytes)
{
    Zone zone;
    if (!accepts([&] { zone = quake::load_bsp29(bytes, "fuzz.bsp"); }) || !zone.baked_pvs)
        return;
    const std::vector<uint8_t> written = quake::write_bsp29_vis(bytes, *zone.baked_pvs, "fuzz.bsp");
    const Zone again = read_back([&] { return quake::load_bsp29(written, "written.bsp"); });
    fuzz_check(again.baked_pvs && same_pvs(*zone.baked_pvs, *again.baked_pvs), "BSP 29: same PVS");
    fuzz_check(same_tree(zone.tree, again.tree), "BSP 29: same tree");
    fuzz_check(zone.region_count() == again.region_count() && zone.region_faces == again.region_faces &&
                   zone.mesh.indices == again.mesh.indices && zone.mesh.positions == again.mesh.positions,
               "BSP 29: same regions and mesh");
}

bool same_map(const doom::DoomMap& a, const doom::DoomMap& b)
{
    auto same_segs = [](const doom::GlSeg& x, const doom::GlSeg& y) {
        return x.v1 == y.v1 && x.v2 == y.v2 && x.linedef == y.linedef && x.side == y.side && x.partner == y.partner;
    };
    if (a.name != b.name || a.hexen != b.hexen || a.gl_version != b.gl_version || a.vertices.size() != b.vertices.size() ||
        a.linedefs.size() != b.linedefs.size() || a.sidedefs.size() != b.sidedefs.size() ||
        a.sectors.size() != b.sectors.size() || a.segs.size() != b.segs.size() ||
        a.subsectors.size() != b.subsectors.size() || a.nodes.size() != b.nodes.size() || a.reject != b.reject ||
        a.gl_pvs != b.gl_pvs)
        return false;
    for (size_t i = 0; i < a.segs.size(); ++i)
        if (!same_segs(a.segs[i], b.segs[i]))
            return false;
    return true;
}

void wad(std::span<const uint8_t> bytes)
{
    doom::WadFile wad;
    if (!accepts([&] { wad = doom::parse_wad(std::vector<uint8_t>(bytes.begin(), bytes.end()), "fuzz.wad"); }))
        return;
    std::vector<doom::WadLumpData> lumps;
    for (size_t i = 0; i < wad.lumps.size(); ++i) {
        const auto data = wad.data(i);
        lumps.push_back({wad.lumps[i].name, std::vector<uint8_t>(data.begin(), data.end())});
    }
    const doom::WadFile again = read_back([&] { return doom::parse_wad(doom::write_wad(wad.iwad, lumps), "written.wad"); });
    fuzz_check(again.iwad == wad.iwad && again.lumps.size() == wad.lumps.size(), "WAD: same header");
    for (size_t i = 0; i < wad.lumps.size(); ++i) {
        const auto a = wad.data(i), b = again.data(i);
        fuzz_check(again.lumps[i].name == wad.lumps[i].name && std::equal(a.begin(), a.end(), b.begin(), b.end()),
                   "WAD: same lumps");
    }
    const std::vector<std::string> names = doom::map_names(wad);
    fuzz_check(names == doom::map_names(again), "WAD: same maps");
    for (const std::string& name : names) {
        std::optional<doom::DoomMap> map;
        if (!accepts([&] { map = doom::read_doom_map(wad, nullptr, name); }))
            continue;
        const doom::DoomMap map_again = read_back([&] { return doom::read_doom_map(again, nullptr, name); });
        fuzz_check(same_map(*map, map_again), "WAD: same map");
    }
}

void prt(std::string_view text)
{
    quake::PrtFile prt;
    if (!accepts([&] { prt = quake::parse_prt(text, "fuzz.prt"); }))
        return;
    const std::string written = quake::format_prt(prt);
    const quake::PrtFile again = read_back([&] { return quake::parse_prt(written, "written.prt"); });
    fuzz_check(again.leaf_count == prt.leaf_count && again.cluster_count == prt.cluster_count &&
                   again.cluster_of_leaf == prt.cluster_of_leaf && again.has_clusters() == prt.has_clusters(),
               "PRT: same header and clusters");
    fuzz_check(again.portals.points == prt.portals.points && again.portals.portals.size() == prt.portals.portals.size(),
               "PRT: same points");
    for (size_t i = 0; i < prt.portals.portals.size(); ++i) {
        const Portal &a = prt.portals.portals[i], &b = again.portals.portals[i];
        fuzz_check(a.regions[0] == b.regions[0] && a.regions[1] == b.regions[1] && a.first_point == b.first_point &&
                       a.point_count == b.point_count,
                   "PRT: same portals");
    }
    fuzz_check(quake::format_prt(again) == written, "PRT: format is stable");
}

void pfs(std::span<const uint8_t> bytes)
{
    std::vector<eq::PfsMember> members;
    if (!accepts([&] {
            const eq::PfsArchive archive(bytes, "fuzz.s3d");
            for (const std::string& name : archive.members())
                members.push_back({name, archive.read(name)});
        }))
        return;
    try {
        const std::vector<uint8_t> written = eq::write_pfs(members);
        const eq::PfsArchive again = read_back([&] { return eq::PfsArchive(written, "written.s3d"); });
        fuzz_check(again.members().size() == members.size(), "PFS: same member count");
        for (const eq::PfsMember& m : members)
            fuzz_check(read_back([&] { return again.read(m.name); }) == m.data, "PFS: same member bytes");
    } catch (const std::invalid_argument&) { // names or sizes write_pfs refuses, as documented
    }

    Zone zone;
    if (!accepts([&] { zone = eq::load_eq_zone(bytes, "fuzz.s3d"); }))
        return;
    std::vector<uint8_t> first;
    try {
        first = eq::write_eq_zone(zone, "fuzz");
    } catch (const std::invalid_argument&) { // a zone the WLD form cannot express, as documented
        return;
    }
    const Zone again = read_back([&] { return eq::load_eq_zone(first, "fuzz.s3d"); });
    check_zone(again);
    fuzz_check(eq::write_eq_zone(again, "fuzz") == first, "EverQuest: write -> read -> write is byte-identical");
}

void hepvs(std::span<const uint8_t> bytes)
{
    HepvsFile file;
    if (!accepts([&] { file = read_hepvs(bytes, "fuzz.hepvs"); }))
        return;
    const std::vector<uint8_t> written = write_hepvs(file);
    fuzz_check(std::equal(written.begin(), written.end(), bytes.begin(), bytes.end()), ".hepvs: byte-identical");
}

} // namespace
} // namespace pvs::fuzz

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    using namespace pvs;
    const std::span<const uint8_t> bytes(data, size);
    if (quake::looks_like_bsp29(bytes))
        fuzz::bsp29(bytes);
    else if (doom::looks_like_wad(bytes))
        fuzz::wad(bytes);
    else if (eq::looks_like_pfs(bytes))
        fuzz::pfs(bytes);
    else if (size >= 3 && std::memcmp(data, "PRT", 3) == 0)
        fuzz::prt(fuzz::as_text(data, size));
    else
        fuzz::hepvs(bytes);
    return 0;
}
