// Each visibility method on each crafted stability case (stability_cases.h), against the case's
// known truth: the table of `pvscope stability --cases` and of the inspector's Stability panel.
//
// missing bits: truth pairs the method's PVS lacks (sight lines it would pop); excess bits: pairs
// it has beyond the truth (overdraw it allows). An upper-bound method with a missing bit, or a
// lower-bound one with an excess bit, breaks its promise: `broken` says so (the tests hold every
// method of the registry to it on every case). Library code: no output; progress(stage,
// fraction) false cancels (the rows so far are kept, `cancelled` set).
#pragma once

#include "visibility/methods/vis_method.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace pvs::gen {

struct CaseTableOptions {
    std::vector<std::string> methods{"portal-fast", "portal-full", "clustered", "reference", "raster"};
    std::vector<std::string> cases; // empty: every case
    uint64_t reference_samples = 1024;
    unsigned threads = 0;
    std::function<bool(const std::string& stage, double fraction)> progress;
};

struct CaseTableRow {
    std::string case_name, method, params;
    Bound bound = Bound::Unknown;
    uint32_t regions = 0;
    uint64_t truth_bits = 0, bits = 0, missing_bits = 0, excess_bits = 0;
    double seconds = 0.0;
    bool broken() const
    {
        return (bound == Bound::Upper && missing_bits > 0) || (bound == Bound::Lower && excess_bits > 0);
    }
};

struct CaseTable {
    std::vector<CaseTableRow> rows; // case by case, methods in the order asked
    bool cancelled = false;
};

// Throws std::invalid_argument for an unknown case or method, or a method that bakes nothing.
CaseTable run_case_table(const CaseTableOptions& options);

} // namespace pvs::gen
