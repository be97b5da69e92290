// EverQuest PFS archives (.s3d; the same container as .eqg/.pfs): reading members and writing
// archives, ../shared/formats/eq-s3d-wld.md §1 (the section numbers below are that file's).
//
// Layout: a 12-byte header (index offset, "PFS ", version 0x00020000), one run of zlib blocks
// per stored file, the index (count, then {filename CRC, data offset, inflated size}), and an
// optional 9-byte "STEVE" footer. The names live in a stored file of their own, the entry with
// CRC 0x61580AC9; each name pairs with the entry holding CRC(name + NUL) (wld/eq/pfs_crc.h).
//
// Opening checks the whole structure and inflates nothing but the name list: header, magic,
// version; the index inside the file; every data offset inside the file and after the header; no
// two entries with the same CRC; every block header of every run inside the file, each block's
// inflated size 1..8192 and no more than zlib could produce from its compressed bytes (1032:1),
// the blocks' sizes adding up exactly to the entry's size; no run overlapping another run or the
// index; a name list no larger than its names can use (4 + 1028 bytes a name), its count equal
// to entry_count - 1, and every name paired with an entry. read() inflates every block of a
// member and checks each against its declared size, and each block's Adler-32.
//
// Hostile input: nothing is allocated from a declared size before the bytes it comes from were
// found in the file, and a member's output grows block by block as its blocks really inflate, so
// a lying header cannot allocate gigabytes (a member that truly inflates to its declared size,
// at most 4 GiB, is returned in full). Every problem throws pvs::FileError naming the archive
// (and the member, as "zone.s3d: member 'gfaydark.wld'", or "zone.s3d: name list"), the absolute
// offset, and what is wrong. A problem inside the inflated name list is reported at the offset
// of the list's first block, with the byte within the list in the message.
//
// Where the examined readers disagree, pvscope does this (docs/formats-eq.md has the reasons):
//  - Pairing names with entries (§1.7): by the CRC of the lowercased name + NUL (WQ, ZU, QL, and
//    the case-insensitive client); if no entry has that CRC, by the CRC of the name as stored
//    (LQ hashes names as given, so LQ-written archives with mixed-case names still open). Never
//    by data offset (EV): a name whose CRC matches no entry is an error, not a guess, because
//    every CRC-based reader, and presumably the client, would not find that file either.
//  - The name count must equal entry_count - 1 (§1.5 "must"; WQ and ZU silently drop entries).
//  - The name list is the entry with CRC 0x61580AC9. When no entry has it but one has
//    0xFFFFFFFF, that one is taken (archives made by EQZip, §1.4; QL reads those too).
//  - Version must be 0x00020000 (LQ, QL; WQ and ZU check only the magic).
//  - Blocks: each inflates to 1..8192 bytes (LQ; the client crashes above 8192). A block that
//    is not a file's last may hold fewer than 8192 bytes (WQ, ZU, QL accept it; only LQ does
//    not). A block overshooting its entry's size is an error (LQ), not truncated.
//  - Runs may sit anywhere after the header with gaps between them (only QL needs them
//    contiguous); index order does not matter (no reader depends on it).
//  - Footer: "STEVE" right after the index; its timestamp is read big-endian (LQ's reading of
//    the originals; ZU and QL use little-endian). Other bytes after the index are ignored (LQ,
//    WQ, ZU; QL would reject them).
//  - Names: 1..1023 bytes other than NUL, then a NUL (LQ's limit). Two names equal ignoring ASCII
//    case are an error, because a case-insensitive lookup could not tell them apart. Bytes after
//    the last name in the name list are ignored (no reader looks at them).
//
// Writing follows §1.9 exactly; see write_pfs.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace pvs::eq {

inline constexpr uint32_t kPfsVersion = 0x00020000;
inline constexpr uint32_t kPfsMaxBlockSize = 8192; // inflated bytes per block (§1.3)

// One stored file as the archive describes it.
struct PfsEntry {
    std::string name;          // as stored in the name list
    uint32_t crc = 0;          // the index entry's filename CRC
    uint32_t data_offset = 0;  // absolute offset of its first block header
    uint32_t size = 0;         // inflated size
    uint64_t stored_size = 0;  // bytes its block run occupies (block headers + zlib data)
    uint32_t block_count = 0;
};

class PfsArchive {
public:
    // Copies `bytes` and checks the structure (see above). `file_name` names the archive in errors.
    PfsArchive(std::span<const uint8_t> bytes, std::string file_name);
    static PfsArchive load(const std::string& path); // read_whole_file + the constructor

    const std::string& file_name() const { return file_name_; }
    // Member names in name-list order, as stored.
    const std::vector<std::string>& members() const { return names_; }
    // The members' index entries, in name-list order.
    const std::vector<PfsEntry>& entries() const { return entries_; }
    // Whether a member has this name, ignoring ASCII case (as the client does).
    bool contains(std::string_view name) const;
    // The member's inflated bytes; the name ignores ASCII case. Throws FileError for a missing
    // member or bad data.
    std::vector<uint8_t> read(std::string_view name) const;
    // The footer's timestamp read big-endian, or nullopt without a "STEVE" footer.
    std::optional<uint32_t> footer_timestamp() const { return footer_timestamp_; }

private:
    std::vector<uint8_t> inflate_run(uint32_t data_offset, uint32_t size, const std::string& what) const;

    std::vector<uint8_t> bytes_;
    std::string file_name_;
    std::vector<std::string> names_;
    std::vector<PfsEntry> entries_;
    std::unordered_map<std::string, size_t> by_lowercase_name_;
    uint32_t index_offset_ = 0;
    std::optional<uint32_t> footer_timestamp_;
};

struct PfsMember {
    std::string name;
    std::vector<uint8_t> data;
};

struct PfsWriteOptions {
    int zlib_level = 9; // 0..9; fixed so that the same input gives the same bytes
    // Writes the optional "STEVE" footer with this timestamp, big-endian (§1.8). Off by default:
    // every reader accepts an archive without one, and a clock value would make output vary.
    std::optional<uint32_t> footer_timestamp;
};

// An archive as §1.9 requires: the header; each member's data, in the given order, as blocks of
// 8192 inflated bytes (the last one shorter), each its own zlib stream; the name list (count,
// then length incl. NUL, name, NUL per member) in the same order, compressed like a file; the
// index right after it, entry_count = members + 1, sorted by unsigned CRC with the name-list
// entry (0x61580AC9) at its sorted place; then the footer when asked for. Names are lowercased
// (ASCII) before they are stored and hashed. The same members and options give the same bytes.
//
// An empty member is stored as a run of zero blocks at the position where the next run starts
// (LQ's form, §1.3); LQ, WQ, ZU and pvscope read it, but QL's sequential reader cannot tell two
// entries at one offset apart, which is why §1.9 advises against empty files.
//
// Throws std::invalid_argument for members no reader could use: an empty name, a name with
// bytes outside printable ASCII or with '/' or '\\', a name longer than 1023 bytes, two names
// equal after lowercasing or with equal CRCs (or one hashing to 0x61580AC9), more than 99 999
// members (LQ's limit), a zlib level outside 0..9, or an archive that would exceed 4 GiB.
std::vector<uint8_t> write_pfs(const std::vector<PfsMember>& members, const PfsWriteOptions& options = {});

} // namespace pvs::eq
