// A ray tracer farmed on demand, the structure of INMOS Technical Note 7 ("Exploiting concurrency:
// a ray tracing example", J. Packer, 1987): a master hands out the lines of an image and collects
// their colours; every other transputer runs a worker (at low priority) beside a router (at high
// priority) that passes work down and results up the links, so work and results reach transputers
// that are not the master's neighbours through the routers of the transputers between. Each
// worker buffers one line ahead, so it never waits for the next after sending a result.
//
// The master is on-demand: each result is also a request, and the master's ALT over its links
// takes results as they come and answers each with the next line. Credits tell each router how
// many lines its worker and each of its subtrees can take: two per worker (the line it traces and
// the one buffered), one back with every result.
#include <optional>
#include <variant>

#include "farm_tree.hpp"
#include "programs/support/checksum.hpp"
#include "scene.hpp"
#include "t800sim/alt.hpp"
#include "t800sim/workload.hpp"

namespace raytrace {

namespace {

using namespace t800sim;

// CASE line; INT | stop
using Work = Variant<Case<INT>, Case<>>;
// CASE line; INT; INT::[]REAL32 (red, green then blue plane) | stopped
using Result = Variant<Case<INT, Counted<INT, REAL32>>, Case<>>;

// Lines a worker holds at once: the one it traces and the one buffered ahead.
constexpr int kLinesPerWorker = 2;
constexpr const char* kKernelName = "TRACE.LINE";

value_of<Work> line_item(int line) {
  return value_of<Work>(std::in_place_index<0>, Case<INT>{{INT(line)}});
}
value_of<Work> stop_item() {
  return value_of<Work>(std::in_place_index<1>);
}
value_of<Result> result_item(int line, std::vector<float> rgb) {
  return value_of<Result>(std::in_place_index<0>,
                          Case<INT, Counted<INT, REAL32>>{{INT(line), std::move(rgb)}});
}
value_of<Result> stopped_item() {
  return value_of<Result>(std::in_place_index<1>);
}
bool is_stop(const value_of<Work>& v) {
  return v.index() == 1;
}
bool is_stop(const value_of<Result>& v) {
  return v.index() == 1;
}

std::string member(const char* group, int i) {
  return std::string(group) + "[" + std::to_string(i) + "]";
}

class RaytraceFarm : public Program {
 public:
  RaytraceFarm(const Params& p, const Network& n)
      : width_(int(p.integer("width"))),
        height_(int(p.integer("height"))),
        reflections_(int(p.integer("reflections"))),
        real64_(p.text("precision") == "real64"),
        tree_(n),
        image_(std::size_t(kColours * width_ * height_), 0.0f),
        line_cycles_(std::size_t(height_), 0),
        line_worker_(std::size_t(height_), -1),
        lines_of_(std::size_t(tree_.workers()), 0) {}

  void build(Builder& b) override {
    const int n = tree_.workers();
    // Placed where the tree says: routers and workers on the workers' processors.
    b.process("master", [this](Process& p) { master(p); }).placed_on(tree_.master_processor());
    b.processes("router", n, [this](Process& p, int w) { router(p, w); })
        .placed_on(tree_.worker_processors())
        .high();
    b.processes("worker", n, [this](Process& p, int w) {
       worker(p, w);
     }).placed_on(tree_.worker_processors());
    for (int w = 0; w < n; ++w) {
      const int up = tree_.worker(w).parent;
      const std::string parent = up < 0 ? "master" : member("router", up);
      work_.push_back(b.channel<Work>(member("work", w), parent, member("router", w)));
      result_.push_back(b.channel<Result>(member("result", w), member("router", w), parent));
    }
    feed_ = b.channels<Work>("feed", n, "router", "worker");
    done_ = b.channels<Result>("done", n, "worker", "router");
    ahead_ = b.channels<Work>("ahead", n, "router", "router");
    credit_ = b.channels<INT>("credit", n, "router", "router");
    // The PROC every worker runs, for its memory: one line's code (the longest path through a
    // pixel sets its size) and its arrays.
    std::vector<float> unused;
    const Kernel line = trace(height_ / 2, unused);
    for (int w = 0; w < n; ++w) b.code(member("worker", w), line);
  }

