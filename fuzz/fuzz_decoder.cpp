// libFuzzer target: random bytes as machine code on the instruction-set simulator, strict and wrap
// addressing (fuzz/iss_harness.hpp). Run from the build directory, e.g.
//   build-fuzz/fuzz/fuzz_decoder -max_total_time=600 -max_len=1024 -timeout=10 fuzz/corpus/decoder
#include "fuzz/iss_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::run_machine_code(data, size);
  return 0;
}
