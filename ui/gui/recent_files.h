// The inspector's recent files: the last kMaxRecentFiles zone files opened, newest first, kept in
// a small text file (default_recent_files_path: $XDG_CONFIG_HOME/pvscope/recent.txt, else
// ~/.config/pvscope/recent.txt). Format: the line "pvscope recent files 1", then one path per
// line. Reading is robust to anything in that file: a wrong header, a file larger than
// kMaxRecentBytes, binary junk, over-long lines or lines with control characters are ignored
// (line by line where the header is right, wholly otherwise); it never throws. Saving writes a
// temporary file next to it and renames it over, so a crash cannot leave half a file.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace pvs::gui {

inline constexpr size_t kMaxRecentFiles = 10;
inline constexpr size_t kMaxRecentBytes = 1 << 20;
inline constexpr size_t kMaxRecentPathLength = 4096;
inline constexpr const char* kRecentFilesHeader = "pvscope recent files 1";

// Empty when neither XDG_CONFIG_HOME nor HOME is set.
std::filesystem::path default_recent_files_path();

class RecentFiles {
public:
    RecentFiles() = default; // not kept anywhere
    explicit RecentFiles(std::filesystem::path store) : store_(std::move(store)) {}

    // Reads the store (see above); a missing store gives an empty list.
    void load();
    // Puts `path` first (once), keeps at most kMaxRecentFiles, and saves. A path with control
    // characters or longer than kMaxRecentPathLength is not remembered.
    void add(const std::string& path);
    void remove(const std::string& path);
    const std::vector<std::string>& paths() const { return paths_; }
    // Why the last save failed (empty when it worked or nothing was saved).
    const std::string& error() const { return error_; }

private:
    void save();

    std::filesystem::path store_;
    std::vector<std::string> paths_;
    std::string error_;
};

} // namespace pvs::gui
