// Where a test finds the source tree (configs, examples, docs), the build tree (t800sim, test
// output) and the test plugins. Read at run time, not compiled in: a test's object is then the same
// in every clone of the repository, and a compiler cache (cmake/compiler_cache.cmake) serves a
// second clone's build from the first's. CTest passes them in the environment
// (tests/CMakeLists.txt); a test binary run by hand finds them from its own place in the build
// tree.
#pragma once

#include <string>
#include "tests/test_paths.hpp"

namespace test_paths {

// test_paths::source_dir(), else the source directory the build tree was configured from.
const std::string& source_dir();
// test_paths::binary_dir(), else the build tree this test binary is in (BUILD/tests/test_AREA).
const std::string& binary_dir();
// test_paths::plugin_dir(), else BUILD/tests/plugins.
const std::string& plugin_dir();

}  // namespace test_paths
