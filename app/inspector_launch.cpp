// The hand-over to pvscope-inspector (inspector_launch.h).
#include "app/inspector_launch.h"
#include "app/error_path.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace pvs::app {

std::string inspector_executable_path()
{
    std::error_code error;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
    const std::filesystem::path folder = error ? std::filesystem::path(".") : self.parent_path();
    return (folder / "pvscope-inspector").string();
}

int launch_inspector(char** argv)
{
    const std::string path = inspector_executable_path();
    std::fflush(stdout);
    execv(path.c_str(), argv);
    return file_error(stderr, "cannot start the inspector " + path + ": " + std::strerror(errno));
}

} // namespace pvs::app
