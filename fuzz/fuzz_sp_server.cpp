// libFuzzer target: SP request bodies through SpServer::handle in a temporary root, SP.SYSTEM
// disallowed (fuzz/iss_harness.hpp). Run from the build directory, e.g.
//   build-fuzz/fuzz/fuzz_sp_server -max_total_time=600 -max_len=2048 fuzz/corpus/sp
#include "fuzz/iss_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::serve_sp_requests(data, size);
  return 0;
}
