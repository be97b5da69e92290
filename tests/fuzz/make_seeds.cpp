// fuzz_make_seeds: writes seed inputs for the fuzz targets from pvscope's own writers, the way
// `pvscope gen` and `pvscope convert` make zones, so that every target starts from files that
// go deep into its parser. Used by make-corpora.sh; writes only under the folder it is given.
//
//   fuzz_make_seeds gen OUT                 generated zones (5 and 12 rooms, baked) as .s3d (with
//                                           and without textures), bare .wld, .obj, .hepvs, .prt,
//                                           and codec/edit-list seeds from their PVS
//   fuzz_make_seeds bsp OUT FILE.bsp [PRT]  a Quake map converted: .s3d, .obj, .hepvs, codec
//                                           seeds from its PVS, and its .prt through format_prt
//   fuzz_make_seeds doom OUT WAD [GL] [N]   the first N (default 3) maps of WAD, each as a small
//                                           PWAD with its map lumps and GL group (from GL: a .gwa
//                                           or a WAD rebuilt with GL nodes), once as found and
//                                           once with an all-visible GL_PVS; plus a textures WAD
//                                           (PLAYPAL, a few TEXTURE1 entries with their patches,
//                                           a few flats)
//   fuzz_make_seeds extract WAD MAP FILE    a PWAD of MAP's lumps alone (the input of glbsp and
//                                           zdbsp, so that they build one map, not the IWAD's 36)
// OUT/<target>/ receives the seeds of each target (the folder names are the targets' names
// without "fuzz_"). Exits non-zero with a message when an input cannot be read.
#include "visibility/bit_row.h"
#include "visibility/codec/eq_vislist.h"
#include "visibility/codec/glvis_rows.h"
#include "visibility/codec/quake_rle.h"
#include "visibility/file_error.h"
#include "wld/common/read_file.h"
#include "wld/convert.h"
#include "wld/doom/doom_map.h"
#include "wld/doom/wad_file.h"
#include "wld/eq/eq_zone_writer.h"
#include "wld/eq/pfs_archive.h"
#include "gen/generate_zone.h"
#include "wld/pvs_edit_list.h"
#include "wld/quake/bsp29_reader.h"
#include "wld/quake/prt_file.h"

#include <squish.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace pvs;

