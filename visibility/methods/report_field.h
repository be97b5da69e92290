// A value a bake or a check measured, named for reports: `bake --report`, `vis --report` and the
// work-counter baseline read them without knowing the method. Names are flat; a dot nests them in
// a report ("work.flow_frames" is "flow_frames" in the report's "work" object). Library code fills
// them, report/ writes them; nothing here knows JSON.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace pvs {

struct ReportField {
    std::string name;
    std::variant<uint64_t, double, std::string> value;
};

// The prefix of work counters: counts of steps (frames entered, windings clipped, boxes tested)
// that depend on the input and the settings only.
inline constexpr std::string_view kWorkPrefix = "work.";

// The field of that name, or nullptr.
const ReportField* find_field(const std::vector<ReportField>& fields, std::string_view name);

} // namespace pvs
