// Every input in the committed fuzz corpus (fuzz/corpus/: what libFuzzer found interesting, and
// every input that once crashed a reader) goes through the fuzz targets' harness: accepted or
// refused with a clean error, never anything else (fuzz/harness.hpp).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "fuzz/harness.hpp"
#include "fuzz/iss_harness.hpp"
#include "tests/test_paths.hpp"

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> corpus(const std::string& target) {
  std::vector<fs::path> files;
  for (const auto& entry :
       fs::directory_iterator(fs::path(test_paths::source_dir()) / "fuzz" / "corpus" / target))
    if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

template <class F>
void replay(const std::string& target, F&& harness) {
  const std::vector<fs::path> files = corpus(target);
  EXPECT_FALSE(files.empty());
  for (const fs::path& file : files) {
    std::ifstream in(file, std::ios::binary);
    const std::string data{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    try {
      harness(reinterpret_cast<const std::uint8_t*>(data.data()), data.size());
    } catch (const std::exception& e) {
      ADD_FAILURE() << file.filename() << ": " << e.what();
    }
  }
}

TEST(FuzzCorpus, ConfigurationFiles) {
  replay("config", fuzz::read_config);
}

TEST(FuzzCorpus, SetOverrides) {
  replay("set", fuzz::apply_overrides);
}

// The instruction-set simulator's inputs (fuzz/iss_harness.hpp): machine code on the ISS, SP
// request bodies on the SP server, text through the assembler.
TEST(FuzzCorpus, MachineCode) {
  replay("decoder", fuzz::run_machine_code);
}

TEST(FuzzCorpus, SpRequests) {
  replay("sp", fuzz::serve_sp_requests);
}

TEST(FuzzCorpus, AssemblerText) {
  replay("asm", fuzz::assemble_source);
}

}  // namespace
