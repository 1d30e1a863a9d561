# The SDK's run-time half: processes, channels, ALT, kernels, programs as declared, and the
# skeletons. It compiles into the workloads library, whose built-in programs (the dynamics farm)
# are written with it; the rest of sdk/ (placement, registration, plugins) builds on workloads/.
set(SDK_RUNTIME_SOURCES
    ${PROJECT_SOURCE_DIR}/sdk/alt.cpp
    ${PROJECT_SOURCE_DIR}/sdk/booted.cpp
    ${PROJECT_SOURCE_DIR}/sdk/builder.cpp
    ${PROJECT_SOURCE_DIR}/sdk/farm_schedule.cpp
    ${PROJECT_SOURCE_DIR}/sdk/farm_support.cpp
    ${PROJECT_SOURCE_DIR}/sdk/kernel.cpp
    ${PROJECT_SOURCE_DIR}/sdk/placement.cpp
    ${PROJECT_SOURCE_DIR}/sdk/process.cpp
    ${PROJECT_SOURCE_DIR}/sdk/realise.cpp
    ${PROJECT_SOURCE_DIR}/sdk/shared.cpp)
