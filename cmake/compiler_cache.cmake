# A compiler cache when the machine has one (scripts/setup.sh installs Debian's ccache): every build of the
# tree -- ./build, ./build-asan, a user's own -- goes through it, so a rebuild, or a fresh clone on a
# machine that has built t800sim before, recompiles only what changed. Never required: without ccache
# the compiler runs directly. A launcher given on the command line (-DCMAKE_CXX_COMPILER_LAUNCHER=...)
# or -DT800SIM_CCACHE=OFF wins.
#
# Paths are made relative to the source tree (CCACHE_BASEDIR) and the working directory is left out
# of the hash (CCACHE_NOHASHDIR), so that two clones in different folders share their objects; no
# object has a clone's absolute path compiled in (tests/test_paths.hpp says how tests find theirs).
option(T800SIM_CCACHE "compile through ccache when it is installed" ON)
if(T800SIM_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  find_program(T800SIM_CCACHE_PROGRAM ccache)
  if(T800SIM_CCACHE_PROGRAM)
    set(CMAKE_CXX_COMPILER_LAUNCHER ${CMAKE_COMMAND} -E env CCACHE_BASEDIR=${PROJECT_SOURCE_DIR}
                                    CCACHE_NOHASHDIR=1 ${T800SIM_CCACHE_PROGRAM})
  endif()
endif()