  void results(Results& r) const override {
    r.set("width", std::int64_t(width_));
    r.set("height", std::int64_t(height_));
    r.set("reflections", std::int64_t(reflections_));
    r.set("precision", real64_ ? "real64" : "real32");
    r.set("workers", std::int64_t(tree_.workers()));
    r.set("tp_us", end_us_ - start_us_);
    r.set("tp_ms", (end_us_ - start_us_) / 1000.0);
    r.set("image_checksum", programs::fnv1a_hex(image_));
    double compute_us = 0;
    std::int64_t fewest = line_cycles_.empty() ? 0 : line_cycles_.front(), most = fewest;
    ResultValue cycles = ResultValue::list();
    for (int line = 0; line < height_; ++line) {
      const std::int64_t c = line_cycles_[std::size_t(line)];
      const int w = line_worker_[std::size_t(line)];
      if (w >= 0) compute_us += double(c) * r.cycle_ns(tree_.worker(w).processor) / 1000.0;
      fewest = std::min(fewest, c);
      most = std::max(most, c);
      cycles.push(ResultValue(c));
    }
    r.set("line_cycles", cycles);
    r.set("line_cycles_min", fewest);
    r.set("line_cycles_max", most);
    r.set("compute_us", compute_us);
    r.set("result_bytes", result_bytes_);
    ResultValue per_worker = ResultValue::list();
    for (int w = 0; w < tree_.workers(); ++w) {
      ResultValue v;
      v.set("name", member("worker", w));
      v.set("processor", tree_.worker(w).processor);
      v.set("parent", tree_.worker(w).parent < 0 ? tree_.master_processor()
                                                 : tree_.worker(tree_.worker(w).parent).processor);
      v.set("lines", std::int64_t(lines_of_[std::size_t(w)]));
      per_worker.push(v);
    }
    r.set("per_worker", per_worker);
  }

 private:
  // On demand: the first lines fill every subtree's credit, taken in turn so that the subtrees
  // start together; then each result earns its subtree the next line.
  void master(Process& p) {
    const std::vector<int>& children = tree_.master_children();
    std::vector<int> credit;
    for (int c : children) credit.push_back(kLinesPerWorker * tree_.worker(c).subtree);
    int next = 0;
    start_us_ = p.now_us();
    for (bool sent = true; sent && next < height_;) {
      sent = false;
      for (std::size_t i = 0; i < children.size() && next < height_; ++i)
        if (credit[i] > 0) {
          p.out(work_[std::size_t(children[i])], line_item(next++));
          --credit[i];
          sent = true;
        }
    }
    for (int received = 0; received < height_; ++received) {
      Alt alt(p);
      for (std::size_t i = 0; i < children.size(); ++i)
        alt.input(result_[std::size_t(children[i])], [&, i](const value_of<Result>& v) {
          store(v);
          if (next < height_) p.out(work_[std::size_t(children[i])], line_item(next++));
        });
      alt.select();
    }
    end_us_ = p.now_us();
    for (int c : children) p.out(work_[std::size_t(c)], stop_item());
    for (int c : children) p.in(result_[std::size_t(c)]);  // stopped
  }

  void store(const value_of<Result>& v) {
    const auto& [line, rgb] = std::get<0>(v).items;
    result_bytes_ += wire_bytes<Result>(v);
    for (int colour = 0; colour < kColours; ++colour)
      for (int x = 0; x < width_; ++x)
        image_[std::size_t((colour * height_ + line) * width_ + x)] =
            rgb[std::size_t(colour * width_ + x)];
  }

  // TN07's PRI PAR: the router's processes run at high priority beside the worker, so work and
  // results pass through at once, whatever the worker computes.
  void router(Process& p, int w) {
    p.par({[this, w](Process& q) { distribute(q, w); }, [this, w](Process& q) { collect(q, w); },
           [this, w](Process& q) { buffer(q, w); }});
  }

  // Lines from the parent go to the local worker while it has credit, else to the subtree with
  // most; credits come back from the collector with the results.
  void distribute(Process& p, int w) {
    const FarmTree::Worker& me = tree_.worker(w);
    std::vector<Out<Work>> to{ahead_[std::size_t(w)]};
    std::vector<int> credit{kLinesPerWorker};
    for (int c : me.children) {
      to.push_back(work_[std::size_t(c)]);
      credit.push_back(kLinesPerWorker * tree_.worker(c).subtree);
    }
    std::optional<value_of<Work>> held;
    for (bool stop = false; !stop;) {
      if (held) {
        std::size_t d = 0;  // the local worker first, as TN07's routers do
        if (credit[0] == 0)
          for (std::size_t i = 1; i < credit.size(); ++i)
            if (credit[i] > credit[d]) d = i;
        if (credit[d] > 0) {
          p.out(to[d], *held);
          --credit[d];
          held.reset();
          continue;
        }
      }
      Alt(p)
          .input(
              work_[std::size_t(w)],
              [&](const value_of<Work>& v) {
                if (is_stop(v))
                  stop = true;
                else
                  held = v;
              },
              !held)
          .input(credit_[std::size_t(w)], [&](INT d) { ++credit[std::size_t(d)]; })
          .select();
    }
    for (const Out<Work>& c : to) p.out(c, stop_item());
  }

