#include "workloads/links/link_workloads.hpp"

#include <stdexcept>

#include "workloads/setting_error.hpp"

namespace workloads {

namespace {

// The two processors a link workload uses: `from` (default the host's processor) and `to` (default its
// first neighbour); they must be neighbours, since these workloads measure one link.
std::pair<int, int> neighbour_pair(const Params& params, const network::Topology& topology) {
  const int from = processor_param(params, "from", topology, std::max(topology.host_processor(), 0));
  const auto neighbours = topology.neighbours(from);
  if (neighbours.empty())
    throw SettingError({"workload.from", kNetworkKey},
                       "processor " + topology.processors[from].name +
                           " has no neighbour: a link workload needs two linked processors");
  const int to = processor_param(params, "to", topology, neighbours.front());
  if (std::find(neighbours.begin(), neighbours.end(), to) == neighbours.end())
    throw SettingError(
        {"workload.to", "workload.from", kNetworkKey},
        "workload.from and workload.to must be neighbours: " + topology.processors[from].name +
            " and " + topology.processors[to].name + " are not linked");
  return {from, to};
}

class PingPong : public Workload {
 public:
  PingPong(const Params& p, const network::Topology& t)
      : bytes_(p.integer("bytes")), iterations_(p.integer("iterations")) {
    std::tie(a_, b_) = neighbour_pair(p, t);
  }

  void build(network::Machine& m) override {
    auto& there = m.channel("ping", a_, b_);
    auto& back = m.channel("pong", b_, a_);
    m.spawn(a_, "pinger", t800::Priority::low, [&, this](network::Process& p) {
      for (std::int64_t i = 0; i < iterations_; ++i) {
        p.out(there, {bytes_, {}, "ping"});
        p.in(back);
      }
      end_us_ = p.now_us();
    });
    m.spawn(b_, "ponger", t800::Priority::low, [&, this](network::Process& p) {
      for (std::int64_t i = 0; i < iterations_; ++i) {
        p.in(there);
        p.out(back, {bytes_, {}, "pong"});
      }
    });
  }

  ResultValue results(const network::Machine& m) const override {
    ResultValue r;
    r.set("from", m.node_name(a_));
    r.set("to", m.node_name(b_));
    r.set("bytes", bytes_);
    r.set("iterations", iterations_);
    r.set("one_way_us", end_us_ / (2.0 * double(iterations_)));
    return r;
  }

 private:
  std::int64_t bytes_, iterations_;
  int a_ = 0, b_ = 0;
  double end_us_ = 0;
};

class LinkStream : public Workload {
 public:
  LinkStream(const Params& p, const network::Topology& t)
      : bytes_(p.integer("bytes")), messages_(p.integer("messages")), both_(p.text("direction") == "both") {
    std::tie(a_, b_) = neighbour_pair(p, t);
  }

  void build(network::Machine& m) override {
    stream(m, a_, b_, 0);
    if (both_) stream(m, b_, a_, 1);
  }

  ResultValue results(const network::Machine& m) const override {
    ResultValue r;
    r.set("bytes", bytes_);
    r.set("messages", messages_);
    r.set("direction", both_ ? "both" : "one");
    ResultValue bw;
    double total = 0;
    for (int d = 0; d < (both_ ? 2 : 1); ++d) {
      const double kBps = double(bytes_ * messages_) / (end_us_[d] * 1e-6) / 1000.0;
      bw.set(m.node_name(d == 0 ? a_ : b_) + "->" + m.node_name(d == 0 ? b_ : a_), kBps);
      total += kBps;
    }
    r.set("bandwidth_kBps", bw);
    r.set("total_kBps", total);
    return r;
  }

 private:
  // Bandwidth is bytes over the time until the last message has arrived (KB = 1000 bytes, as the datasheet).
  void stream(network::Machine& m, int from, int to, int d) {
    auto& c = m.channel(d == 0 ? "stream" : "stream-back", from, to);
    m.spawn(from, d == 0 ? "source" : "source-back", t800::Priority::low, [&c, this](network::Process& p) {
      for (std::int64_t i = 0; i < messages_; ++i) p.out(c, {bytes_, {}, "block"});
    });
    m.spawn(to, d == 0 ? "sink" : "sink-back", t800::Priority::low, [&c, this, d](network::Process& p) {
      for (std::int64_t i = 0; i < messages_; ++i) p.in(c);
      end_us_[d] = p.now_us();
    });
  }

  std::int64_t bytes_, messages_;
  bool both_;
  int a_ = 0, b_ = 0;
  double end_us_[2] = {0, 0};
};

}  // namespace

std::unique_ptr<Workload> make_pingpong(const WorkloadContext& c) {
  return std::make_unique<PingPong>(c.params, c.topology);
}

std::unique_ptr<Workload> make_link_stream(const WorkloadContext& c) {
  return std::make_unique<LinkStream>(c.params, c.topology);
}

}  // namespace workloads
