// A ray tracer farmed on demand with the structure of INMOS Technical Note 7 ("Exploiting
// concurrency: a ray tracing example", J. Packer, 1987), on the SDK's farm skeleton
// (t800sim/farm.hpp): a master hands out the lines of an image and collects their colours; every
// other transputer runs a worker. A task is a line (its cost follows what its rays hit), a result
// the line's colours.
//
// On demand: each result is also a request. The master waits in one ALT over its workers' replies
// and answers each with the next line, in the image's order -- it cannot know a line's cost before
// the line is traced. Each worker holds two lines (the one it traces and one buffered ahead by its
// feeder), so it never waits for work after sending a result, and hands each result to a one-place
// buffer, so it starts its next line while the result crosses the link. Workers that are not the
// master's neighbours are reached through the simulator's routers: store-and-forward processes at
// high priority on every transputer a message enters, as TN07's routers run beside its workers.
#include <algorithm>

#include "programs/support/checksum.hpp"
#include "scene.hpp"
#include "t800sim/farm.hpp"
#include "t800sim/workload.hpp"

namespace raytrace {

namespace {

using namespace t800sim;

// A round is a frame: its shared input is the frame's number; a task's result is the line's
// colours, red, green then blue plane, one message of 3 x width REAL32s.
using LineFarm = Farm<INT, Block<REAL32>>;

// Lines a worker holds at once: the one it traces and the one buffered ahead.
constexpr int kLinesPerWorker = 2;
constexpr const char* kKernelName = "TRACE.LINE";

struct Image {
  int width, height, reflections;
  bool real64;
};

// One line traced in the image's precision, recorded as the kernel the worker computes (the colours
// travel as REAL32 either way).
Kernel line_kernel(const Image& im, int line) {
  if (im.real64)
    return record_kernel<Real64>(
        kKernelName, [&] { trace_line<Real64>(line, im.width, im.height, im.reflections); });
  return record_kernel<Real32>(
      kKernelName, [&] { trace_line<Real32>(line, im.width, im.height, im.reflections); });
}

std::vector<FarmTask> line_tasks(const Image& im) {
  std::vector<FarmTask> tasks;
  for (int line = 0; line < im.height; ++line)
    tasks.push_back({"line" + std::to_string(line), line_kernel(im, line)});
  return tasks;
}

// What a worker computes for a line once its kernel's time is taken: the same trace in plain
// float or double.
std::vector<float> traced(const Image& im, int line) {
  if (im.real64) return trace_line<double>(line, im.width, im.height, im.reflections);
  return trace_line<float>(line, im.width, im.height, im.reflections);
}

FarmOptions on_demand() {
  FarmOptions o;
  o.schedule = FarmSchedule::on_demand;
  o.in_flight = kLinesPerWorker;
  o.alt_master = true;
  o.longest_first = false;
  o.buffered_replies = true;
  return o;
}

Image image_of(const Params& p) {
  return {int(p.integer("width")), int(p.integer("height")), int(p.integer("reflections")),
          p.text("precision") == "real64"};
}

class RaytraceFarm : public Program {
 public:
  RaytraceFarm(const Params& p, const Network& n)
      : image_(image_of(p)),
        farm_(
            line_tasks(image_), [this](int line, const INT&) { return traced(image_, line); },
            on_demand()),
        master_(n.processor_name(n.host_processor())) {
    for (int i = 0; i < n.processors(); ++i)
      if (i != n.host_processor()) workers_.push_back(n.processor_name(i));
    if (workers_.empty())
      throw SettingError({kNetworkKey}, "the farm needs a worker processor beside the master's " +
                                            master_ +
                                            " (network.family with network.workers >= 1)");
  }

  void build(Builder& b) override {
    b.process("master", [this](Process& p) {
       store(farm_.round(p, INT(0)));
       farm_.finish(p);
     }).placed_on(master_);
    farm_.build(b, "master", workers_);
  }

  void results(Results& r) const override {
    r.set("width", std::int64_t(image_.width));
    r.set("height", std::int64_t(image_.height));
    r.set("reflections", std::int64_t(image_.reflections));
    r.set("precision", image_.real64 ? "real64" : "real32");
    r.set("workers", std::int64_t(workers_.size()));
    const FarmRoundTiming& frame = farm_.last_round();
    r.set("tp_us", frame.end_us - frame.start_us);
    r.set("tp_ms", (frame.end_us - frame.start_us) / 1000.0);
    r.set("image_checksum", programs::fnv1a_hex(pixels_));
    const std::vector<std::int64_t>& cycles = farm_.task_cycles();
    ResultValue line_cycles = ResultValue::list();
    for (std::int64_t c : cycles) line_cycles.push(ResultValue(c));
    r.set("line_cycles", line_cycles);
    r.set("line_cycles_min", *std::min_element(cycles.begin(), cycles.end()));
    r.set("line_cycles_max", *std::max_element(cycles.begin(), cycles.end()));
    double compute_us = 0;
    ResultValue per_worker = ResultValue::list();
    for (std::size_t w = 0; w < workers_.size(); ++w) {
      const std::vector<int>& lines = farm_.done_by()[w];
      for (int line : lines)
        compute_us += double(cycles[std::size_t(line)]) * r.cycle_ns(workers_[w]) / 1000.0;
      ResultValue v;
      v.set("name", "worker[" + std::to_string(w) + "]");
      v.set("processor", workers_[w]);
      v.set("processor_type", r.processor_type(workers_[w]));
      v.set("lines", std::int64_t(lines.size()));
      per_worker.push(v);
    }
    r.set("compute_us", compute_us);
    r.set("result_bytes", result_bytes_);
    r.set("per_worker", per_worker);
  }

 private:
  // The lines into the image, red plane, green plane, blue plane, line by line.
  void store(const std::vector<std::vector<float>>& lines) {
    const int width = image_.width, height = image_.height;
    pixels_.assign(std::size_t(kColours * width * height), 0.0f);
    for (int line = 0; line < height; ++line) {
      const std::vector<float>& rgb = lines[std::size_t(line)];
      result_bytes_ += wire_bytes<FarmReplies<Block<REAL32>>>({INT(line), {rgb}});
      for (int colour = 0; colour < kColours; ++colour)
        for (int x = 0; x < width && std::size_t(colour * width + x) < rgb.size(); ++x)
          pixels_[std::size_t((colour * height + line) * width + x)] =
              rgb[std::size_t(colour * width + x)];
    }
  }

  Image image_;
  LineFarm farm_;
  std::string master_;
  std::vector<std::string> workers_;
  std::vector<float> pixels_;
  std::int64_t result_bytes_ = 0;
};

}  // namespace

T800SIM_WORKLOAD(raytrace_farm) {
  return {
      "raytrace-farm",
      "a ray tracer farmed line by line from a master to a worker on every other transputer "
      "(INMOS TN07) on the SDK's farm skeleton: an ALT-ing on-demand master, workers buffering a "
      "line ahead, the simulator's routers forwarding work and results",
      {integer_param("width", 64, "pixels per line (a line is one work item)", 4, 4096),
       integer_param("height", 64, "lines of the image", 1, 4096),
       integer_param("reflections", 2, "mirror bounces traced at most", 0, 8),
       precision_param("precision", "real32", "occam REAL32 or REAL64 arithmetic of the tracing")},
      [](const Params& p, const Network& n) { return std::make_unique<RaytraceFarm>(p, n); }};
}

}  // namespace raytrace
