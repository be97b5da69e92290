#include "app/cmd_check.h"
#include "app/error_path.h"

#include "app/argument_parsers.h"
#include "app/zone_load_args.h"
#include "report/zone_health_json.h"
#include "visibility/eval/zone_check.h"
#include "visibility/file_error.h"
#include "wld/zone_file.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

namespace pvs::app {

struct CheckCommandOptions {
    std::string path;
    bool json = false;
    bool strict = false;
    std::string sky = "sky-to-sky";
    size_t examples = 10;
    ZoneLoadOptions load;
};

namespace {

void print_text(const Zone& zone, const ZoneHealth& health, bool strict)
{
    std::printf("%s\n  %s, %zu regions\n\n", zone.source.path.c_str(), zone.source.format.c_str(), zone.regions.size());
    for (const CheckItem& item : health.items) {
        const char* status = !item.applicable ? "n/a" : item.passed() ? "ok" : check_severity_name(item.severity);
        std::printf("  %-19s %-8s %s\n", item.name.c_str(), status, item.summary.c_str());
        for (const std::string& example : item.examples)
            std::printf("  %-19s          %s\n", "", example.c_str());
        if (item.failed > item.examples.size())
            std::printf("  %-19s          ... and %zu more\n", "", item.failed - item.examples.size());
    }
    const bool healthy = check_exit_code(health, strict) == 0;
    std::printf("\n%s: %zu failed error checks, %zu failed warning checks%s\n", healthy ? "healthy" : "UNHEALTHY",
                health.errors(), health.warnings(), strict ? " (--strict: warnings count)" : "");
}

// check's 1 is "unhealthy": a file it cannot read exits 2 (cmd_check.h).
constexpr int kCheckUnreadable = 2;

int run_check(const CheckCommandOptions& o)
{
    return run_reporting_errors(o.path, stderr, [&] {
        const Zone zone = load_zone(o.path, o.load);
        CheckOptions options;
        options.sky = sky_mode_from_name(o.sky);
        options.max_examples = o.examples;
        const ZoneHealth health = check_zone(zone, options);
        if (o.json)
            std::cout << zone_health_json(zone, health).dump(2) << "\n";
        else
            print_text(zone, health, o.strict);
        return check_exit_code(health, o.strict);
    }, {}, kCheckUnreadable);
}

} // namespace

int check_exit_code(const ZoneHealth& health, bool strict)
{
    return health.errors() == 0 && (!strict || health.warnings() == 0) ? 0 : 1;
}

void register_check_command(CLI::App& app, int& exit_code)
{
    auto o = std::make_shared<CheckCommandOptions>();
    CLI::App* cmd = app.add_subcommand(
        "check", "A zone's health: tree and portal invariants, blocked portal crossings, leaks, regions without faces, "
                 "PVS rows and asymmetries. Exit 0 healthy, 1 unhealthy, 2 unreadable");
    cmd->add_option("file", o->path, "Zone file (.bsp, .s3d, .wad/.gwa, .obj, .hepvs)")->required();
    cmd->add_flag("--json", o->json, "Print the report as JSON (stable field names, for scripts)");
    cmd->add_flag("--strict", o->strict, "Failed warning checks (leaks, PVS neighbours, ...) also make the exit code 1");
    cmd->add_option("--sky", o->sky, "Portals and crossings at sky leaves: sky-to-sky, all, none")
        ->check(CLI::IsMember({"sky-to-sky", "all", "none"}))
        ->capture_default_str();
    cmd->add_option("--examples", o->examples, "Failures listed per check")->check(CLI::NonNegativeNumber)->capture_default_str();
    cmd->add_option("--obj", o->load.obj, "A .hepvs's OBJ level (default: the .obj of the same name beside it)");
    cmd->add_option("--hepvs", o->load.hepvs, "An OBJ's .hepvs PVS (default: the .hepvs of the same name, if any)");
    add_zone_load_options(cmd, o->load);
    cmd->callback([o, &exit_code] { exit_code = run_check(*o); });
}

} // namespace pvs::app
