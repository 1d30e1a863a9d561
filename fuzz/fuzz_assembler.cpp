// libFuzzer target: arbitrary text through the T800 assembler, which may only refuse it with an
// AssemblyError (fuzz/iss_harness.hpp). Run from the build directory, e.g.
//   build-fuzz/fuzz/fuzz_assembler -max_total_time=600 -max_len=4096 fuzz/corpus/asm
#include "fuzz/iss_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::assemble_source(data, size);
  return 0;
}
