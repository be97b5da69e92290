#include "app/bake_shard.h"

#include "visibility/bit_row.h"
#include "visibility/file_error.h"
#include "wld/common/read_file.h"

#include <nlohmann/json.hpp>

#include <sys/resource.h>

#include <charconv>

namespace pvs::app {

namespace {

std::optional<uint32_t> parse_u32(std::string_view text)
{
    uint32_t value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || text.empty())
        return std::nullopt;
    return value;
}

uint64_t hash_file(const std::string& path, uint64_t hash)
{
    const std::vector<uint8_t> bytes = read_whole_file(path);
    const uint64_t size = bytes.size(); // the size too, so that moving bytes between files changes the hash
    hash = fnv1a64(std::span(reinterpret_cast<const uint8_t*>(&size), sizeof size), hash);
    return fnv1a64(bytes, hash);
}

} // namespace

std::optional<ShardSpec> parse_shard_spec(const std::string& text)
{
    const size_t slash = text.find('/');
    if (slash == std::string::npos)
        return std::nullopt;
    const std::optional<uint32_t> k = parse_u32(std::string_view(text).substr(0, slash));
    const std::optional<uint32_t> n = parse_u32(std::string_view(text).substr(slash + 1));
    if (!k || !n || *n == 0 || *k >= *n)
        return std::nullopt;
    return ShardSpec{*k, *n};
}

std::string bake_settings_text(const BakeOptions& o)
{
    nlohmann::json j;
    j["method"] = o.method;
    j["level"] = o.level;
    j["sky"] = o.sky;
    j["clusters"] = o.clusters;
    j["passages"] = o.passages;
    j["target_checks"] = o.target_checks;
    j["samples"] = o.samples;
    j["seed"] = o.seed;
    j["per_source"] = o.per_source;
    j["resolution"] = o.resolution;
    j["points"] = o.points;
    j["step"] = o.step;
    j["lattice"] = o.lattice;
    j["engine"] = o.raster_engine;
    j["device"] = o.device; // the batch changes no bit (gpu_cube.h): not a setting
    j["back_faces"] = o.cull_back_faces;
    j["cell"] = o.cell;
    j["grid_size"] = o.grid_size;
    j["hepvs"] = o.hepvs;
    j["map"] = o.map;
    j["gwa"] = o.gwa;
    j["heights"] = o.heights;
    j["reject"] = o.reject;
    j["ambient"] = o.ambient;
    j["ambient_classes"] = {o.ambient_classes.water, o.ambient_classes.sky, o.ambient_classes.slime,
                            o.ambient_classes.lava};
    j["phs_rule"] = o.phs_rule;
    j["prt"] = o.prt_in;
    return j.dump();
}

BakeOptions options_from_settings(const std::string& text, const std::string& part)
{
    BakeOptions o;
    try {
        const nlohmann::json j = nlohmann::json::parse(text);
        o.method = j.at("method").get<std::string>();
        o.level = j.at("level").get<int>();
        o.sky = j.at("sky").get<std::string>();
        o.clusters = j.at("clusters").get<std::string>();
        o.passages = j.at("passages").get<bool>();
        o.target_checks = j.at("target_checks").get<bool>();
        o.samples = j.at("samples").get<uint64_t>();
        o.seed = j.at("seed").get<uint64_t>();
        o.per_source = j.at("per_source").get<bool>();
        o.resolution = j.at("resolution").get<uint32_t>();
        o.points = j.at("points").get<uint32_t>();
        o.step = j.at("step").get<float>();
        o.lattice = j.at("lattice").get<std::string>();
        o.raster_engine = j.at("engine").get<std::string>();
        o.device = j.value("device", std::string("cpu"));
        o.cull_back_faces = j.at("back_faces").get<bool>();
        o.cell = j.at("cell").get<float>();
        o.grid_size = j.at("grid_size").get<float>();
        o.hepvs = j.at("hepvs").get<std::string>();
        o.map = j.at("map").get<std::string>();
        o.gwa = j.at("gwa").get<std::string>();
        o.heights = j.at("heights").get<bool>();
        o.reject = j.at("reject").get<bool>();
        o.ambient = j.at("ambient").get<bool>();
        const auto classes = j.at("ambient_classes").get<std::vector<bool>>();
        if (classes.size() != 4)
            throw std::invalid_argument("ambient_classes must hold 4 flags");
        o.ambient_classes = {classes[0], classes[1], classes[2], classes[3]};
        o.phs_rule = j.at("phs_rule").get<std::string>();
        o.prt_in = j.at("prt").get<std::string>();
    } catch (const std::exception& e) {
        throw FileError(part, 40, std::string("the bake's settings are unreadable: ") + e.what());
    }
    return o;
}

uint64_t bake_zone_hash(const BakeOptions& o, const BakeInput& in)
{
    uint64_t hash = hash_file(o.input, kFnvOffset);
    if (in.format == ZoneFormat::DoomWad && in.doom_source.gl_path != o.input)
        hash = hash_file(in.doom_source.gl_path, hash);
    if (!o.hepvs.empty())
        hash = hash_file(o.hepvs, hash);
    if (!o.prt_in.empty())
        hash = hash_file(o.prt_in, hash);
    return hash;
}

PvsPart make_pvs_part(const Pvs& pvs, std::span<const uint32_t> sources, ShardSpec shard, uint64_t zone_hash,
                      std::string settings, PartRows join)
{
    PvsPart part;
    part.join = join;
    part.zone_hash = zone_hash;
    part.shard = shard.index;
    part.shards = shard.count;
    part.row_count = pvs.row_count();
    part.region_count = pvs.region_count();
    part.settings = std::move(settings);
    part.sources.assign(sources.begin(), sources.end());
    const size_t words = part.words_per_row();
    part.rows.assign(sources.size() * words, 0);
    for (size_t i = 0; i < sources.size(); ++i)
        pvs.decode_row(sources[i], std::span(part.rows).subspan(i * words, words));
    return part;
}

double process_cpu_seconds()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

} // namespace pvs::app
