#include "report/pvs_diff_json.h"

#include "visibility/eval/pvs_gap.h"

#include <algorithm>

namespace pvs::report {

nlohmann::json pvs_diff_json(const Pvs& baked, const Pvs& file)
{
    const PvsGap gap = pvs_gap(&baked, file);
    const double rows = std::max<double>(baked.row_count(), 1.0);
    return {{"mean_visible_file", double(gap.reference_bits) / rows},
            {"mean_visible_baked", double(gap.bits) / rows},
            {"bits_only_baked", gap.excess_bits},
            {"bits_only_file", gap.missing_bits},
            {"rows_differing", gap.rows_differing},
            {"rows_with_bits_only_baked", gap.rows_excess_bits},
            {"file_missing_rows", file.missing_row_count()}};
}

} // namespace pvs::report
