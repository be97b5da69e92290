// `pvscope vis`'s options as parsed (cmd_vis.h documents them): the Quake path (cmd_vis.cpp) and
// the Quake 2 path (vis_quake2.h) read them.
#pragma once

#include <string>

namespace pvs::app {

struct VisCommandOptions {
    std::string map;
    std::string method = "portal-full";
    std::string portals = "file"; // file (MAP.prt) | tree
    int level = 4;
    unsigned threads = 0;
    bool fast = false;
    bool ambient_only = false;
    bool noambient = false, noambientsky = false, noambientwater = false, noambientslime = false, noambientlava = false;
    bool nostate = false;
    double visdist = 0.0; // refused when set
    std::string report;
    bool phs_only = false;           // Quake 2: keep the PVS, make the PHS again
    std::string phs_rule = "quake2"; // Quake 2: quake2 | ericw
};

} // namespace pvs::app
