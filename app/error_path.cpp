#include "app/error_path.h"

#include "visibility/file_error.h"

#include <exception>
#include <string_view>

namespace pvs::app {

int run_reporting_errors(const std::string& input, std::FILE* err, const std::function<int()>& body,
                         const std::function<void()>& after_error, int error_code)
{
    try {
        return body();
    } catch (const FileError& e) {
        std::fprintf(err, "pvscope: error: %s\n", e.what());
    } catch (const std::exception& e) { // a zone without a tree, a result that cannot be written
        std::fprintf(err, "pvscope: error: %s: %s\n", input.c_str(), e.what());
    }
    if (after_error)
        after_error();
    return error_code;
}

int bad_arguments(std::FILE* err, const std::string& problem)
{
    std::fprintf(err, "pvscope: error: %s\n", problem.c_str());
    return kExitBadArguments;
}

int file_error(std::FILE* err, const std::string& problem)
{
    std::fprintf(err, "pvscope: error: %s\n", problem.c_str());
    return kExitFileError;
}

} // namespace pvs::app
