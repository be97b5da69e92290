#include "visibility/eval/stability.h"

#include "visibility/eval/pvs_gap.h"

#include <chrono>
#include <optional>
#include <stdexcept>
#include <vector>

namespace pvs {

StabilityResult run_stability(const Zone& zone, const StabilityOptions& options)
{
    std::vector<const VisMethod*> methods;
    for (const std::string& name : options.methods) {
        const VisMethod* m = find_vis_method(name);
        if (!m || !m->bakes)
            throw std::invalid_argument("stability: '" + name + "' is not a method that bakes (" + vis_method_names() +
                                        ")");
        methods.push_back(m);
    }
    MethodSettings settings;
    settings.sky = options.sky;
    settings.threads = options.threads;
    settings.samples = options.reference_samples;
    StabilityResult result;
    auto bake = [&](const VisMethod& method, const Zone& z, const std::string& stage) -> std::optional<Pvs> {
        MethodSettings s = settings;
        s.progress = [&](double f) { return !options.progress || options.progress(stage, f); };
        MethodRun run = method.run(z, s);
        if (run.cancelled || !run.pvs)
            return std::nullopt;
        return std::move(run.pvs);
    };
    const std::optional<Pvs> reference = bake(*find_vis_method("reference"), zone, "reference");
    if (!reference) {
        result.cancelled = true;
        return result;
    }
    result.reference_bits = pvs_gap(&*reference, *reference).bits;
    // The transformed zones, made once for all methods.
    std::vector<Zone> transformed;
    for (const ZoneTransform& t : options.transforms)
        transformed.push_back(transform_zone(zone, t));
    for (const VisMethod* method : methods) {
        const std::optional<Pvs> base = bake(*method, zone, std::string(method->name));
        if (!base) {
            result.cancelled = true;
            return result;
        }
        for (size_t k = 0; k < transformed.size(); ++k) {
            const ZoneTransform& t = options.transforms[k];
            const auto start = std::chrono::steady_clock::now();
            const std::optional<Pvs> moved = bake(*method, transformed[k], std::string(method->name) + " " + t.name);
            if (!moved) {
                result.cancelled = true;
                return result;
            }
            StabilityRow row;
            row.method = std::string(method->name);
            row.params = method->label(settings);
            row.transform = t.name;
            row.exact = t.exact;
            row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            const PvsGap diff = pvs_gap(&*moved, *base); // excess: gained; missing: lost
            row.gained_bits = diff.excess_bits;
            row.lost_bits = diff.missing_bits;
            row.changed_rows = diff.rows_differing;
            row.missing_bits = pvs_gap(&*moved, *reference).missing_bits;
            result.rows.push_back(std::move(row));
        }
    }
    return result;
}

} // namespace pvs
