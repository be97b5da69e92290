// EverQuest zone archives <-> the zone model (wld/eq/eq_zone_writer.h, eq_zone_reader.h):
//  - a hand-built zone, Quake maps and generated zones written and read back answer the same:
//    regions, flags, PVS rows, point -> region, triangles (or surface area per texture), materials;
//  - write -> read -> write is byte-identical;
//  - bad archives fail with FileError only, naming member, fragment and offset;
//  - what the writer cannot express is refused with std::invalid_argument.
#include "tests/support/test_data.h"
#include "tests/wld/wld_test_bytes.h"
#include "visibility/bit_row.h"
#include "visibility/file_error.h"
#include "visibility/region_lookup.h"
#include "wld/common/read_file.h"
#include "wld/eq/eq_zone_reader.h"
#include "wld/eq/eq_zone_writer.h"
#include "wld/eq/pfs_archive.h"
#include "wld/eq/stb_image_io.h"
#include "wld/eq/wld_mesh.h"
#include "wld/eq/wld_file.h"
#include "gen/generate_zone.h"
#include "wld/zone_file.h"

#include <gtest/gtest.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>
#include <random>

namespace pvs {
namespace {

using eq::load_eq_zone;
using eq::write_eq_zone;

// ---- A small zone built by hand ----

// Four regions in the box [0, 256]^3, split by three planes and one slanted one:
//   x >= 128: y >= 128 -> region 0, else region 1
//   x <  128: z >= 64 -> (0.6x + 0.8y >= 100 -> region 2, else region 3), else outside
void add_quad(Zone& z, std::array<glm::vec3, 4> corners, uint32_t material, glm::vec2 uv0 = glm::vec2(0.0f))
{
    const auto base = static_cast<uint32_t>(z.mesh.positions.size());
    const glm::vec2 uvs[4] = {{0, 0}, {2, 0}, {2, 1.5f}, {0, 1.5f}};
    for (int i = 0; i < 4; ++i) {
        z.mesh.positions.push_back(corners[i]);
        z.mesh.uvs.push_back(uv0 + uvs[i]);
    }
    z.mesh.faces.push_back({static_cast<uint32_t>(z.mesh.triangle_count()), 2, material});
    z.mesh.indices.insert(z.mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

void hand_tree(Zone& z)
{
    z.tree.tie_rule = TieRule::OnPlaneGoesFront;
    z.tree.leaf_region = {0, 1, kLeafOutside, 2, 3};
    z.tree.nodes = {
        {{1, 0, 0}, 128.0f, {1, 2}},
        {{0, 1, 0}, 128.0f, {~0, ~1}},
        {{0, 0, 1}, 64.0f, {3, ~2}},
        {{0.6f, 0.8f, 0}, 100.0f, {~3, ~4}},
    };
    z.tree.root = 0;
}

void hand_materials(Zone& z)
{
    Material stone{"stone.bmp", 3, 2, {}, 0};
    std::vector<uint8_t> rgba(6 * 4);
    for (uint8_t i = 0; i < 6; ++i) {
        rgba[4 * i] = uint8_t(40 * i);
        rgba[4 * i + 1] = uint8_t(255 - 30 * i);
        rgba[4 * i + 2] = uint8_t(7 * i + 1);
        rgba[4 * i + 3] = 255;
    }
    set_material_rgba(stone, 3, 2, rgba);
    z.materials = {stone, Material{"grass.bmp", 0, 0, {}, 0}, Material{"clip.bmp", 0, 0, {}, kMaterialInvisible}};
}

void hand_faces(Zone& z)
{
    std::vector<std::vector<uint32_t>> faces(4);
    const auto quad = [&](uint32_t region, std::array<glm::vec3, 4> c, uint32_t material, glm::vec2 uv0 = {}) {
        faces[region].push_back(static_cast<uint32_t>(z.mesh.faces.size()));
        add_quad(z, c, material, uv0);
    };
    quad(0, {{{128, 128, 0}, {256, 128, 0}, {256, 256, 0}, {128, 256, 0}}}, 0);
    quad(0, {{{256, 128, 0}, {256, 256, 0}, {256, 256, 96}, {256, 128, 96}}}, 1);
    quad(1, {{{128, 0, 0}, {256, 0, 0}, {256, 128, 0}, {128, 128, 0}}}, 1);
    quad(1, {{{128, 0, 0}, {128, 0, 64}, {256, 0, 64}, {256, 0, 0}}}, 2);
    quad(2, {{{0, 128, 64}, {128, 128, 64}, {128, 256, 64}, {0, 256, 64}}}, 0);
    quad(2, {{{0, 256, 64}, {128, 256, 64}, {128, 256, 200}, {0, 256, 200}}}, 1);
    // uvs far past the old form's [-128, 128): the writer moves them by whole repeats.
    quad(3, {{{0, 0, 64}, {64, 0, 64}, {64, 32, 64}, {0, 32, 64}}}, 0, glm::vec2(300.0f, -1000.0f));
    z.region_face_offsets = {0};
    for (const auto& list : faces) {
        z.region_faces.insert(z.region_faces.end(), list.begin(), list.end());
        z.region_face_offsets.push_back(static_cast<uint32_t>(z.region_faces.size()));
    }
}

Zone hand_zone()
{
    Zone z;
    hand_tree(z);
    hand_materials(z);
    hand_faces(z);
    z.regions.resize(4);
    z.regions[0].flags = kRegionPvp;
    z.regions[1].flags = kRegionWater | kRegionSlime;
    z.regions[2].flags = kRegionZoneLine;
    z.regions[2].zone_line = 0;
    z.regions[3].flags = kRegionLava | kRegionIce | kRegionVWater;
    z.regions[0].bounds = {{128, 128, 0}, {256, 256, 256}};
    z.regions[1].bounds = {{128, 0, 0}, {256, 128, 256}};
    z.regions[2].bounds = {{0, 0, 64}, {128, 256, 256}};
    z.regions[3].bounds = {{0, 0, 64}, {128, 125, 256}};
    z.zone_lines.push_back({"qeynos", z.regions[2].bounds});
    const std::vector<std::vector<uint32_t>> rows = {{0, 1, 2}, {0, 1}, {0, 2, 3}};
    z.baked_pvs = Pvs::build(4, [&](uint32_t r, std::span<uint64_t> row) {
        if (r >= rows.size())
            return false; // region 3: a missing row
        for (const uint32_t v : rows[r])
            bits::set(row, v);
        return true;
    });
    return z;
}

// ---- Comparisons ----

using Triangle = std::array<float, 9>;

// Each region's triangles as a sorted list of vertex triples, each rotated to start at its
// smallest vertex (the winding is kept).
std::vector<std::vector<Triangle>> triangles_by_region(const Zone& z)
{
    std::vector<std::vector<Triangle>> out(z.region_count());
    for (uint32_t r = 0; r < z.region_count(); ++r) {
        for (const uint32_t f : z.faces_of_region(r)) {
            const Face& face = z.mesh.faces[f];
            for (uint32_t t = face.first_triangle; t < face.first_triangle + face.triangle_count; ++t) {
                std::array<std::array<float, 3>, 3> v;
                for (int k = 0; k < 3; ++k) {
                    const glm::vec3 p = z.mesh.positions[z.mesh.indices[3 * t + k]];
                    v[k] = {p.x, p.y, p.z};
                }
                std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
                Triangle tri;
                for (int k = 0; k < 9; ++k)
                    tri[k] = v[k / 3][k % 3];
                out[r].push_back(tri);
            }
        }
        std::sort(out[r].begin(), out[r].end());
    }
    return out;
}

void expect_same_flags(const Zone& a, const Zone& b, uint32_t ignored = 0)
{
    ASSERT_EQ(a.region_count(), b.region_count());
    for (uint32_t r = 0; r < a.region_count(); ++r)
        ASSERT_EQ(a.regions[r].flags & ~ignored, b.regions[r].flags) << "region " << r;
}

// Row by row; the writer adds each region's own bit (§7.4.9).
void expect_same_pvs(const Zone& a, const Zone& b)
{
    ASSERT_EQ(a.baked_pvs.has_value(), b.baked_pvs.has_value());
    if (!a.baked_pvs)
        return;
    const uint32_t n = a.baked_pvs->region_count();
    ASSERT_EQ(b.baked_pvs->region_count(), n);
    std::vector<uint64_t> ra(bits::words_for(n)), rb(bits::words_for(n));
    for (uint32_t r = 0; r < n; ++r) {
        a.baked_pvs->decode_row(r, ra);
        b.baked_pvs->decode_row(r, rb);
        bits::set(ra, r);
        ASSERT_EQ(ra, rb) << "PVS row " << r;
    }
}

// Whether the walk for `p` meets a split plane exactly (a tie, decided by the tie rule).
bool on_a_split_plane(const BspTree& tree, const glm::vec3& p)
{
    std::vector<PathStep> path;
    trace_point(tree, p, path);
    return std::any_of(path.begin(), path.end(), [&](const PathStep& step) {
        const BspNode& node = tree.nodes[step.node];
        return glm::dot(node.normal, p) - node.dist == 0.0f;
    });
}

// The same region (or none) for random points in and around the zone. A random float can land
// exactly on an axial plane (e1m1: y = 2176); such ties go back in Quake and front in EverQuest.
void expect_same_regions_for_points(const Zone& a, const Zone& b, int count, uint32_t seed)
{
    Aabb box = a.bounds();
    box.grow(box.min - 8.0f);
    box.grow(box.max + 8.0f);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> ux(box.min.x, box.max.x), uy(box.min.y, box.max.y), uz(box.min.z, box.max.z);
    int mismatches = 0;
    for (int i = 0; i < count; ++i) {
        const glm::vec3 p{ux(rng), uy(rng), uz(rng)};
        const int32_t ra = locate_point(a.tree, p).region, rb = locate_point(b.tree, p).region;
        // Quake's solid leaves become EverQuest's missing children: both "no region".
        if ((ra < 0 ? -1 : ra) == (rb < 0 ? -1 : rb) || on_a_split_plane(a.tree, p) || on_a_split_plane(b.tree, p))
            continue;
        if (mismatches++ < 5)
            ADD_FAILURE() << "point (" << p.x << ", " << p.y << ", " << p.z << "): region " << ra << " vs " << rb;
    }
    EXPECT_EQ(mismatches, 0);
}

void expect_same_materials(const Zone& a, const Zone& b)
{
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (size_t i = 0; i < a.materials.size(); ++i) {
        EXPECT_EQ(a.materials[i].name, b.materials[i].name);
        EXPECT_EQ(a.materials[i].flags, b.materials[i].flags) << a.materials[i].name;
        EXPECT_EQ(a.materials[i].width, b.materials[i].width) << a.materials[i].name;
        EXPECT_EQ(a.materials[i].height, b.materials[i].height) << a.materials[i].name;
        EXPECT_EQ(material_rgba(a.materials[i]), material_rgba(b.materials[i])) << a.materials[i].name;
    }
}

// Everything a written zone keeps exactly (triangles, when they sit on the mesh grid).
void expect_round_trip(const Zone& a, const Zone& b, int points)
{
    ASSERT_EQ(a.region_count(), b.region_count());
    expect_same_flags(a, b);
    expect_same_pvs(a, b);
    expect_same_regions_for_points(a, b, points, 12345);
    EXPECT_EQ(triangles_by_region(a), triangles_by_region(b));
    EXPECT_EQ(b.tree.tie_rule, TieRule::OnPlaneGoesFront);
}

Zone read_back(const std::vector<uint8_t>& s3d, const std::string& file = "zone.s3d")
{
    return load_eq_zone(s3d, file);
}

// ---- The hand-built zone ----

TEST(EqZoneRoundTrip, HandZoneReadsBackTheSame)
{
    const Zone a = hand_zone();
    const Zone b = read_back(write_eq_zone(a, "zone"));
    expect_round_trip(a, b, 10000);
    expect_same_materials(a, b);
    ASSERT_EQ(b.zone_lines.size(), 1u);
    EXPECT_EQ(b.zone_lines[0].target, "zone 255 point 0");
    EXPECT_EQ(b.regions[2].zone_line, 0);
    EXPECT_EQ(b.source.format, "EverQuest S3D/WLD");
    // Region bounds are the mesh's vertices; the zone line's are its region's.
    EXPECT_EQ(b.regions[0].bounds.min, glm::vec3(128, 128, 0));
    EXPECT_EQ(b.regions[0].bounds.max, glm::vec3(256, 256, 96));
    EXPECT_EQ(b.zone_lines[0].bounds.min, b.regions[2].bounds.min);
}

TEST(EqZoneRoundTrip, UvsMovedByWholeRepeatsOnly)
{
    const Zone a = hand_zone();
    const Zone b = read_back(write_eq_zone(a, "zone"));
    const Face& fa = a.mesh.faces[a.faces_of_region(3)[0]];
    const Face& fb = b.mesh.faces[b.faces_of_region(3)[0]];
    for (int k = 0; k < 3; ++k) {
        const glm::vec2 ua = a.mesh.uvs[a.mesh.indices[3 * fa.first_triangle + k]];
        const glm::vec2 ub = b.mesh.uvs[b.mesh.indices[3 * fb.first_triangle + k]];
        const glm::vec2 shift = ua - ub;
        EXPECT_EQ(shift, glm::round(shift));
        EXPECT_LT(std::abs(ub.x), 128.0f);
        EXPECT_LT(std::abs(ub.y), 128.0f);
    }
}

TEST(EqZoneRoundTrip, WriteReadWriteIsByteIdentical)
{
    for (const uint32_t version : {eq::kWldVersionOld, eq::kWldVersionNew}) {
        eq::EqWriteOptions options;
        options.wld_version = version;
        const std::vector<uint8_t> first = write_eq_zone(hand_zone(), "zone", options);
        EXPECT_EQ(write_eq_zone(read_back(first), "zone", options), first);
        EXPECT_EQ(write_eq_zone(hand_zone(), "zone", options), first) << "deterministic";
    }
}

// Zone line i is written as zone 255, zone point i. Read back, the targets are named so and are
// what writing again writes: no note that they are lost. A target from another format (a Quake
// changelevel's map name) is not representable, and the note says so, quoting it.
TEST(EqZoneRoundTrip, ZoneLineTargetsReadFromAnS3dAreNotNotedAsLost)
{
    const auto lost_note = [](const std::vector<std::string>& notes) {
        for (const std::string& note : notes)
            if (note.find("not representable") != std::string::npos)
                return note;
        return std::string();
    };
    Zone zone = gen::generate_zone({6, 3, 32.0f, false});
    ASSERT_FALSE(zone.zone_lines.empty());
    const Zone back = read_back(eq::write_eq_zone_archive(zone, "zone").bytes);
    ASSERT_EQ(back.zone_lines.size(), zone.zone_lines.size());
    EXPECT_EQ(back.zone_lines[0].target, "zone 255 point 0");
    EXPECT_EQ(lost_note(eq::write_eq_zone_archive(back, "zone").notes), "");
    Zone quake = back;
    quake.zone_lines[0].target = "e1m2";
    EXPECT_NE(lost_note(eq::write_eq_zone_archive(quake, "zone").notes).find("'e1m2'"), std::string::npos);
}

TEST(EqZoneRoundTrip, PositionsOffTheGridSettleInTheFirstWrite)
{
    Zone a = hand_zone();
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> jitter(-0.37f, 0.37f);
    for (glm::vec3& p : a.mesh.positions)
        p += glm::vec3(jitter(rng), jitter(rng), jitter(rng)) + glm::vec3(1000.0f, -3000.0f, 20.0f);
    const std::vector<uint8_t> first = write_eq_zone(a, "zone");
    const Zone b = read_back(first);
    EXPECT_EQ(write_eq_zone(b, "zone"), first);
    for (uint32_t r = 0; r < a.region_count(); ++r) {
        const auto ta = triangles_by_region(a)[r], tb = triangles_by_region(b)[r];
        ASSERT_EQ(ta.size(), tb.size());
        for (size_t t = 0; t < ta.size(); ++t)
            for (int k = 0; k < 9; ++k)
                EXPECT_NEAR(ta[t][k], tb[t][k], 1.0 / 256) << "region " << r; // scale >= 8 here
    }
}

TEST(EqZoneRoundTrip, RegionWithoutFacesKeepsItsBoundsInItsSphere)
{
    Zone a = hand_zone();
    a.region_faces.resize(a.region_face_offsets[3]); // region 3 loses its faces
    a.region_face_offsets[4] = a.region_face_offsets[3];
    a.regions[3].bounds = {{0.3f, 0.1f, 64.7f}, {128.2f, 125.0f, 256.0f}};
    const std::vector<uint8_t> first = write_eq_zone(a, "zone");
    const Zone b = read_back(first);
    EXPECT_TRUE(b.faces_of_region(3).empty());
    const Aabb& box = b.regions[3].bounds;
    EXPECT_TRUE(box.contains(a.regions[3].bounds.min) && box.contains(a.regions[3].bounds.max));
    EXPECT_EQ(write_eq_zone(b, "zone"), first);
}

TEST(EqZoneRoundTrip, LoadZoneRecognisesTheArchive)
{
    const auto path = std::filesystem::temp_directory_path() / "pvscope_eqzone_test.s3d";
    write_whole_file(path.string(), write_eq_zone(hand_zone(), "pvscope_eqzone_test"));
    const Zone z = load_zone(path.string());
    std::filesystem::remove(path);
    EXPECT_EQ(z.region_count(), 4u);
    EXPECT_EQ(z.source.format, "EverQuest S3D/WLD");
}

TEST(EqZoneRoundTrip, FindsTheOnlyZoneWldWhenTheStemDiffers)
{
    const Zone b = read_back(write_eq_zone(hand_zone(), "zone"), "renamed.s3d");
    EXPECT_EQ(b.region_count(), 4u);
}

TEST(EqZoneRoundTrip, NoPvsIsWrittenAsEmptyListsAndReadAsNone)
{
    Zone a = hand_zone();
    a.baked_pvs.reset();
    const eq::EqZoneArchive written = eq::write_eq_zone_archive(a, "zone");
    const Zone b = read_back(written.bytes);
    EXPECT_FALSE(b.baked_pvs.has_value());
    EXPECT_TRUE(std::any_of(b.source.notes.begin(), b.source.notes.end(),
                            [](const std::string& n) { return n.find("no PVS") != std::string::npos; }));
    EXPECT_TRUE(std::any_of(written.notes.begin(), written.notes.end(),
                            [](const std::string& n) { return n.find("no baked PVS") != std::string::npos; }));
}

// The zone WLD member of an archive (a WldFile views these bytes: keep them while it lives).
std::vector<uint8_t> zone_wld_bytes(const std::vector<uint8_t>& s3d)
{
    const eq::PfsArchive archive(s3d, "zone.s3d");
    return archive.read("zone.wld");
}

// A zone line in water is one 0x29 whose name says both (WTNTP...), so that a reader keeping one
// type per region (ZU: the first prefix that matches) still sees water, and LX/ES/WillEQ both.
TEST(EqZoneRoundTrip, ZoneLineInWaterIsOneCombinedFlag)
{
    Zone a = hand_zone();
    a.regions[2].flags = kRegionZoneLine | kRegionWater;
    const std::vector<uint8_t> s3d = write_eq_zone(a, "zone");
    const std::vector<uint8_t> wld_bytes = zone_wld_bytes(s3d);
    const eq::WldFile wld = eq::parse_wld(wld_bytes, "zone.wld");
    int combined = 0;
    for (uint32_t n = 1; n <= wld.fragments.size(); ++n) {
        if (wld.fragments[n - 1].type != eq::kWldRegionFlag)
            continue;
        const eq::WldRegionFlag flag = eq::parse_region_flag(wld, n);
        const bool holds_2 = std::find(flag.regions.begin(), flag.regions.end(), 2u) != flag.regions.end();
        if (flag.type.flags == (kRegionWater | kRegionZoneLine)) {
            ++combined;
            EXPECT_EQ(flag.regions, std::vector<uint32_t>{2});
            ASSERT_TRUE(flag.type.zone_line);
            EXPECT_EQ(flag.type.zone_line->zone_point, 0u);
        } else {
            EXPECT_FALSE(holds_2) << "region 2 is in no other list (type flags " << flag.type.flags << ")";
        }
    }
    EXPECT_EQ(combined, 1);
    const Zone b = read_back(s3d);
    EXPECT_EQ(b.regions[2].flags, kRegionZoneLine | kRegionWater);
    EXPECT_EQ(b.regions[2].zone_line, 0);
    EXPECT_EQ(b.zone_lines.size(), 1u) << "the empty DRNTP and the WTNTP of one destination are one line";
    EXPECT_EQ(write_eq_zone(b, "zone"), s3d) << "and it writes back the same";
    EXPECT_EQ(b.regions[1].flags, kRegionWater | kRegionSlime) << "plain water stays WT_ZONE";
}

// Every 0x36 carries its vertices' box, relative to its centre (WillEQ adds the centre).
TEST(EqZoneRoundTrip, MeshBoxesHoldTheirVerticesTightly)
{
    const std::vector<uint8_t> wld_bytes = zone_wld_bytes(write_eq_zone(hand_zone(), "zone"));
    const eq::WldFile wld = eq::parse_wld(wld_bytes, "zone.wld");
    int meshes = 0;
    for (uint32_t n = 1; n <= wld.fragments.size(); ++n) {
        if (wld.fragments[n - 1].type != eq::kWldMesh)
            continue;
        ++meshes;
        const eq::WldMesh mesh = eq::parse_mesh(wld, n);
        ASSERT_FALSE(mesh.positions.empty());
        const glm::vec3 lo = mesh.center + mesh.min, hi = mesh.center + mesh.max;
        glm::vec3 seen_lo(1e30f), seen_hi(-1e30f);
        for (const glm::vec3& p : mesh.positions) {
            seen_lo = glm::min(seen_lo, p);
            seen_hi = glm::max(seen_hi, p);
        }
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(lo[k], seen_lo[k], 1.0 / 64) << "fragment " << n << " axis " << k;
            EXPECT_NEAR(hi[k], seen_hi[k], 1.0 / 64) << "fragment " << n << " axis " << k;
            EXPECT_LE(lo[k], hi[k]);
        }
        EXPECT_GT(glm::length(hi - lo), 0.0f) << "not the zero box";
    }
    EXPECT_GT(meshes, 0);
}

// ---- Quake maps ----

double triangle_area(const Zone& z, uint32_t t)
{
    const glm::vec3 a = z.mesh.positions[z.mesh.indices[3 * t]], b = z.mesh.positions[z.mesh.indices[3 * t + 1]],
                    c = z.mesh.positions[z.mesh.indices[3 * t + 2]];
    return 0.5 * double(glm::length(glm::cross(b - a, c - a)));
}

// Surface area per texture name, each face counted once per region listing it.
std::map<std::string, double> area_by_texture(const Zone& z, const std::vector<std::string>& names)
{
    std::map<std::string, double> out;
    for (const uint32_t f : z.region_faces) {
        const Face& face = z.mesh.faces[f];
        for (uint32_t t = face.first_triangle; t < face.first_triangle + face.triangle_count; ++t)
            out[names[face.material]] += triangle_area(z, t);
    }
    return out;
}

bool any_note(const std::vector<std::string>& notes, const std::string& text)
{
    return std::any_of(notes.begin(), notes.end(),
                       [&](const std::string& n) { return n.find(text) != std::string::npos; });
}

class EqZoneQuake : public ::testing::TestWithParam<const char*> {};

TEST_P(EqZoneQuake, WrittenAsEverQuestAnswersTheSame)
{
    SHARED_DATA_OR_SKIP(path, GetParam());
    const Zone& a = *test::shared_zone(GetParam());
    const eq::EqZoneArchive written = eq::write_eq_zone_archive(a, "quake");
    const Zone b = read_back(written.bytes, "quake.s3d");

    ASSERT_EQ(a.region_count(), b.region_count());
    expect_same_flags(a, b, kRegionSky);
    const bool sky =
        std::any_of(a.regions.begin(), a.regions.end(), [](const Region& r) { return (r.flags & kRegionSky) != 0; });
    EXPECT_EQ(any_note(written.notes, "sky regions"), sky);
    EXPECT_TRUE(any_note(written.notes, "split plane")) << "the tie rule change is noted";
    expect_same_pvs(a, b);
    expect_same_regions_for_points(a, b, 100000, 777);

    std::vector<std::string> read_names;
    for (const Material& m : b.materials)
        read_names.push_back(m.name);
    const auto area_a = area_by_texture(a, eq::eq_texture_file_names(a));
    const auto area_b = area_by_texture(b, read_names);
    ASSERT_EQ(area_a.size(), area_b.size());
    double worst = 0.0;
    for (const auto& [name, area] : area_a) {
        ASSERT_TRUE(area_b.count(name)) << name;
        worst = std::max(worst, std::abs(area_b.at(name) - area) / area);
        EXPECT_NEAR(area_b.at(name), area, area * 1e-3) << name;
    }
    std::printf("[ %s ] %zu regions, %zu textures, worst area difference %.2e, archive %zu bytes\n", GetParam(),
                a.region_count(), area_a.size(), worst, written.bytes.size());
}

INSTANTIATE_TEST_SUITE_P(SharedData, EqZoneQuake,
                         ::testing::Values("quake/e1m1.bsp", "quake/e1m2.bsp", "quake/e2m1.bsp", "quake/dm2.bsp",
                                           "quake/end.bsp", "quake/start.bsp"),
                         [](const auto& p) { return test::param_name(p.param); });

// ---- Generated zones ----

class EqZoneGenerated : public ::testing::TestWithParam<int> {};

TEST_P(EqZoneGenerated, ReadsBackTheSameAndWritesBackIdentically)
{
    const Zone a = gen::generate_zone({.rooms = GetParam(), .seed = 99, .cell_size = 32.0f});
    const std::vector<uint8_t> first = write_eq_zone(a, "gen");
    const Zone b = read_back(first, "gen.s3d");
    expect_round_trip(a, b, 10000);
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (size_t i = 0; i < a.materials.size(); ++i)
        EXPECT_EQ(a.materials[i].width * a.materials[i].height, b.materials[i].width * b.materials[i].height);
    EXPECT_EQ(a.zone_lines.size(), b.zone_lines.size());
    EXPECT_EQ(write_eq_zone(b, "gen"), first);
}

INSTANTIATE_TEST_SUITE_P(Rooms, EqZoneGenerated, ::testing::Values(5, 60));

// ---- Bad input ----

void expect_loads_or_file_error(const std::vector<uint8_t>& bytes, const std::string& what)
{
    try {
        (void)load_eq_zone(bytes, "zone.s3d");
    } catch (const FileError&) {
    } catch (const std::exception& e) {
        ADD_FAILURE() << what << ": " << typeid(e).name() << ": " << e.what();
    }
}

TEST(EqZoneBadInput, TruncatedArchivesFailCleanly)
{
    const std::vector<uint8_t> good = write_eq_zone(hand_zone(), "zone");
    for (size_t i = 0; i < 200; ++i) {
        const std::vector<uint8_t> cut(good.begin(), good.begin() + std::ptrdiff_t(good.size() * i / 200));
        expect_loads_or_file_error(cut, "cut at " + std::to_string(cut.size()));
    }
}

// The archive with its zone WLD replaced by what `edit` makes of it.
std::vector<uint8_t> with_wld(const std::vector<uint8_t>& s3d, const std::function<void(std::vector<uint8_t>&)>& edit)
{
    const eq::PfsArchive archive(s3d, "zone.s3d");
    std::vector<eq::PfsMember> members;
    for (const std::string& name : archive.members()) {
        members.push_back({name, archive.read(name)});
        if (name == "zone.wld")
            edit(members.back().data);
    }
    return eq::write_pfs(members);
}

TEST(EqZoneBadInput, RandomByteChangesFailCleanly)
{
    const std::vector<uint8_t> good = write_eq_zone(hand_zone(), "zone");
    std::mt19937 rng(2024);
    for (int i = 0; i < 200; ++i) {
        std::vector<uint8_t> bad = good;
        bad[rng() % bad.size()] ^= uint8_t(1 + rng() % 255);
        expect_loads_or_file_error(bad, "archive change " + std::to_string(i));
    }
    // The archive's checksums catch most of those; these go past them, into the WLD.
    for (int i = 0; i < 200; ++i) {
        const std::vector<uint8_t> bad = with_wld(good, [&](std::vector<uint8_t>& wld) {
            for (int k = 0; k < 1 + i % 3; ++k)
                wld[rng() % wld.size()] ^= uint8_t(1 + rng() % 255);
        });
        expect_loads_or_file_error(bad, "WLD change " + std::to_string(i));
    }
}

TEST(EqZoneBadInput, NoZoneWldListsTheMembers)
{
    const std::vector<uint8_t> bmp = encode_bmp(1, 1, std::vector<uint8_t>{1, 2, 3, 255});
    const std::vector<uint8_t> s3d = eq::write_pfs({{"stone.bmp", bmp}, {"objects.wld", {1, 2, 3}}});
    try {
        (void)load_eq_zone(s3d, "zone.s3d");
        FAIL() << "no error";
    } catch (const FileError& e) {
        EXPECT_NE(std::string(e.what()).find("no zone WLD"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("'stone.bmp'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("'objects.wld'"), std::string::npos) << e.what();
    }
}

struct FragmentAt {
    uint32_t number;
    uint64_t body;
};

FragmentAt find_fragment(const std::vector<uint8_t>& wld, uint32_t type, int nth = 0)
{
    const eq::WldFile file = eq::parse_wld(wld, "zone.wld");
    for (uint32_t n = 1; n <= file.fragments.size(); ++n)
        if (file.fragments[n - 1].type == type && nth-- == 0)
            return {n, file.fragments[n - 1].body_offset};
    throw std::logic_error("no such fragment");
}

using eq::wld_test::put_u32;

// Loads, expecting a FileError in the zone WLD at `offset` whose reason names the fragment.
void expect_wld_error(const std::vector<uint8_t>& s3d, uint32_t fragment, uint64_t offset, const std::string& text)
{
    try {
        (void)load_eq_zone(s3d, "zone.s3d");
        FAIL() << "no error";
    } catch (const FileError& e) {
        EXPECT_EQ(e.file(), "zone.s3d: member 'zone.wld'");
        EXPECT_EQ(e.offset(), offset) << e.what();
        EXPECT_NE(e.reason().find("fragment " + std::to_string(fragment) + " "), std::string::npos) << e.what();
        EXPECT_NE(e.reason().find(text), std::string::npos) << e.what();
    }
}

TEST(EqZoneBadInput, TreeCycle)
{
    const std::vector<uint8_t> good = write_eq_zone(hand_zone(), "zone");
    FragmentAt tree{};
    const auto bad = with_wld(good, [&](std::vector<uint8_t>& wld) {
        tree = find_fragment(wld, eq::kWldBspTree);
        put_u32(wld, tree.body + 8 + 28 * 1 + 20, 1); // node 2's front child is the root
    });
    expect_wld_error(bad, tree.number, tree.body + 8, "cycle");
}

TEST(EqZoneBadInput, RegionNumberPastTheRegions)
{
    const std::vector<uint8_t> good = write_eq_zone(hand_zone(), "zone");
    FragmentAt tree{};
    const auto bad = with_wld(good, [&](std::vector<uint8_t>& wld) {
        tree = find_fragment(wld, eq::kWldBspTree);
        put_u32(wld, tree.body + 8 + 28 * 2 + 16, 5); // node 3 is region 1's leaf; the file has 4
    });
    expect_wld_error(bad, tree.number, tree.body + 8 + 28 * 2 + 16, "region 5 is out of range");
}

TEST(EqZoneBadInput, VislistPastTheFragment)
{
    const std::vector<uint8_t> good = write_eq_zone(hand_zone(), "zone");
    FragmentAt region{};
    const auto bad = with_wld(good, [&](std::vector<uint8_t>& wld) {
        region = find_fragment(wld, eq::kWldRegion, 1);
        wld[region.body + 0x48] = 0xFF; // range_count of the §4.7 layout
        wld[region.body + 0x49] = 0xFF;
    });
    expect_wld_error(bad, region.number, region.body + 0x4A, "vis list 1");
}

TEST(EqZoneBadInput, MalformedVislist)
{
    const std::vector<uint8_t> good = write_eq_zone(hand_zone(), "zone");
    FragmentAt region{};
    uint16_t length = 0;
    const auto bad = with_wld(good, [&](std::vector<uint8_t>& wld) {
        region = find_fragment(wld, eq::kWldRegion, 2);
        std::memcpy(&length, &wld[region.body + 0x48], 2);
        std::fill_n(&wld[region.body + 0x4A], length - 1, uint8_t{0x00}); // no-op skips
        wld[region.body + 0x4A + length - 1] = 0x3F;                     // a skip without its u16
    });
    ASSERT_GE(length, 2);
    expect_wld_error(bad, region.number, region.body + 0x4A + length - 1, "VISLIST of region 2 is malformed");
}

// ---- Writer refusals ----

TEST(EqZoneWriter, RefusesARegionThatIsTwoLeaves)
{
    Zone z = hand_zone();
    z.tree.leaf_region[2] = 0; // the outside leaf becomes region 0 as well
    try {
        (void)write_eq_zone(z, "zone");
        FAIL() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("region 0 is 2 leaves"), std::string::npos) << e.what();
    }
}

TEST(EqZoneWriter, RefusesARegionMeshOver65535Vertices)
{
    Zone z;
    z.tree.leaf_region = {0};
    z.tree.root = ~0;
    z.regions.resize(1);
    z.materials.push_back({"m.bmp", 0, 0, {}, 0});
    for (uint32_t t = 0; t < 22000; ++t) {
        const glm::vec3 o(float(t % 200), float(t / 200), 0.0f);
        z.mesh.positions.insert(z.mesh.positions.end(), {o, o + glm::vec3(0.5f, 0, 0), o + glm::vec3(0, 0.5f, 0)});
        z.mesh.indices.insert(z.mesh.indices.end(), {3 * t, 3 * t + 1, 3 * t + 2});
        z.mesh.faces.push_back({t, 1, 0});
        z.region_faces.push_back(t);
    }
    z.region_face_offsets = {0, 22000};
    try {
        (void)write_eq_zone(z, "zone");
        FAIL() << "no error";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("66000 vertices"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("65535"), std::string::npos) << e.what();
    }
}

TEST(EqZoneWriter, TextureNamesAreSanitizedAndUnique)
{
    Zone z;
    z.materials = {{"*Water0", 0, 0, {}, 0}, {"_water0", 0, 0, {}, 0}, {"", 0, 0, {}, 0}, {"Stone.BMP", 0, 0, {}, 0}};
    EXPECT_EQ(eq::eq_texture_file_names(z),
              (std::vector<std::string>{"_water0.bmp", "_water0_2.bmp", "texture.bmp", "stone.bmp"}));
}

// ---- BMP ----

TEST(EqZoneBmp, TwentyFourBitRoundTripKeepsColours)
{
    std::vector<uint8_t> rgba;
    for (uint8_t i = 0; i < 5 * 3; ++i)
        rgba.insert(rgba.end(), {uint8_t(i * 17), uint8_t(255 - i), uint8_t(i * 3), 255});
    const auto image = decode_bmp(encode_bmp(5, 3, rgba));
    ASSERT_TRUE(image.has_value());
    EXPECT_EQ(image->width, 5u);
    EXPECT_EQ(image->height, 3u);
    EXPECT_EQ(image->rgba, rgba);
}

// A 2x2 8-bit palettized BMP, the originals' kind, written out by hand.
std::vector<uint8_t> palettized_bmp()
{
    std::vector<uint8_t> b = {'B', 'M', 0, 0, 0, 0, 0, 0, 0, 0, 14 + 40 + 8, 0, 0, 0, // file header
                              40, 0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 0, 1, 0, 8, 0,        // size, w, h, planes, bpp
                              0, 0, 0, 0, 8, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,         // BI_RGB, image size
                              2, 0, 0, 0, 0, 0, 0, 0,                                 // 2 palette colours
                              0x10, 0x20, 0x30, 0, 0xA0, 0xB0, 0xC0, 0,               // palette (B, G, R, 0)
                              1, 0, 0, 0, 0, 1, 0, 0};                                // bottom row, top row
    const auto size = uint32_t(b.size());
    std::memcpy(&b[2], &size, 4);
    return b;
}

TEST(EqZoneBmp, DecodesPalettizedBitmaps)
{
    const auto image = decode_bmp(palettized_bmp());
    ASSERT_TRUE(image.has_value());
    EXPECT_EQ(image->rgba, (std::vector<uint8_t>{0x30, 0x20, 0x10, 255, 0xC0, 0xB0, 0xA0, 255, // top row
                                                 0xC0, 0xB0, 0xA0, 255, 0x30, 0x20, 0x10, 255}));
}

TEST(EqZoneBmp, RefusesHeadersLargerThanTheFile)
{
    std::vector<uint8_t> b = palettized_bmp();
    const uint32_t side = 16000;
    std::memcpy(&b[18], &side, 4);
    std::memcpy(&b[22], &side, 4);
    std::string why;
    EXPECT_FALSE(decode_bmp(b, &why).has_value());
    EXPECT_NE(why.find("needs more bytes"), std::string::npos) << why;
    EXPECT_FALSE(decode_bmp(std::vector<uint8_t>{'B', 'M', 1}).has_value());
}

// Random byte changes give an image whose pixels the file's bytes can hold (at least one bit
// each), with width x height x 4 bytes of RGBA, or nullopt with a reason: never a crash.
TEST(EqZoneBmp, RandomByteChangesGiveAWholeImageOrAReason)
{
    const std::vector<uint8_t> good = encode_bmp(7, 5, std::vector<uint8_t>(7 * 5 * 4, 200));
    std::mt19937 rng(7);
    for (int i = 0; i < 2000; ++i) {
        std::vector<uint8_t> bad = i % 2 ? good : palettized_bmp();
        for (int k = 0; k < 1 + i % 4; ++k)
            bad[rng() % bad.size()] = uint8_t(rng());
        std::string why;
        const std::optional<RgbaImage> image = decode_bmp(bad, &why);
        if (!image) {
            EXPECT_FALSE(why.empty()) << "case " << i;
            continue;
        }
        ASSERT_GT(image->width, 0u) << "case " << i;
        ASSERT_GT(image->height, 0u) << "case " << i;
        ASSERT_LE(uint64_t(image->width) * image->height, 8 * uint64_t(bad.size())) << "case " << i;
        ASSERT_EQ(image->rgba.size(), size_t(image->width) * image->height * 4) << "case " << i;
    }
}

TEST(EqZoneRoundTrip, MissingTexturesAreNoted)
{
    const Zone b = read_back(write_eq_zone(hand_zone(), "zone"));
    EXPECT_TRUE(any_note(b.source.notes, "'grass.bmp'"));
    EXPECT_TRUE(any_note(b.source.notes, "winding"));
}

} // namespace
} // namespace pvs
