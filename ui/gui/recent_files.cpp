#include "ui/gui/recent_files.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <system_error>

namespace pvs::gui {

namespace {

bool acceptable_path(const std::string& path)
{
    return !path.empty() && path.size() <= kMaxRecentPathLength &&
           std::none_of(path.begin(), path.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7F; });
}

} // namespace

std::filesystem::path default_recent_files_path()
{
    if (const char* config = std::getenv("XDG_CONFIG_HOME"); config && config[0] == '/')
        return std::filesystem::path(config) / "pvscope" / "recent.txt";
    if (const char* home = std::getenv("HOME"); home && home[0])
        return std::filesystem::path(home) / ".config" / "pvscope" / "recent.txt";
    return {};
}

void RecentFiles::load()
{
    paths_.clear();
    if (store_.empty())
        return;
    std::error_code error;
    const auto size = std::filesystem::file_size(store_, error);
    if (error || size > kMaxRecentBytes)
        return;
    std::ifstream in(store_, std::ios::binary);
    std::string line;
    if (!std::getline(in, line) || line != kRecentFilesHeader)
        return;
    while (paths_.size() < kMaxRecentFiles && std::getline(in, line))
        if (acceptable_path(line) && std::find(paths_.begin(), paths_.end(), line) == paths_.end())
            paths_.push_back(line);
}

void RecentFiles::add(const std::string& path)
{
    if (!acceptable_path(path))
        return;
    std::erase(paths_, path);
    paths_.insert(paths_.begin(), path);
    if (paths_.size() > kMaxRecentFiles)
        paths_.resize(kMaxRecentFiles);
    save();
}

void RecentFiles::remove(const std::string& path)
{
    if (std::erase(paths_, path))
        save();
}

void RecentFiles::save()
{
    error_.clear();
    if (store_.empty())
        return;
    std::error_code error;
    std::filesystem::create_directories(store_.parent_path(), error);
    std::filesystem::path temporary = store_;
    temporary += ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out << kRecentFilesHeader << '\n';
        for (const std::string& p : paths_)
            out << p << '\n';
        if (!out.flush()) {
            error_ = "cannot write " + temporary.string();
            return;
        }
    }
    std::filesystem::rename(temporary, store_, error);
    if (error)
        error_ = "cannot replace " + store_.string() + ": " + error.message();
}

} // namespace pvs::gui
