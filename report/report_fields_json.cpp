#include "report/report_fields_json.h"

namespace pvs::report {

void add_report_fields(nlohmann::json& object, const std::vector<ReportField>& fields)
{
    for (const ReportField& f : fields) {
        nlohmann::json* at = &object;
        std::string_view name = f.name;
        for (size_t dot = name.find('.'); dot != std::string_view::npos; dot = name.find('.')) {
            nlohmann::json& child = (*at)[std::string(name.substr(0, dot))];
            if (!child.is_object())
                child = nlohmann::json::object();
            at = &child;
            name.remove_prefix(dot + 1);
        }
        std::visit([&](const auto& v) { (*at)[std::string(name)] = v; }, f.value);
    }
}

} // namespace pvs::report
