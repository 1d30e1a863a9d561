// GoogleTest's main for every test binary. libsystemc.so defines main() and calls sc_main(); a test binary
// brings its own main, and a trivial sc_main so the library links (docs/architecture.md).
#include <gtest/gtest.h>
#include <systemc>

int sc_main(int, char*[]) { return 0; }

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
