#include "wld/doom/gl_pvs_writer.h"

#include "visibility/bit_row.h"
#include "visibility/codec/glvis_rows.h"
#include "visibility/file_error.h"
#include "wld/common/read_file.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <limits>
#include <optional>
#include <stdexcept>
#include <unistd.h>

namespace pvs::doom {

namespace {

namespace fs = std::filesystem;

constexpr std::array<const char*, 4> kGlGroup = {"GL_VERT", "GL_SEGS", "GL_SSECT", "GL_NODES"};
constexpr size_t kGlPvsSlot = 5; // GL_PVS sits right after GL_NODES (marker + 4)
constexpr uint64_t kSectorBytes = 26;

std::string lump_label(const WadFile& file, size_t lump)
{
    return "lump " + std::to_string(lump) + " '" + file.lumps[lump].name + "'";
}

// The callers hold indices from an earlier read; a mismatch means the file changed since.
[[noreturn]] void changed(const WadFile& file, size_t lump, const std::string& reason)
{
    const uint64_t at = lump < file.lumps.size() ? file.lumps[lump].directory_offset : 4; // 4: the lump count
    throw FileError(file.path, at, reason + " (was the file changed since it was read?)");
}

void check_gl_group(const WadFile& file, size_t gl_marker)
{
    if (gl_marker >= file.lumps.size() || file.lumps.size() - gl_marker < 1 + kGlGroup.size())
        changed(file, file.lumps.size(), "no GL group at lump " + std::to_string(gl_marker) + ": the file has " +
                                             std::to_string(file.lumps.size()) + " lumps");
    if (file.lumps[gl_marker].name.rfind("GL_", 0) != 0)
        changed(file, gl_marker, lump_label(file, gl_marker) + " is not a GL marker (GL_<map> or GL_LEVEL)");
    for (size_t k = 0; k < kGlGroup.size(); ++k)
        if (file.lumps[gl_marker + 1 + k].name != kGlGroup[k])
            changed(file, gl_marker + 1 + k,
                    lump_label(file, gl_marker + 1 + k) + " should be " + kGlGroup[k] + " of the GL group at lump " +
                        std::to_string(gl_marker));
}

bool is_map_marker(const WadFile& file, size_t lump)
{
    return lump + 2 < file.lumps.size() && file.lumps[lump + 1].name == "THINGS" && file.lumps[lump + 2].name == "LINEDEFS";
}

// The lump called `name` among the map's own lumps: after its marker, before the next map's.
size_t map_lump(const WadFile& file, size_t map_marker, const std::string& name)
{
    if (!is_map_marker(file, map_marker))
        changed(file, map_marker,
                (map_marker < file.lumps.size() ? lump_label(file, map_marker) : "lump " + std::to_string(map_marker)) +
                    " is not a map marker followed by THINGS and LINEDEFS");
    for (size_t i = map_marker + 1; i < file.lumps.size() && !is_map_marker(file, i); ++i)
        if (file.lumps[i].name == name)
            return i;
    changed(file, map_marker, "the map at " + lump_label(file, map_marker) + " has no " + name + " lump");
}

void check_sector_count(const WadFile& file, size_t map_marker, uint32_t sector_count)
{
    const size_t sectors = map_lump(file, map_marker, "SECTORS");
    if (file.lumps[sectors].size != uint64_t(sector_count) * kSectorBytes)
        changed(file, sectors, lump_label(file, sectors) + " holds " + std::to_string(file.lumps[sectors].size) +
                                   " bytes, not the " + std::to_string(sector_count) + " sectors of 26 bytes expected");
}

// The name as the file spells it: WadFile upper-cases names, a rewrite must not.
std::string stored_name(const WadFile& file, size_t lump)
{
    const WadLump& entry = file.lumps[lump];
    if (uint64_t(entry.directory_offset) + 16 > file.bytes.size())
        return entry.name; // a WadFile made by hand, not by parse_wad
    const uint8_t* raw = file.bytes.data() + entry.directory_offset + 8;
    std::string name(reinterpret_cast<const char*>(raw), strnlen(reinterpret_cast<const char*>(raw), 8));
    std::string upper = name;
    std::transform(upper.begin(), upper.end(), upper.begin(), [](char c) { return char(std::toupper(uint8_t(c))); });
    return upper == entry.name ? name : entry.name;
}

std::vector<WadLumpData> lump_list(const WadFile& file)
{
    std::vector<WadLumpData> lumps;
    lumps.reserve(file.lumps.size() + 1);
    for (size_t i = 0; i < file.lumps.size(); ++i) {
        const std::span<const uint8_t> data = file.data(i);
        lumps.push_back({stored_name(file, i), std::vector<uint8_t>(data.begin(), data.end())});
    }
    return lumps;
}

// Edits `lumps` (the lumps of `file`, in its order). Only put_gl_pvs may insert, and it runs
// last, so every index taken from `file` still holds when the edits are combined.
void put_reject(const WadFile& file, size_t map_marker, std::span<const uint8_t> reject, std::vector<WadLumpData>& lumps)
{
    lumps[map_lump(file, map_marker, "REJECT")].bytes.assign(reject.begin(), reject.end());
}

bool put_gl_pvs(const WadFile& file, size_t gl_marker, std::span<const uint8_t> gl_pvs, std::vector<WadLumpData>& lumps)
{
    check_gl_group(file, gl_marker);
    const size_t slot = gl_marker + kGlPvsSlot;
    if (slot < file.lumps.size() && file.lumps[slot].name == "GL_PVS") {
        lumps[slot].bytes.assign(gl_pvs.begin(), gl_pvs.end());
        return false;
    }
    lumps.insert(lumps.begin() + std::ptrdiff_t(slot), WadLumpData{"GL_PVS", {gl_pvs.begin(), gl_pvs.end()}});
    return true;
}

std::vector<uint8_t> pack(const WadFile& file, std::span<const WadLumpData> lumps)
{
    std::vector<uint8_t> out = write_wad(file.iwad, lumps);
    if (out.size() > size_t(std::numeric_limits<int32_t>::max()))
        throw std::invalid_argument(file.path + ": the new file would exceed the WAD format's 2 GiB");
    return out;
}

void check_square(const Pvs& pvs)
{
    if (!pvs.square())
        throw std::invalid_argument("a GL_PVS needs one row per subsector: the PVS has " + std::to_string(pvs.row_count()) +
                                    " rows of " + std::to_string(pvs.region_count()) + " bits");
}

bool same_file(const std::string& a, const std::string& b)
{
    std::error_code ec;
    const bool same = fs::equivalent(a, b, ec);
    return ec ? a == b : same;
}


// Backs `original` up (when asked), then replaces it by `bytes`. Returns the backup's path.
std::string rewrite(const WadFile& original, const std::vector<uint8_t>& bytes, bool backup)
{
    std::string backup_path;
    if (backup) {
        backup_path = gl_pvs_backup_path(original.path);
        replace_atomically(backup_path, original.bytes); // the bytes as read: what the file held
    }
    replace_atomically(original.path, bytes);
    return backup_path;
}

} // namespace

std::string gl_pvs_backup_path(const std::string& path)
{
    fs::path p(path);
    std::string extension = p.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](char c) { return char(std::tolower(uint8_t(c))); });
    p.replace_extension(extension == ".gwa" ? ".~gw" : ".~wa");
    return p.string();
}

