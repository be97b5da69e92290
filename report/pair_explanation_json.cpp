// A pair's explanation as JSON (pair_explanation_json.h).
#include "report/pair_explanation_json.h"

#include <cstdio>

namespace pvs {
namespace {

nlohmann::json point_json(const glm::dvec3& p) { return nlohmann::json::array({p.x, p.y, p.z}); }

} // namespace

std::string camera_argument(const WitnessCamera& camera)
{
    char text[160];
    std::snprintf(text, sizeof text, "%.3f,%.3f,%.3f,%.2f,%.2f", camera.eye.x, camera.eye.y, camera.eye.z,
                  camera.yaw_degrees, camera.pitch_degrees);
    return text;
}

nlohmann::json pair_explanation_json(const std::string& file, const std::string& pvs_name, const PairExplanation& e)
{
    nlohmann::json j;
    j["file"] = file;
    j["a"] = e.a;
    j["b"] = e.b;
    j["pvs"] = pvs_name;
    j["in_pvs"] = e.in_pvs;
    j["in_reference"] = e.witness.has_value();
    j["grid"] = e.grid; // a is a view cell, b an object
    j["verdict"] = pair_verdict_name(e.verdict);
    j["summary"] = e.summary;
    j["witness_tries"] = e.witness_tries;
    if (e.witness)
        j["witness"] = {{"from", point_json(e.witness->from)}, {"to", point_json(e.witness->to)}, {"tries", e.witness->tries}};
    else
        j["witness"] = nullptr;
    if (e.camera)
        j["camera"] = {{"position", point_json(e.camera->eye)},
                       {"yaw", e.camera->yaw_degrees},
                       {"pitch", e.camera->pitch_degrees},
                       {"argument", camera_argument(*e.camera)}};
    else
        j["camera"] = nullptr;
    j["witness_regions"] = e.witness_regions;
    j["flow_cut"] = e.flow_cut ? nlohmann::json(e.witness_regions[*e.flow_cut]) : nlohmann::json(nullptr);
    j["chain_method"] = e.chain_2d ? "portal-full (2-D)" : "portal-full";
    j["flow_run"] = e.flow_run;
    j["flow_holds"] = e.grid || e.flow_run ? nlohmann::json(e.flow_holds) : nlohmann::json(nullptr);
    j["size_unit"] = e.chain_2d ? "width" : "area";
    if (!e.chain) {
        j["portal_chain"] = nullptr;
        j["chain_steps"] = nlohmann::json::array();
        return j;
    }
    nlohmann::json regions = nlohmann::json::array({e.a});
    nlohmann::json steps = nlohmann::json::array();
    for (const ChainStep& s : e.chain->steps) {
        regions.push_back(s.region);
        nlohmann::json window = nlohmann::json::array();
        for (const glm::dvec3& p : s.window)
            window.push_back(point_json(p));
        nlohmann::json planes = nlohmann::json::array();
        for (const glm::dvec4& plane : s.separator_planes)
            planes.push_back({plane.x, plane.y, plane.z, plane.w});
        const Portal& portal = e.portals.portals[s.portal];
        steps.push_back({{"region", s.region},
                         {"portal", s.portal},
                         {"portal_regions", {portal.regions[0], portal.regions[1]}},
                         {"portal_size", s.portal_size},
                         {"window_size", s.window_size},
                         {"window_fraction", s.portal_size > 0 ? s.window_size / s.portal_size : 0.0},
                         {"separators", s.separators},
                         {"separator_planes", planes},
                         {"window", window}});
    }
    j["portal_chain"] = regions;
    j["chain_steps"] = steps;
    return j;
}

} // namespace pvs
