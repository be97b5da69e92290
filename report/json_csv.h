// JSON reports as CSV: scalars flattened to dotted column names ("pvs.mean_visible"); a short
// array of scalars (a point, a grid's counts: at most kCsvArrayColumns) to one column per element
// ("bounds.min.0", ".1", ".2"); longer arrays and arrays of objects left out (a list does not fit
// one row); strings quoted with "" doubled; null gives no cell (a part the zone does not have).
// Rows of different shape (a zone with a view grid, one without) share one header: the union of
// their columns in first-seen order, empty where a row has none.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <utility>
#include <vector>

namespace pvs {

inline constexpr size_t kCsvArrayColumns = 4;

using CsvFields = std::vector<std::pair<std::string, std::string>>; // (column, cell text)

// Appends the scalars of `value` under `prefix` (empty: top level).
void flatten_json(const nlohmann::json& value, const std::string& prefix, CsvFields& out);

// A header line and one line per row.
std::string csv_table(const std::vector<CsvFields>& rows);

// A string as one CSV cell.
std::string csv_cell(const std::string& text);

} // namespace pvs
