// libFuzzer target: configuration files through every reader (fuzz/harness.hpp).
#include "fuzz/harness.hpp"

extern "C" int sc_main(int, char**) { return 0; }  // libsystemc.so's main needs one; libFuzzer's runs

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::read_config(data, size);
  return 0;
}
