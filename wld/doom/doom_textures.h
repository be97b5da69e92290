// The textures of a Doom-engine WAD as RGBA: flats (floors and ceilings) and composite wall
// textures, decoded on demand by name for the zone builder's materials.
//
// What is read:
//  - PLAYPAL (the last one): its first palette, 256 RGB triples (768 bytes).
//  - Flats: the lumps between F_START or FF_START and F_END or FF_END (size-0 lumps inside,
//    such as F1_START, are markers and skipped). A flat is raw palette indices, rows top to
//    bottom: 4096 bytes = 64x64; any other size that is an exact square n*n (n <= 4096) is n x n;
//    anything else is not a flat. Of several flats with one name the last wins, like the
//    engines' lump lookup.
//  - Wall textures: TEXTURE1 then TEXTURE2 (each: i32 count, i32 offsets[count] from the lump
//    start, then maptexture records: char name[8], i32 masked, i16 width, i16 height,
//    i32 columndirectory, i16 patchcount, patchcount mappatch records of i16 originx, originy,
//    patch, stepdir, colormap), composed from the patches PNAMES names (i32 count, count 8-char
//    names; each is the last lump of that name, as WadFile::find_last finds). Of several
//    textures with one name the first wins, as in the engines' texture lookup. Strife's
//    shorter layout is not read.
//  - Patches are Doom pictures: i16 width, height, leftoffset, topoffset, u32 column offsets
//    [width] from the lump start; a column is posts (u8 topdelta, 0xFF ends; u8 length; a pad
//    byte; length palette indices; a pad byte). DeePsea's tall patches are read: a topdelta not
//    above the previous post's top is added to it. Each patch is placed at its origin (its
//    left/top offsets are not used, as in the engines), clipped to the texture, later patches
//    over earlier ones. Texels no post covers are transparent: RGBA 0,0,0,0; all others have
//    alpha 255.
//
// Contract. A missing lump means no textures of that kind, not an error; without PLAYPAL
// nothing has colors, so flat() and wall() give nullopt. A texture whose patch name has no lump
// leaves that patch out (the texture may end up transparent). Anything corrupt throws
// FileError naming the WAD file, the absolute byte offset and, in the reason, the lump (and the
// texture being composed): the constructor for a short PLAYPAL, a negative count, or a PNAMES /
// TEXTURE1 / TEXTURE2 directory past its lump; wall() for a texture record past its lump, a size
// outside 1..kMaxDoomTextureSide, a negative patch count, a patch index outside PNAMES, a patch
// with a negative width or whose header, column offsets or posts run past its lump (only the
// columns inside the texture are read), or a composition that takes more than
// 32 * width * height + 2^22 steps (posts and texels: only garbage gets there, and it is
// stopped instead of hanging). Nothing is read outside a lump.
//
// The object keeps a reference to the WadFile, which must outlive it. Nothing is cached: each
// call decodes again (callers keep what they use). Const calls are safe from several threads.
#pragma once

#include "wld/doom/wad_file.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace pvs::doom {

inline constexpr uint32_t kMaxDoomTextureSide = 4096;

// An RGBA picture, width*height*4 bytes, rows top to bottom.
struct DoomImage {
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba;
};

// Textures of a WAD: flats and composite wall textures as RGBA, decoded lazily by name.
class DoomTextures {
public:
    // Indexes PLAYPAL, the flats, PNAMES, TEXTURE1 and TEXTURE2. Throws FileError (see above).
    explicit DoomTextures(const WadFile& wad);

    // RGBA of flat `name` (any case); nullopt when there is no such flat or no palette.
    std::optional<DoomImage> flat(const std::string& name) const;
    // RGBA of wall texture `name` (any case), transparent texels alpha 0; nullopt when there is
    // no such texture or no palette. Throws FileError when its record or a patch is corrupt.
    std::optional<DoomImage> wall(const std::string& name) const;

    // The names flat() and wall() know (upper case, sorted), whether or not they decode.
    std::vector<std::string> flat_names() const;
    std::vector<std::string> wall_names() const;

private:
    struct TextureRecord {
        size_t lump = 0;     // TEXTURE1 or TEXTURE2
        uint64_t offset = 0; // absolute file offset of the maptexture record
    };

    // Adds the textures of TEXTURE1 or TEXTURE2 (lump `lump`) that `out` does not have yet.
    static void index_textures(const WadFile& wad, size_t lump, std::unordered_map<std::string, TextureRecord>& out);

    const WadFile& wad_;
    bool has_palette_ = false;
    std::array<uint8_t, 768> palette_{};
    std::unordered_map<std::string, size_t> flats_;           // name -> lump
    std::vector<std::optional<size_t>> patches_;              // PNAMES index -> lump, nullopt = missing
    std::unordered_map<std::string, TextureRecord> textures_; // name -> record
};

} // namespace pvs::doom
