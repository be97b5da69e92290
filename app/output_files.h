// What commands write besides the zone: text files and JSON reports, to a path or "-" (standard
// output). A file that cannot be written throws FileError naming it.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <string>

namespace pvs::app {

// Writes `text` to `path` (read_file.h's write_whole_file).
void write_text_file(const std::string& path, const std::string& text);

// Writes a --report JSON, indented, to `path` ("-": standard output).
void write_report(const std::string& path, const nlohmann::json& report);

} // namespace pvs::app