size_t gl_subsector_count(const WadFile& file, size_t gl_marker)
{
    check_gl_group(file, gl_marker);
    const auto magic = [](std::span<const uint8_t> lump, const char* tag) {
        return lump.size() >= 4 && std::memcmp(lump.data(), tag, 4) == 0;
    };
    const size_t ssect = gl_marker + 3;
    const std::span<const uint8_t> records = file.data(ssect);
    size_t header = 0, record = 4; // V1, V2
    if (magic(file.data(gl_marker + 1), "gNd5")) {
        record = 8; // V5: no magic in GL_SSECT
    } else if (magic(file.data(gl_marker + 2), "gNd3")) {
        if (!magic(records, "gNd3"))
            changed(file, ssect, lump_label(file, ssect) + " of a V3 group does not start with \"gNd3\"");
        header = 4;
        record = 8;
    }
    if (records.size() < header || (records.size() - header) % record != 0)
        changed(file, ssect, lump_label(file, ssect) + " holds " + std::to_string(records.size()) +
                                 " bytes, not whole records of " + std::to_string(record) + " bytes");
    return (records.size() - header) / record;
}

std::vector<uint8_t> gl_pvs_lump(const Pvs& pvs)
{
    check_square(pvs);
    const size_t count = pvs.region_count();
    const size_t words = pvs.words_per_row();
    std::vector<uint64_t> rows(count * words);
    for (uint32_t r = 0; r < count; ++r)
        pvs.decode_row(r, std::span<uint64_t>(rows).subspan(r * words, words));
    std::vector<uint8_t> lump;
    encode_glvis_rows(rows, count, lump);
    return lump;
}

