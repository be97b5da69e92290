#include "app/output_files.h"

#include "wld/common/read_file.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <vector>

namespace pvs::app {

void write_text_file(const std::string& path, const std::string& text)
{
    write_whole_file(path, std::vector<uint8_t>(text.begin(), text.end()));
}

void write_report(const std::string& path, const nlohmann::json& report)
{
    const std::string text = report.dump(2) + "\n";
    if (path == "-") {
        std::fputs(text.c_str(), stdout);
        return;
    }
    write_whole_file(path, std::vector<uint8_t>(text.begin(), text.end()));
}

} // namespace pvs::app
