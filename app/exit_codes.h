// The exit codes of every pvscope command, as --help and docs/cli.md give them.
#pragma once

namespace pvs::app {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFileError = 1;    // a file could not be read or written (or a zone not used)
inline constexpr int kExitBadArguments = 2; // the command line asks for something impossible
inline constexpr int kExitCancelled = 130;  // 128 + SIGINT, what a shell reports for Ctrl-C

} // namespace pvs::app
