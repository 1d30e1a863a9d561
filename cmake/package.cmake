# The installable SDK: `cmake --install build --prefix P` puts the public headers, the static
# libraries, the t800sim executable and a CMake package under P. An out-of-tree project then does
#   find_package(t800sim REQUIRED)
# and links t800sim::plugin (a plugin t800sim loads) or t800sim::run (its own executable).
#
# Plugins link no simulator library: t800sim exports its symbols (ENABLE_EXPORTS) and holds the
# whole SDK (tools/CMakeLists.txt), so a plugin's references resolve to the one copy of the
# registry, the kernel recorder and the scheduler inside the executable that loads it. A plugin that
# carried its own static copy would register its kinds in a registry nobody reads; a shared
# libt800sim_sdk would need -fPIC across the simulator and would change how every test and tool
# links. Static archives therefore serve the stand-alone case only, and need no -fPIC.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(T800SIM_PACKAGE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/t800sim)

# The public headers, and the internal headers they include (their include closure, under
# include/t800sim/detail so that the installed tree adds no top-level folders but t800sim/). The
# test `sdk_install_headers` compiles every public header alone against the installed tree: a header
# missing here fails it.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/t800sim DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp")
install(FILES ${PROJECT_BINARY_DIR}/include/t800sim/version.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/t800sim)
set(T800SIM_DETAIL_HEADERS
    t800/codegen/recording.hpp
    t800/compute_work.hpp
    t800/isa/instruction.hpp
    t800/isa/opcode.hpp
    t800/operation_mix.hpp
    workloads/dynamics/counted.hpp
    workloads/dynamics/op_counts.hpp
    workloads/occam/structure.hpp
    workloads/occam/subscript.hpp
    workloads/params.hpp
    workloads/run/result_value.hpp
    workloads/setting_error.hpp)
foreach(header ${T800SIM_DETAIL_HEADERS})
  get_filename_component(dir ${header} DIRECTORY)
  install(FILES ${PROJECT_SOURCE_DIR}/${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/t800sim/detail/${dir})
endforeach()

# A plugin: the headers and nothing to link (the executable that loads it provides the rest).
add_library(t800sim_plugin INTERFACE)
target_include_directories(
  t800sim_plugin INTERFACE $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include> $<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/include>
                           $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}> $<INSTALL_INTERFACE:include>
                           $<INSTALL_INTERFACE:include/t800sim/detail>)
target_compile_features(t800sim_plugin INTERFACE cxx_std_17)
set_target_properties(t800sim_plugin PROPERTIES EXPORT_NAME plugin)
set_target_properties(t800sim_sdk PROPERTIES EXPORT_NAME sdk)
set_target_properties(t800sim_run PROPERTIES EXPORT_NAME run)

# The libraries an SDK user links, in lib/t800sim/ (their names -- network, workloads -- are too
# plain for lib/).
install(TARGETS t800_code t800_iss t800_host t800 network numerics workloads t800sim_sdk programs registered_workloads scene tools
                t800sim_run t800sim_plugin
        EXPORT t800simTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}/t800sim
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT t800simTargets NAMESPACE t800sim:: DESTINATION ${T800SIM_PACKAGE_DIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/t800simConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/t800simConfig.cmake INSTALL_DESTINATION ${T800SIM_PACKAGE_DIR}
                              PATH_VARS CMAKE_INSTALL_BINDIR)
# A plugin must be built against the SDK of the t800sim that loads it (T800SIM_PLUGIN records the
# version): only the exact version is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/t800simConfigVersion.cmake COMPATIBILITY ExactVersion)
install(FILES ${PROJECT_BINARY_DIR}/t800simConfig.cmake ${PROJECT_BINARY_DIR}/t800simConfigVersion.cmake
        DESTINATION ${T800SIM_PACKAGE_DIR})
