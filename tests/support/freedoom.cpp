#include "tests/support/freedoom.h"

#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>
#include <unistd.h>

namespace pvs::test {

namespace fs = std::filesystem;

std::optional<std::string> find_freedoom(const std::string& name)
{
    const char* env = std::getenv("PVSCOPE_FREEDOOM_DIR");
    const fs::path path = fs::path(env ? env : "/usr/share/games/doom") / name;
    std::error_code ec;
    if (!fs::exists(path, ec))
        return std::nullopt;
    return path.string();
}

const char* gl_builder_name(GlBuilder builder)
{
    switch (builder) {
    case GlBuilder::glbsp_v2: return "glbsp -v2";
    case GlBuilder::glbsp_v3: return "glbsp -v3";
    case GlBuilder::glbsp_v5: return "glbsp -v5";
    case GlBuilder::zdbsp_v2: return "zdbsp -g";
    case GlBuilder::zdbsp_v5: return "zdbsp -g -5";
    }
    return "?";
}

namespace {

// GL nodes are made once per user and WAD, not once per test process (ctest runs each test in a
// process of its own): files named after the WAD's size and time stamp in a folder per user,
// each made under a name of its own and renamed into place, so concurrent tests share them safely.
fs::path scratch_dir()
{
    static const fs::path dir = [] {
        fs::path d = fs::temp_directory_path() / ("pvscope-gl-nodes-" + std::to_string(getuid()));
        fs::create_directories(d);
        return d;
    }();
    return dir;
}

// The WAD's identity for the cache: its size and modification time.
std::string wad_key(const std::string& wad)
{
    std::error_code ec;
    const auto size = fs::file_size(wad, ec);
    const auto time = fs::last_write_time(wad, ec).time_since_epoch().count();
    return std::to_string(size) + "-" + std::to_string(time);
}

std::string shell_quoted(const std::string& s) { return "'" + s + "'"; }

} // namespace

std::optional<std::string> gl_nodes_file(const std::string& wad, GlBuilder builder)
{
    static std::mutex mutex;
    static std::map<std::pair<std::string, GlBuilder>, std::optional<std::string>> made;
    std::lock_guard lock(mutex);
    auto [slot, fresh] = made.try_emplace({wad, builder});
    if (!fresh)
        return slot->second;
    const std::string stem = fs::path(wad).stem().string() + "-" + wad_key(wad);
    const int tag = int(builder);
    std::string out, command;
    switch (builder) {
    case GlBuilder::glbsp_v2:
    case GlBuilder::glbsp_v3:
    case GlBuilder::glbsp_v5: {
        const char* version = builder == GlBuilder::glbsp_v2 ? "-v2" : builder == GlBuilder::glbsp_v3 ? "-v3" : "-v5";
        out = (scratch_dir() / (stem + "-" + std::to_string(tag) + ".gwa")).string();
        command = std::string("glbsp -q -xp ") + version + " " + shell_quoted(wad) + " -o " + shell_quoted(out);
        break;
    }
    case GlBuilder::zdbsp_v2:
    case GlBuilder::zdbsp_v5:
        out = (scratch_dir() / (stem + "-" + std::to_string(tag) + ".wad")).string();
        command = std::string("zdbsp -t -g ") + (builder == GlBuilder::zdbsp_v5 ? "-5 " : "") + "-o " + shell_quoted(out) +
                  " " + shell_quoted(wad);
        break;
    }
    std::error_code ec;
    if (fs::exists(out, ec)) { // made by an earlier test process
        slot->second = out;
        return slot->second;
    }
    // Made under a name of this process's, then renamed: readers see no half-written file.
    const std::string mine = out + "." + std::to_string(getpid());
    const std::string made_here = mine + fs::path(out).extension().string();
    std::string own_command = command;
    own_command.replace(own_command.find(shell_quoted(out)), shell_quoted(out).size(), shell_quoted(made_here));
    own_command += " > /dev/null 2>&1";
    if (std::system(own_command.c_str()) == 0 && fs::exists(made_here, ec)) {
        fs::rename(made_here, out, ec);
        if (!ec || fs::exists(out))
            slot->second = out;
    }
    fs::remove(made_here, ec);
    return slot->second;
}

} // namespace pvs::test