namespace {

fs::path g_out;

void put(const std::string& target, const std::string& name, const std::vector<uint8_t>& bytes)
{
    const fs::path dir = g_out / target;
    fs::create_directories(dir);
    write_whole_file((dir / name).string(), bytes);
}

void put_text(const std::string& target, const std::string& name, const std::string& text)
{
    put(target, name, std::vector<uint8_t>(text.begin(), text.end()));
}

std::vector<uint8_t> with_prefix(std::initializer_list<uint8_t> prefix, const std::vector<uint8_t>& rest)
{
    std::vector<uint8_t> out(prefix);
    out.insert(out.end(), rest.begin(), rest.end());
    return out;
}

// Codec and edit-list seeds from a zone's PVS: a few rows in each codec, the GL_PVS lump of
// the whole PVS when it is small enough for the target's 12-bit count, and an edit list.
void codec_seeds(const Zone& zone, const std::string& stem)
{
    if (!zone.baked_pvs)
        return;
    const Pvs& pvs = *zone.baked_pvs;
    const uint32_t n = pvs.region_count();
    std::vector<uint64_t> row(pvs.words_per_row());
    for (uint32_t r : {0u, n / 3, n / 2, n - 1}) {
        if (r >= pvs.row_count())
            continue;
        pvs.decode_row(r, row);
        const uint8_t lo = uint8_t(n & 0xFF), hi = uint8_t(n >> 8);
        std::vector<uint8_t> rle;
        encode_quake_rle(row, n, rle);
        put("quake_rle", stem + "_row" + std::to_string(r), with_prefix({lo, hi}, rle));
        std::vector<uint8_t> list;
        encode_eq_vislist_bytes(row, n, list);
        put("eq_vislist", stem + "_bytes" + std::to_string(r), with_prefix({lo, hi, 0}, list));
        list.clear();
        if (encode_eq_vislist_words(row, n, list))
            put("eq_vislist", stem + "_words" + std::to_string(r), with_prefix({lo, hi, 1}, list));
    }
    if (n < 4096 && pvs.square()) {
        std::vector<uint64_t> rows(size_t(n) * pvs.words_per_row());
        for (uint32_t r = 0; r < n; ++r)
            pvs.decode_row(r, std::span(rows).subspan(size_t(r) * pvs.words_per_row(), pvs.words_per_row()));
        std::vector<uint8_t> lump;
        encode_glvis_rows(rows, n, lump);
        put("gl_pvs", stem, with_prefix({uint8_t(n & 0xFF), uint8_t(n >> 8)}, lump));
    }
    if (n >= 3 && n < 256 && pvs.row_count() < 256) {
        std::vector<PvsEdit> edits = {pair_edit(0, 1, false, true), pair_edit(2, 0, true, false)};
        PvsEdit row_edit;
        row_edit.op = PvsEdit::Op::Row;
        row_edit.from = 1;
        row_edit.row_visible = {0, 2};
        row_edit.note = "reference";
        edits.push_back(row_edit);
        const std::string json = edit_list_json(edits, pvs.row_count(), n);
        std::vector<uint8_t> seed = {uint8_t(pvs.row_count()), uint8_t(n)};
        seed.insert(seed.end(), json.begin(), json.end());
        put("edit_list", stem, seed);
    }
}

// The zone as .s3d (also the WLD inside it, bare) and as .obj + .hepvs.
void zone_file_seeds(const Zone& zone, const std::string& stem)
{
    const fs::path tmp = g_out / "tmp";
    fs::create_directories(tmp);
    const std::string s3d = (tmp / (stem + ".s3d")).string();
    write_zone(zone, s3d, ZoneOutput::S3d);
    const std::vector<uint8_t> archive = read_whole_file(s3d);
    for (const char* target : {"eq_zone", "pfs", "roundtrip"})
        put(target, stem + ".s3d", archive);
    const eq::PfsArchive pfs(archive, s3d);
    for (const std::string& member : pfs.members()) {
        if (member.size() > 4 && member.substr(member.size() - 4) == ".wld")
            put("wld", stem + ".wld", pfs.read(member));
        else if (member.size() > 4 && member.substr(member.size() - 4) == ".bmp")
            put("bmp", stem + "_" + member, pfs.read(member));
    }
    const std::string obj = (tmp / (stem + ".obj")).string();
    write_zone(zone, obj, ZoneOutput::Obj);
    put("obj", stem + ".obj", read_whole_file(obj));
    const fs::path hepvs = fs::path(obj).replace_extension(".hepvs");
    if (fs::exists(hepvs)) {
        const std::vector<uint8_t> bytes = read_whole_file(hepvs.string());
        if (bytes.size() < 200000) {
            put("hepvs", stem + ".hepvs", bytes);
            put("roundtrip", stem + ".hepvs", bytes);
        }
    }
}

void prt_seed(const Zone& zone, uint32_t leaf_count, const std::string& stem)
{
    if (!zone.portals)
        return;
    quake::PrtFile prt;
    prt.leaf_count = leaf_count;
    prt.portals = *zone.portals;
    const std::string text = quake::format_prt(prt);
    put_text("prt", stem + ".prt", text);
    put_text("roundtrip", stem + ".prt", text);
}

// DXT1/3/5 files of a small gradient picture, made with squish (as the tests do).
void dds_seeds()
{
    const uint32_t w = 8, h = 4;
    std::vector<uint8_t> rgba(w * h * 4);
    for (uint32_t i = 0; i < w * h; ++i) {
        rgba[i * 4 + 0] = uint8_t(i * 8);
        rgba[i * 4 + 1] = uint8_t(255 - i * 8);
        rgba[i * 4 + 2] = uint8_t(i * 3);
        rgba[i * 4 + 3] = uint8_t(i % 2 ? 255 : 0);
    }
    const std::pair<const char*, int> kinds[] = {{"DXT1", squish::kDxt1}, {"DXT3", squish::kDxt3}, {"DXT5", squish::kDxt5}};
    for (const auto& [fourcc, flags] : kinds) {
        std::vector<uint8_t> file(128, 0);
        auto u32 = [&](size_t at, uint32_t v) { std::memcpy(file.data() + at, &v, 4); };
        std::memcpy(file.data(), "DDS ", 4);
        u32(4, 124);
        u32(8, 0x1007); // caps, height, width, pixel format
        u32(12, h);
        u32(16, w);
        u32(76, 32);
        u32(80, 0x4);
        std::memcpy(file.data() + 84, fourcc, 4);
        u32(108, 0x1000);
        std::vector<uint8_t> blocks(size_t(squish::GetStorageRequirements(int(w), int(h), flags)));
        squish::CompressImage(rgba.data(), int(w), int(h), blocks.data(), flags);
        file.insert(file.end(), blocks.begin(), blocks.end());
        put("dds", std::string("gradient_") + fourcc + ".dds", file);
    }
}

void gen_seeds()
{
    for (int rooms : {5, 12}) {
        gen::GenParams params;
        params.rooms = rooms;
        params.seed = 2026;
        params.bake = true;
        params.bake_threads = 1;
        Zone zone = gen::generate_zone(params);
        const std::string stem = "gen" + std::to_string(rooms);
        zone_file_seeds(zone, stem);
        codec_seeds(zone, stem);
        prt_seed(zone, uint32_t(zone.region_count()), stem);
        for (Material& m : zone.materials) // the same zone without textures: a much smaller archive
            set_material_rgba(m, 0, 0, {});
        const std::vector<uint8_t> bare = eq::write_eq_zone(zone, stem + "_untextured");
        for (const char* target : {"eq_zone", "pfs", "roundtrip"})
            put(target, stem + "_untextured.s3d", bare);
    }
    dds_seeds();
}

void bsp_seeds(const std::string& bsp, const std::string& prt_path)
{
    const std::vector<uint8_t> bytes = read_whole_file(bsp);
    const std::string stem = fs::path(bsp).stem().string();
    Zone zone = quake::load_bsp29(bytes, bsp);
    for (const char* target : {"bsp29", "roundtrip"})
        put(target, stem + ".bsp", bytes);
    codec_seeds(zone, stem);
    if (!prt_path.empty()) {
        const std::vector<uint8_t> prt = read_whole_file(prt_path);
        for (const char* target : {"prt", "roundtrip"})
            put(target, stem + ".prt", prt);
        const quake::PrtFile parsed = quake::load_prt(prt_path);
        put_text("prt", stem + "_formatted.prt", quake::format_prt(parsed));
    }
    for (Material& m : zone.materials) // the converted archive without the map's textures: small
        set_material_rgba(m, 0, 0, {});
    zone_file_seeds(zone, stem);
}

// The map lumps read_doom_map reads (plus THINGS, which marks a map): the classic nodes and
// the BLOCKMAP are left out of the seeds, where they would only make every input larger.
bool is_read_map_lump(const std::string& name)
{
    static const std::set<std::string> names = {"THINGS", "LINEDEFS", "SIDEDEFS", "VERTEXES", "SECTORS", "REJECT",
                                                "BEHAVIOR"};
    return names.count(name) > 0;
}

bool is_map_lump(const std::string& name)
{
    static const std::set<std::string> names = {"THINGS", "LINEDEFS", "SIDEDEFS", "VERTEXES", "SEGS", "SSECTORS",
                                                "NODES", "SECTORS", "REJECT", "BLOCKMAP", "BEHAVIOR", "SCRIPTS"};
    return names.count(name) > 0;
}

std::vector<doom::WadLumpData> copy_lumps(const doom::WadFile& wad, size_t first, size_t count)
{
    std::vector<doom::WadLumpData> out;
    for (size_t i = first; i < first + count && i < wad.lumps.size(); ++i) {
        const auto data = wad.data(i);
        out.push_back({wad.lumps[i].name, std::vector<uint8_t>(data.begin(), data.end())});
    }
    return out;
}

void doom_map_seeds(const doom::WadFile& wad, const doom::WadFile* gl, const std::string& stem, size_t max_maps)
{
    const std::vector<std::string> names = doom::map_names(wad);
    for (size_t k = 0; k < names.size() && k < max_maps; ++k) {
        const doom::DoomMap map = doom::read_doom_map(wad, gl, names[k]);
        size_t map_lumps = 1;
        while (map.source.map_marker + map_lumps < wad.lumps.size() &&
               is_map_lump(wad.lumps[map.source.map_marker + map_lumps].name))
            ++map_lumps;
        std::vector<doom::WadLumpData> lumps = copy_lumps(wad, map.source.map_marker, 1);
        for (size_t i = 1; i < map_lumps; ++i)
            if (is_read_map_lump(wad.lumps[map.source.map_marker + i].name))
                lumps.push_back(copy_lumps(wad, map.source.map_marker + i, 1)[0]);
        const doom::WadFile& gl_file = map.source.gl_path == wad.path || !gl ? wad : *gl;
        size_t gl_lumps = 1; // GL_<name> or GL_LEVEL, then up to five GL_ lumps
        while (map.source.gl_marker + gl_lumps < gl_file.lumps.size() && gl_lumps < 6 &&
               gl_file.lumps[map.source.gl_marker + gl_lumps].name.rfind("GL_", 0) == 0)
            ++gl_lumps;
        const auto group = copy_lumps(gl_file, map.source.gl_marker, gl_lumps);
        lumps.insert(lumps.end(), group.begin(), group.end());
        const std::string name = stem + "_" + map.name;
        const std::vector<uint8_t> pwad = doom::write_wad(false, lumps);
        for (const char* target : {"doom_map", "roundtrip"})
            put(target, name + ".wad", pwad);
        if (!map.source.gl_pvs_present && map.subsectors.size() < 2000) {
            // An all-visible GL_PVS after the GL group (marker + 5), as glVIS writes it.
            const size_t n = map.subsectors.size();
            lumps.push_back({"GL_PVS", std::vector<uint8_t>(glvis_row_bytes(n) * n, 0xFF)});
            put("doom_map", name + "_glpvs.wad", doom::write_wad(false, lumps));
        }
    }
}

// A few TEXTURE1 entries of the IWAD with only the patches they use (PNAMES renumbered), the
// first flats, and PLAYPAL: a textures WAD of some kilobytes.
void doom_texture_seed(const doom::WadFile& wad, const std::string& stem)
{
    const auto texture1 = wad.find_last("TEXTURE1");
    const auto pnames = wad.find_last("PNAMES");
    const auto playpal = wad.find_last("PLAYPAL");
    if (!texture1 || !pnames || !playpal)
        return;
    auto i16 = [](std::span<const uint8_t> b, size_t at) { int16_t v; std::memcpy(&v, b.data() + at, 2); return v; };
    auto i32 = [](std::span<const uint8_t> b, size_t at) { int32_t v; std::memcpy(&v, b.data() + at, 4); return v; };
    const auto tex = wad.data(*texture1);
    const auto names = wad.data(*pnames);
    std::vector<std::string> used; // new PNAMES
    std::map<int, int> renumber;
    std::vector<std::vector<uint8_t>> records;
    const int count = std::min(i32(tex, 0), 6);
    for (int t = 0; t < count; ++t) {
        const size_t at = size_t(i32(tex, 4 + size_t(t) * 4));
        const int patches = i16(tex, at + 20);
        std::vector<uint8_t> record(tex.begin() + long(at), tex.begin() + long(at + 22 + size_t(patches) * 10));
        for (int p = 0; p < patches; ++p) {
            const int old = i16(tex, at + 22 + size_t(p) * 10 + 4);
            if (!renumber.count(old)) {
                renumber[old] = int(used.size());
                used.push_back(doom::wad_name(names.subspan(4 + size_t(old) * 8, 8)));
            }
            const int16_t now = int16_t(renumber[old]);
            std::memcpy(record.data() + 22 + size_t(p) * 10 + 4, &now, 2);
        }
        records.push_back(record);
    }
    std::vector<uint8_t> new_tex(4 + records.size() * 4);
    const int32_t n = int32_t(records.size());
    std::memcpy(new_tex.data(), &n, 4);
    for (size_t t = 0; t < records.size(); ++t) {
        const int32_t offset = int32_t(new_tex.size());
        std::memcpy(new_tex.data() + 4 + t * 4, &offset, 4);
        new_tex.insert(new_tex.end(), records[t].begin(), records[t].end());
    }
    std::vector<uint8_t> new_names(4 + used.size() * 8, 0);
    const int32_t m = int32_t(used.size());
    std::memcpy(new_names.data(), &m, 4);
    for (size_t p = 0; p < used.size(); ++p)
        std::memcpy(new_names.data() + 4 + p * 8, used[p].data(), std::min<size_t>(8, used[p].size()));
    std::vector<doom::WadLumpData> lumps = copy_lumps(wad, *playpal, 1);
    lumps.push_back({"PNAMES", new_names});
    lumps.push_back({"TEXTURE1", new_tex});
    for (const std::string& patch : used)
        if (const auto lump = wad.find_last(patch))
            lumps.push_back(copy_lumps(wad, *lump, 1)[0]);
    if (const auto f_start = wad.find_from("F_START", 0)) {
        lumps.push_back({"F_START", {}});
        for (size_t i = *f_start + 1, taken = 0; i < wad.lumps.size() && taken < 3; ++i)
            if (wad.lumps[i].size == 4096) {
                lumps.push_back(copy_lumps(wad, i, 1)[0]);
                ++taken;
            }
        lumps.push_back({"F_END", {}});
    }
    put("doom_textures", stem + "_textures.wad", doom::write_wad(false, lumps));
}

} // namespace

