// The chart's points for a compare result (ui/method_compare.h): one per row, labelled short
// ("portal-full L2 -passages", "reference 1024"), methods that bake nothing in the stored column.
// Shared by `pvscope compare --chart` and the inspector's Compare panel, so both label alike.
#pragma once

#include "ui/chart/speed_accuracy_chart.h"
#include "render/method_compare.h"

#include <vector>

namespace pvs::ui::chart {

std::vector<ChartPoint> compare_chart_points(const CompareResult& result);

} // namespace pvs::ui::chart
