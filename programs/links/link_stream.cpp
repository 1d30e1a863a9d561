// Link streaming: a source sends `messages` blocks of `bytes` to a sink on a neighbour, in one
// direction or both at once; bandwidth is bytes over the time until the last block has arrived
// (kB = 1000 bytes, as the datasheet).
#include "programs/links/neighbours.hpp"
#include "t800sim/workload.hpp"

namespace programs {

namespace {

using namespace t800sim;

class LinkStream : public Program {
 public:
  LinkStream(const Params& p, const Network& n)
      : bytes_(p.integer("bytes")),
        messages_(p.integer("messages")),
        both_(p.text("direction") == "both"),
        ends_(neighbour_pair(p, n)) {}

  void build(Builder& b) override {
    stream(b, 0, "", ends_.first, ends_.second);
    if (both_) stream(b, 1, "-back", ends_.second, ends_.first);
  }

  void results(Results& r) const override {
    r.set("bytes", bytes_);
    r.set("messages", messages_);
    r.set("direction", both_ ? "both" : "one");
    workloads::ResultValue bandwidth;
    double total = 0;
    for (int d = 0; d < (both_ ? 2 : 1); ++d) {
      const double kBps = double(bytes_ * messages_) / (end_us_[d] * 1e-6) / 1000.0;
      bandwidth.set(d == 0 ? ends_.first + "->" + ends_.second : ends_.second + "->" + ends_.first,
                    kBps);
      total += kBps;
    }
    r.set("bandwidth_kBps", bandwidth);
    r.set("total_kBps", total);
  }

 private:
  void stream(Builder& b, int d, const std::string& suffix, const std::string& from,
              const std::string& to) {
    const auto c = b.channel<Block<BYTE>>("stream" + suffix, "source" + suffix, "sink" + suffix);
    b.process("source" + suffix, [this, c](Process& p) {
       const std::vector<BYTE> block(std::size_t(bytes_), 0);
       for (std::int64_t i = 0; i < messages_; ++i) p.out(c, block);
     }).placed_on(from);
    b.process("sink" + suffix, [this, c, d](Process& p) {
       for (std::int64_t i = 0; i < messages_; ++i) p.in(c);
       end_us_[d] = p.now_us();
     }).placed_on(to);
  }

  std::int64_t bytes_, messages_;
  bool both_;
  std::pair<std::string, std::string> ends_;
  double end_us_[2] = {0, 0};
};

}  // namespace

T800SIM_WORKLOAD(link_stream) {
  return {"link-stream",
          "one processor streams messages to a neighbour, in one or both directions",
          {integer_param("bytes", 4096, "message length in bytes", 1, 1e7),
           integer_param("messages", 64, "messages per direction", 1, 1e7),
           text_param("direction", "one", "\"one\" or \"both\"", {"one", "both"}),
           processor_param("from", "sending processor (default: the host's processor)"),
           processor_param("to", "receiving processor (default: a neighbour of `from`)")},
          [](const Params& p, const Network& n) { return std::make_unique<LinkStream>(p, n); }};
}

}  // namespace programs
