#include "report/json_csv.h"

#include <algorithm>
#include <map>

namespace pvs {

std::string csv_cell(const std::string& text)
{
    std::string cell = "\"";
    for (char c : text)
        cell += c == '"' ? std::string("\"\"") : std::string(1, c);
    return cell + "\"";
}

void flatten_json(const nlohmann::json& value, const std::string& prefix, CsvFields& out)
{
    if (value.is_object()) {
        for (const auto& [key, child] : value.items())
            flatten_json(child, prefix.empty() ? key : prefix + "." + key, out);
    } else if (value.is_string()) {
        out.emplace_back(prefix, csv_cell(value.get<std::string>()));
    } else if (value.is_array()) {
        const bool short_scalars = value.size() <= kCsvArrayColumns &&
                                   std::all_of(value.begin(), value.end(), [](const nlohmann::json& v) {
                                       return v.is_primitive() && !v.is_null();
                                   });
        if (short_scalars)
            for (size_t i = 0; i < value.size(); ++i)
                flatten_json(value[i], prefix + "." + std::to_string(i), out);
    } else if (!value.is_null()) {
        out.emplace_back(prefix, value.dump());
    }
}

std::string csv_table(const std::vector<CsvFields>& rows)
{
    std::vector<std::string> columns;
    std::map<std::string, size_t> index;
    for (const CsvFields& row : rows)
        for (const auto& [name, text] : row)
            if (index.emplace(name, columns.size()).second)
                columns.push_back(name);
    std::string out;
    for (size_t c = 0; c < columns.size(); ++c)
        out += (c ? "," : "") + columns[c];
    out += "\n";
    std::vector<const std::string*> cells(columns.size());
    for (const CsvFields& row : rows) {
        std::fill(cells.begin(), cells.end(), nullptr);
        for (const auto& [name, text] : row)
            cells[index[name]] = &text;
        for (size_t c = 0; c < columns.size(); ++c)
            out += (c ? "," : "") + (cells[c] ? *cells[c] : std::string());
        out += "\n";
    }
    return out;
}

} // namespace pvs