  // Results from the subtrees (first: TN07 passes through traffic first) and the local worker go
  // up; each gives its source a credit. Stops when every source has stopped.
  void collect(Process& p, int w) {
    const FarmTree::Worker& me = tree_.worker(w);
    std::vector<In<Result>> from;
    for (int c : me.children) from.push_back(result_[std::size_t(c)]);
    from.push_back(done_[std::size_t(w)]);
    const std::size_t local = from.size() - 1;
    std::vector<bool> stopped(from.size(), false);
    for (std::size_t left = from.size(); left > 0;) {
      PriAlt alt(p);
      for (std::size_t i = 0; i < from.size(); ++i)
        alt.input(
            from[i],
            [&, i](const value_of<Result>& v) {
              if (is_stop(v)) {
                stopped[i] = true;
                --left;
                return;
              }
              p.out(credit_[std::size_t(w)], INT(i == local ? 0 : i + 1));
              p.out(result_[std::size_t(w)], v);
            },
            !stopped[i]);
      alt.select();
    }
    p.out(result_[std::size_t(w)], stopped_item());
  }

  // One line ahead of the worker.
  void buffer(Process& p, int w) {
    for (;;) {
      const value_of<Work> v = p.in(ahead_[std::size_t(w)]);
      p.out(feed_[std::size_t(w)], v);
      if (is_stop(v)) return;
    }
  }

  // One line traced in the program's precision (the colours travel as REAL32 either way), recorded
  // as the kernel the worker computes.
  Kernel trace(int line, std::vector<float>& rgb) const {
    if (real64_)
      return record_kernel<Real64>(
          kKernelName, [&] { rgb = trace_line<Real64>(line, width_, height_, reflections_); });
    return record_kernel<Real32>(
        kKernelName, [&] { rgb = trace_line<Real32>(line, width_, height_, reflections_); });
  }

  void worker(Process& p, int w) {
    for (;;) {
      const value_of<Work> v = p.in(feed_[std::size_t(w)]);
      if (is_stop(v)) break;
      const int line = std::get<0>(std::get<0>(v).items);
      std::vector<float> rgb;
      const Kernel k = trace(line, rgb);
      line_cycles_[std::size_t(line)] = p.cycles(k);
      line_worker_[std::size_t(line)] = w;
      p.compute(k);
      ++lines_of_[std::size_t(w)];
      p.out(done_[std::size_t(w)], result_item(line, std::move(rgb)));
    }
    p.out(done_[std::size_t(w)], stopped_item());
  }

  int width_, height_, reflections_;
  bool real64_;
  FarmTree tree_;
  std::vector<Chan<Work>> work_, feed_, ahead_;
  std::vector<Chan<Result>> result_, done_;
  std::vector<Chan<INT>> credit_;
  std::vector<float> image_;  // red plane, green plane, blue plane; line by line
  std::vector<std::int64_t> line_cycles_;
  std::vector<int> line_worker_, lines_of_;
  std::int64_t result_bytes_ = 0;
  double start_us_ = 0, end_us_ = 0;
};

}  // namespace

T800SIM_WORKLOAD(raytrace_farm) {
  return {
      "raytrace-farm",
      "a ray tracer farmed line by line from a master to a worker on every other transputer "
      "(INMOS TN07): an ALT-ing on-demand master, workers buffering a line ahead, routers "
      "forwarding work and results on every transputer",
      {integer_param("width", 64, "pixels per line (a line is one work item)", 4, 4096),
       integer_param("height", 64, "lines of the image", 1, 4096),
       integer_param("reflections", 2, "mirror bounces traced at most", 0, 8),
       precision_param("precision", "real32", "occam REAL32 or REAL64 arithmetic of the tracing")},
      [](const Params& p, const Network& n) { return std::make_unique<RaytraceFarm>(p, n); }};
}

}  // namespace raytrace
