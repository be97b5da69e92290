// Committed baselines of work counters (tests/baselines/*.tsv: key, counter, value per line; '#'
// comments): the regression net for speed that machine noise cannot fool. check_work compares
// what a test measured with its baseline: a counter more than 5 % above fails naming the key, the
// counter and both values; one more than 5 % below passes with a note to tighten the baseline; a
// counter missing on either side fails. With PVSCOPE_WORK_BASELINE_OUT=FILE set, every measured
// line is also appended to FILE, to rewrite a baseline after a deliberate change (in a commit that
// says why).
#pragma once

#include <cstdint>
#include <map>
#include <string>

namespace pvs::test {

using WorkCounts = std::map<std::string, uint64_t>;

// The baseline file tests/baselines/<name> of the source tree.
std::string baseline_path(const std::string& name);

// Adds gtest failures (not fatal) for every counter of `measured` outside its baseline.
void check_work(const std::string& baseline_name, const std::string& key, const WorkCounts& measured);

} // namespace pvs::test
