// The file browser's listing: one directory's sub-directories and zone files, for the
// inspector's File -> Open dialog. Errors (a missing or unreadable directory) come back in the
// listing, never as exceptions, so the dialog can show them.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace pvs::gui {

// The file types the inspector opens, by extension (case-insensitive): .bsp, .s3d, .obj, .wad.
bool is_zone_file_name(const std::filesystem::path& path);

struct BrowserEntry {
    std::string name;
    bool directory = false;
    uintmax_t size = 0; // bytes, files only
};

struct DirectoryListing {
    std::filesystem::path directory; // as given, made absolute
    std::vector<BrowserEntry> entries; // directories first, then files; each group by name
    std::string error;                 // empty when the directory was read
};

// Lists `directory`: its sub-directories and the files is_zone_file_name accepts (every file
// with `all_files`). Names starting with '.' are left out. Entries that cannot be examined
// (a dangling link, no permission) are skipped; a directory that cannot be read gives an
// empty listing with `error` naming it and the reason.
DirectoryListing list_directory(const std::filesystem::path& directory, bool all_files = false);

} // namespace pvs::gui
