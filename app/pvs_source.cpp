#include "app/pvs_source.h"

#include "visibility/methods/vis_method.h"

#include <stdexcept>

namespace pvs::app {

const std::vector<std::string>& pvs_source_names()
{
    static const std::vector<std::string> names = [] {
        std::vector<std::string> list;
        for (const VisMethod& m : vis_methods())
            list.emplace_back(m.name);
        list.emplace_back("baked");
        return list;
    }();
    return names;
}

PvsSource make_pvs_source(const Zone& zone, const std::string& name)
{
    const VisMethod* method = find_vis_method(name == "baked" ? "file" : name);
    if (!method)
        throw std::invalid_argument("unknown PVS source '" + name + "' (" + vis_method_names() + ")");
    PvsSource source;
    if (method->name == "file") { // the zone's own rows, not a copy
        source.pvs = zone.baked_pvs ? &*zone.baked_pvs : nullptr;
        source.note = zone.baked_pvs ? "file: the file's PVS" : "file: the file has no PVS; culling with the frustum only";
        return source;
    }
    MethodRun run = method->run(zone, MethodSettings{});
    source.baked_now = std::move(run.pvs);
    source.pvs = source.baked_now ? &*source.baked_now : nullptr;
    source.note = run.summary;
    return source;
}

} // namespace pvs::app
