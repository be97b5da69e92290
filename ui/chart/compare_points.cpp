#include "ui/chart/compare_points.h"

namespace pvs::ui::chart {

namespace {

// The value of `key=` in a row's params ("level=2 passages=on ..."), or empty.
std::string param(const std::string& params, const std::string& key)
{
    const size_t at = params.find(key + "=");
    if (at == std::string::npos)
        return {};
    const size_t begin = at + key.size() + 1;
    return params.substr(begin, params.find(' ', begin) - begin);
}

std::string short_label(const CompareRow& r)
{
    if (r.method == "portal-full" || r.method == "clustered")
        return r.method + " L" + param(r.params, "level") + (param(r.params, "passages") == "off" ? " -passages" : "") +
               (param(r.params, "target-checks") == "off" ? " -checks" : "") +
               (r.params.ends_with(" heights") ? " heights" : "");
    if (r.method == "reference")
        return r.method + " " + param(r.params, "samples");
    if (r.method == "raster" && !param(r.params, "res").empty()) // several rows differ by these two
        return r.method + " " + param(r.params, "res") + "px " + param(r.params, "points") + "pt";
    return r.method;
}

} // namespace

std::vector<ChartPoint> compare_chart_points(const CompareResult& result)
{
    std::vector<ChartPoint> points;
    for (const CompareRow& r : result.rows)
        points.push_back({short_label(r), r.method, r.baked ? r.wall_s : 0.0, double(r.missing_bits),
                          double(r.excess_bits)});
    return points;
}

} // namespace pvs::ui::chart