int main(int argc, char** argv)
{
    try {
        const std::string mode = argc > 2 ? argv[1] : "";
        if (mode.empty()) {
            std::fprintf(stderr, "usage: fuzz_make_seeds gen OUT | bsp OUT FILE.bsp [PRT] | doom OUT WAD [GL] [N] | extract WAD MAP FILE\n");
            return 2;
        }
        if (mode == "extract" && argc > 4) {
            const doom::WadFile wad = doom::read_wad(argv[2]);
            const auto marker = wad.find_from(doom::upper_case(argv[3]), 0);
            if (!marker)
                throw std::runtime_error(std::string("no map ") + argv[3] + " in " + argv[2]);
            size_t count = 1;
            while (*marker + count < wad.lumps.size() && is_map_lump(wad.lumps[*marker + count].name))
                ++count;
            write_whole_file(argv[4], doom::write_wad(false, copy_lumps(wad, *marker, count)));
            return 0;
        }
        g_out = argv[2];
        if (mode == "gen") {
            gen_seeds();
        } else if (mode == "bsp" && argc > 3) {
            bsp_seeds(argv[3], argc > 4 ? argv[4] : "");
        } else if (mode == "doom" && argc > 3) {
            const doom::WadFile wad = doom::read_wad(argv[3]);
            std::optional<doom::WadFile> gl;
            if (argc > 4 && std::string(argv[4]) != "-")
                gl = doom::read_wad(argv[4]);
            const size_t maps = argc > 5 ? size_t(std::stoul(argv[5])) : 3;
            const std::string stem = fs::path(argc > 4 && gl ? argv[4] : argv[3]).stem().string();
            doom_map_seeds(gl && !gl->iwad && doom::map_names(*gl).size() > 0 ? *gl : wad,
                           gl && doom::map_names(*gl).empty() ? &*gl : nullptr, stem, maps);
            if (wad.iwad)
                doom_texture_seed(wad, fs::path(argv[3]).stem().string());
        } else {
            std::fprintf(stderr, "fuzz_make_seeds: unknown mode or missing file\n");
            return 2;
        }
        fs::remove_all(g_out / "tmp");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz_make_seeds: %s\n", e.what());
        return 1;
    }
    return 0;
}
