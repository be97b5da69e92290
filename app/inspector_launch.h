// Hands the process over to the inspector executable.
//
// `pvscope` links no GUI library (no GLFW, OpenGL or Dear ImGui), so that the commands most runs
// use -- bake, info, stats -- start without them (docs/performance.md, "Memory of the bake").
// When the inspector is asked for (`pvscope inspect ...`, or `pvscope [FILE]`), pvscope checks
// the arguments and then replaces itself with `pvscope-inspector` from its own folder, passing
// the same arguments: the window, its exit code and its output are the inspector's.
#pragma once

#include <string>

namespace pvs::app {

// The inspector executable next to the running one (/proc/self/exe's folder).
std::string inspector_executable_path();

// execv(inspector_executable_path(), argv). Returns only when that fails: prints
// "pvscope: error: cannot start the inspector PATH: REASON" on stderr and returns 1.
int launch_inspector(char** argv);

} // namespace pvs::app
