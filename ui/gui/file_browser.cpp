#include "ui/gui/file_browser.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <system_error>

namespace pvs::gui {

bool is_zone_file_name(const std::filesystem::path& path)
{
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    constexpr std::array<const char*, 4> kExtensions{".bsp", ".s3d", ".obj", ".wad"};
    return std::any_of(kExtensions.begin(), kExtensions.end(), [&](const char* e) { return extension == e; });
}

DirectoryListing list_directory(const std::filesystem::path& directory, bool all_files)
{
    DirectoryListing listing;
    std::error_code error;
    listing.directory = std::filesystem::absolute(directory, error);
    if (error)
        listing.directory = directory;
    std::filesystem::directory_iterator it(listing.directory, std::filesystem::directory_options::skip_permission_denied,
                                           error);
    if (error) {
        listing.error = "cannot list " + listing.directory.string() + ": " + error.message();
        return listing;
    }
    for (const std::filesystem::directory_iterator end; it != end; it.increment(error)) {
        if (error) {
            listing.error = "cannot list all of " + listing.directory.string() + ": " + error.message();
            break;
        }
        const std::string name = it->path().filename().string();
        if (name.empty() || name[0] == '.')
            continue;
        std::error_code entry_error;
        const bool directory_entry = it->is_directory(entry_error);
        if (entry_error)
            continue;
        BrowserEntry entry{name, directory_entry, 0};
        if (!directory_entry) {
            if (!it->is_regular_file(entry_error) || entry_error || !(all_files || is_zone_file_name(name)))
                continue;
            entry.size = it->file_size(entry_error);
            if (entry_error)
                entry.size = 0;
        }
        listing.entries.push_back(std::move(entry));
    }
    std::sort(listing.entries.begin(), listing.entries.end(), [](const BrowserEntry& a, const BrowserEntry& b) {
        return a.directory != b.directory ? a.directory : a.name < b.name;
    });
    return listing;
}

} // namespace pvs::gui
