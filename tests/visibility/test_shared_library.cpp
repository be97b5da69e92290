// Libraries opened at run time (visibility/shared_library.h), as Embree and Irrlicht are: a
// library that is not there, or lacks a symbol, must come back as one sentence naming it, the
// Debian package to install and what the loader said -- not a crash at the first call.
#include "visibility/shared_library.h"

#include <gtest/gtest.h>

#include <string>

namespace pvs {
namespace {

TEST(SharedLibrary, AMissingLibraryIsNamedWithItsPackage)
{
    std::string error;
    EXPECT_EQ(open_shared_library("libpvscope-no-such-library.so.7", "No Such", "libnosuch7", error), nullptr);
    EXPECT_NE(error.find("cannot open No Such (libpvscope-no-such-library.so.7; Debian package libnosuch7): "),
              std::string::npos)
        << error;
    EXPECT_NE(error.find("libpvscope-no-such-library.so.7: cannot open shared object file"), std::string::npos)
        << error; // the dynamic loader's own words follow
}

TEST(SharedLibrary, SymbolsResolveAndAMissingOneIsNamed)
{
    // zlib: installed wherever pvscope runs (the readers link it).
    std::string error;
    void* zlib = open_shared_library("libz.so.1", "zlib", "zlib1g", error);
    ASSERT_NE(zlib, nullptr) << error;
    using Version = const char* (*)();
    const auto version = reinterpret_cast<Version>(shared_library_symbol(zlib, "libz.so.1", "zlib", "zlibVersion", error));
    ASSERT_NE(version, nullptr) << error;
    EXPECT_EQ(version()[0], '1'); // zlib 1.x
    EXPECT_EQ(shared_library_symbol(zlib, "libz.so.1", "zlib", "no_such_function", error), nullptr);
    EXPECT_EQ(error, "zlib (libz.so.1) has no no_such_function");
}

} // namespace
} // namespace pvs
