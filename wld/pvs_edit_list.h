// PVS edit lists on disk (visibility/pvs_edits.h): what the inspector saves and
// `pvscope bake --apply-edits` re-applies after a re-bake, as JSON:
//   {"format": "pvscope-pvs-edits", "version": 1, "rows": R, "regions": N,
//    "edits": [{"op": "pair", "from": a, "to": b, "visible": true, "both": false},
//              {"op": "row", "row": r, "visible": [region, ...], "note": "reference"}]}
// read_edit_list checks the format, the counts against the zone's and every index, and throws
// FileError naming the file, the edit's position in the list and what is wrong.
#pragma once

#include "visibility/pvs_edits.h"

#include <string>
#include <vector>

namespace pvs {

std::string edit_list_json(const std::vector<PvsEdit>& edits, uint32_t rows, uint32_t regions);
std::vector<PvsEdit> parse_edit_list(const std::string& json, const std::string& file, uint32_t rows,
                                     uint32_t regions);
std::vector<PvsEdit> read_edit_list(const std::string& path, uint32_t rows, uint32_t regions);

} // namespace pvs
