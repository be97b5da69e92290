// The one way a command reports a failure: "pvscope: error: ..." on `err`, and the exit code of
// exit_codes.h. A file's error names the file, the offset and the problem (FileError); another
// error names the input it concerns.
#pragma once

#include "app/exit_codes.h"

#include <cstdio>
#include <functional>
#include <string>

namespace pvs::app {

// Runs a command's body; a FileError or other exception it throws is printed to `err` as
// "pvscope: error: ..." (naming `input` when the message does not) and gives kExitFileError.
// `after_error`, when given, runs after the message (e.g. to say what was left as it was).
// `error_code`: what an error exits with, for the commands whose 1 means something else (`check`:
// unhealthy) and that document 2 for an unreadable file.
int run_reporting_errors(const std::string& input, std::FILE* err, const std::function<int()>& body,
                         const std::function<void()>& after_error = {}, int error_code = kExitFileError);

// Prints "pvscope: error: PROBLEM" and returns kExitBadArguments: a command line that cannot be
// carried out, found before anything is read or written.
int bad_arguments(std::FILE* err, const std::string& problem);
// The same for a file that cannot be read or written, found without an exception: kExitFileError.
int file_error(std::FILE* err, const std::string& problem);

} // namespace pvs::app