std::vector<uint8_t> reject_from_pvs(const Pvs& pvs, std::span<const uint32_t> sector_of_subsector,
                                     uint32_t sector_count)
{
    check_square(pvs);
    const size_t count = pvs.region_count();
    if (sector_of_subsector.size() != count)
        throw std::invalid_argument("REJECT needs one sector per subsector: " + std::to_string(sector_of_subsector.size()) +
                                    " sectors for " + std::to_string(count) + " subsectors");
    for (size_t i = 0; i < count; ++i)
        if (sector_of_subsector[i] >= sector_count)
            throw std::invalid_argument("subsector " + std::to_string(i) + " is in sector " +
                                        std::to_string(sector_of_subsector[i]) + " of " + std::to_string(sector_count));
    const uint64_t n = sector_count;
    // Everything rejected to start with (padding bits too, as glVIS starts from all 1s).
    std::vector<uint8_t> reject(bits::bytes_for(n * n), 0xFF);
    std::vector<uint64_t> row(pvs.words_per_row());
    for (uint32_t i = 0; i < count; ++i) {
        pvs.decode_row(i, row);
        const uint64_t from = uint64_t(sector_of_subsector[i]) * n;
        bits::for_each_set(row, [&](size_t j) {
            if (j >= count)
                return;
            const uint64_t bit = from + sector_of_subsector[j];
            reject[bit >> 3] &= uint8_t(~(1u << (bit & 7)));
        });
    }
    return reject;
}

std::vector<uint8_t> with_gl_pvs(const WadFile& file, size_t gl_marker, std::span<const uint8_t> gl_pvs_lump)
{
    std::vector<WadLumpData> lumps = lump_list(file);
    put_gl_pvs(file, gl_marker, gl_pvs_lump, lumps);
    return pack(file, lumps);
}

std::vector<uint8_t> with_reject(const WadFile& file, size_t map_marker, std::span<const uint8_t> reject_lump)
{
    std::vector<WadLumpData> lumps = lump_list(file);
    put_reject(file, map_marker, reject_lump, lumps);
    return pack(file, lumps);
}

GlPvsWriteResult write_gl_pvs(const MapSource& source, const Pvs& pvs, std::span<const uint32_t> sector_of_subsector,
                              uint32_t sector_count, const GlPvsWriteOptions& options)
{
    const WadFile gl = read_wad(source.gl_path);
    const size_t subsectors = gl_subsector_count(gl, source.gl_marker);
    check_square(pvs);
    if (pvs.region_count() != subsectors)
        throw std::invalid_argument("the PVS has " + std::to_string(pvs.region_count()) + " regions but the GL group in " +
                                    source.gl_path + " has " + std::to_string(subsectors) + " subsectors");

    // Every new byte is made before anything is written, so an error leaves the files alone.
    GlPvsWriteResult result;
    result.gl_file = source.gl_path;
    std::vector<WadLumpData> gl_lumps = lump_list(gl);
    std::optional<WadFile> wad; // the WAD, when REJECT goes to a file other than the GL file
    std::vector<uint8_t> new_wad;
    if (options.rebuild_reject) {
        const bool one_file = same_file(source.wad_path, source.gl_path);
        if (!one_file)
            wad = read_wad(source.wad_path);
        const WadFile& map_file = one_file ? gl : *wad;
        check_sector_count(map_file, source.map_marker, sector_count);
        const std::vector<uint8_t> reject = reject_from_pvs(pvs, sector_of_subsector, sector_count);
        if (one_file) {
            put_reject(gl, source.map_marker, reject, gl_lumps); // before put_gl_pvs may insert
        } else {
            std::vector<WadLumpData> wad_lumps = lump_list(*wad);
            put_reject(*wad, source.map_marker, reject, wad_lumps);
            new_wad = pack(*wad, wad_lumps);
        }
    }
    result.inserted = put_gl_pvs(gl, source.gl_marker, gl_pvs_lump(pvs), gl_lumps);
    const std::vector<uint8_t> new_gl = pack(gl, gl_lumps);

    if (wad)
        result.wad_backup_file = rewrite(*wad, new_wad, options.backup);
    result.backup_file = rewrite(gl, new_gl, options.backup);
    result.reject_written = options.rebuild_reject;
    return result;
}

} // namespace pvs::doom
