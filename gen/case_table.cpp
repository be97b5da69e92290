#include "gen/case_table.h"

#include "visibility/eval/pvs_gap.h"
#include "gen/stability_cases.h"

#include <stdexcept>

namespace pvs::gen {

namespace {

std::vector<const VisMethod*> methods_of(const std::vector<std::string>& names)
{
    std::vector<const VisMethod*> methods;
    for (const std::string& name : names) {
        const VisMethod* m = find_vis_method(name);
        if (!m || !m->bakes)
            throw std::invalid_argument("'" + name + "' is not a method that bakes (" + vis_method_names() + ")");
        methods.push_back(m);
    }
    return methods;
}

} // namespace

CaseTable run_case_table(const CaseTableOptions& options)
{
    const std::vector<const VisMethod*> methods = methods_of(options.methods);
    std::vector<std::string> cases = options.cases;
    if (cases.empty())
        for (std::string_view name : stability_case_names())
            cases.emplace_back(name);
    CaseTable table;
    const double steps = double(cases.size() * methods.size());
    size_t step = 0;
    for (const std::string& name : cases) {
        const StabilityCase c = make_stability_case(name); // throws for an unknown name
        for (const VisMethod* method : methods) {
            const std::string stage = name + " " + std::string(method->name);
            MethodSettings settings;
            settings.threads = options.threads;
            settings.samples = options.reference_samples;
            settings.progress = [&](double f) {
                return !options.progress || options.progress(stage, (double(step) + f) / steps);
            };
            const MethodRun run = method->run(c.zone, settings);
            if (run.cancelled) {
                table.cancelled = true;
                return table;
            }
            const PvsGap gap = pvs_gap(run.pvs ? &*run.pvs : nullptr, c.truth);
            CaseTableRow row;
            row.case_name = name;
            row.method = std::string(method->name);
            row.params = method->label(settings);
            row.bound = method->bound;
            row.regions = uint32_t(c.zone.regions.size());
            row.truth_bits = gap.reference_bits;
            row.bits = gap.bits;
            row.missing_bits = gap.missing_bits;
            row.excess_bits = gap.excess_bits;
            row.seconds = run.seconds;
            table.rows.push_back(std::move(row));
            ++step;
        }
    }
    return table;
}

} // namespace pvs::gen
