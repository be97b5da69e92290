// The zones a batch command (`pvscope stats`) goes through: files and folders as given, folders
// recursed, each WAD expanded to its maps.
//
// Inputs. A file is taken as it is (any format load_zone reads); a folder contributes every
// file below it whose extension is .bsp, .s3d, .wad or .obj (case-insensitive; .gwa and .hepvs
// are opened with their WAD / OBJ, not on their own), in sorted path order, so a batch is the
// same on every run. A WAD becomes one item per map (map_names); a WAD that cannot be read is
// one item whose error says why. A missing input is an error item too: a batch never stops on
// one bad file.
#pragma once

#include "visibility/zone.h"

#include <optional>
#include <string>
#include <vector>

namespace pvs {

struct BatchItem {
    std::string path;
    std::string map;   // a WAD's map; empty otherwise
    std::string error; // set when the item is already known bad (unreadable WAD, missing path)
};

std::vector<BatchItem> batch_items(const std::vector<std::string>& inputs);

struct LoadedZone {
    std::optional<Zone> zone; // absent on error
    std::string error;        // the loader's message
    double load_ms = 0;
};

// Loads one item; a FileError (or any exception of the loader) becomes `error`.
LoadedZone load_batch_item(const BatchItem& item);

} // namespace pvs
