// Benchmark programs have their own main() and never start SystemC, but what they link may bring
// libsystemc.so, whose main() needs an sc_main to link (in a sanitizer build always). This is it,
// with the C linkage <systemc> declares it with.
extern "C" int sc_main(int, char**) {
  return 0;
}
