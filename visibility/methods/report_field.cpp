#include "visibility/methods/report_field.h"

namespace pvs {

const ReportField* find_field(const std::vector<ReportField>& fields, std::string_view name)
{
    for (const ReportField& f : fields)
        if (f.name == name)
            return &f;
    return nullptr;
}

} // namespace pvs
