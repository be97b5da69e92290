// plot_peer_ratios SUMMARY.csv OUT.png|.svg|.pdf: the chart of peer_bench.py - pvscope's wall time
// over the peer's, one bar per map and mode, sorted, on a log axis, with the targets (0.1x for Doom,
// 0.2x for Quake) and parity marked. Reads the columns corpus, map, mode and wall_ratio.
#include "ui/chart/chart_file.h"
#include "ui/chart/ratio_chart.h"

#include <cstdio>
#include <exception>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::vector<std::string> split(const std::string& line)
{
    std::vector<std::string> fields;
    std::stringstream in(line);
    std::string field;
    while (std::getline(in, field, ','))
        fields.push_back(field);
    return fields;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc != 3) {
        std::fprintf(stderr, "usage: plot_peer_ratios SUMMARY.csv OUT.png|.svg|.pdf\n");
        return 2;
    }
    try {
        std::ifstream in(argv[1]);
        std::string line;
        std::getline(in, line);
        const std::vector<std::string> header = split(line);
        const auto column = [&](const char* name) {
            for (size_t i = 0; i < header.size(); ++i)
                if (header[i] == name)
                    return i;
            throw std::runtime_error(std::string(argv[1]) + ": no column " + name);
        };
        const size_t corpus = column("corpus"), map = column("map"), mode = column("mode"), ratio = column("wall_ratio");
        std::vector<pvs::ui::chart::RatioBar> bars;
        while (std::getline(in, line)) {
            const std::vector<std::string> f = split(line);
            if (f.size() <= ratio || f[ratio].empty())
                continue;
            bars.push_back({f[map] + " " + f[mode], f[corpus], std::stod(f[ratio])});
        }
        const pvs::ui::chart::RatioLine lines[] = {{0.1, "0.1x"}, {0.2, "0.2x"}, {1.0, "parity"}};
        const float height = pvs::ui::chart::ratio_chart_height(bars.size());
        pvs::ui::chart::write_canvas_file(900, uint32_t(height), argv[2], [&](pvs::ui::chart::Canvas& c, glm::vec2 size) {
            pvs::ui::chart::draw_ratio_chart(bars, lines, "pvscope wall time / peer's, same run (median of repetitions)",
                                             c, {0, 0}, size);
        });
    } catch (const std::exception& e) {
        std::fprintf(stderr, "plot_peer_ratios: %s\n", e.what());
        return 1;
    }
    return 0;
}
