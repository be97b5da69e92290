// `pvscope convert IN OUT [--to s3d|obj]`: write a zone in another format. A Quake .bsp becomes an
// EverQuest .s3d (faces clipped to each region's cell, the PVS re-encoded as VISLISTs, textures
// as BMP); an .s3d is re-written; any zone exports to .obj.
#pragma once

#include <CLI/App.hpp>

namespace pvs::app {

void register_convert_command(CLI::App& app, int& exit_code);

} // namespace pvs::app
