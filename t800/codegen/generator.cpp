#include "t800/codegen/generator.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

#include "t800/codegen/expression.hpp"
#include "t800/codegen/frame.hpp"
#include "t800/codegen/integer_expression.hpp"
#include "t800/codegen/runtime_library.hpp"
#include "t800/codegen/subscripts.hpp"

namespace t800::codegen {

namespace {

using isa::Instruction;
using isa::MemoryRef;
using isa::Op;
using isa::Region;

// A loop's iterations as the recording has them, found before generating: how many there are and
// the index of the first (the control block is set up with both).
struct LoopShape {
  std::int64_t first = 0;
  std::int64_t count = 0;
};

std::map<std::size_t, LoopShape> loop_shapes(const Recording& r) {
  std::map<std::size_t, LoopShape> shapes;
  std::vector<std::size_t> open;
  for (std::size_t i = 0; i < r.events().size(); ++i) {
    const Event& e = r.events()[i];
    if (e.kind == EventKind::loop_begin) open.push_back(i);
    if (e.kind == EventKind::iteration) {
      LoopShape& s = shapes[open.back()];
      if (s.count++ == 0) s.first = e.index;
    }
    if (e.kind == EventKind::loop_end) {
      shapes[open.back()];  // a loop of no iterations still has a shape
      open.pop_back();
    }
  }
  return shapes;
}

// Code being emitted for one body: the top level, or one iteration of a loop.
struct Body {
  std::vector<CodeRun> runs;
  isa::Sequence open;  // straight-line code not yet closed into a run
  // Bytes from the body's first instruction to where its code continues: a loop inside counts
  // as its last iteration, the one the processor falls through from (each iteration's code starts
  // at the loop's first address).
  int static_bytes = 0;
  // What the loops inside occupy beyond that: their largest iteration's code less their last's.
  int extra_bytes = 0;
  int footprint() const { return static_bytes + extra_bytes; }  // its code in memory
  void flush(const std::string& label, std::int64_t seq_iterations = -1) {
    if (open.empty()) return;
    runs.push_back({label, std::move(open), 1, false, seq_iterations});
    open.clear();
  }
};

bool same_code(const std::vector<CodeRun>& a, const std::vector<CodeRun>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].times != b[i].times || a[i].code.size() != b[i].code.size()) return false;
    for (std::size_t k = 0; k < a[i].code.size(); ++k) {
      const Instruction& x = a[i].code[k];
      const Instruction& y = b[i].code[k];
      if (x.op != y.op || x.operand != y.operand || x.param != y.param || x.real64 != y.real64 ||
          !(x.data == y.data))
        return false;
    }
    if (a[i].seq_iterations != b[i].seq_iterations) return false;
  }
  return true;
}

// One open replicated SEQ: its control block and the iterations emitted so far, grouped into
// runs of identical code.
struct OpenLoop {
  int depth = 0;
  std::size_t begin_event = 0;
  LoopShape shape;
  bool known_bounds = true;    // its first index and count are constants the compiler knows
  std::int64_t iteration = 0;  // iterations finished
  int max_footprint = 0;       // the largest iteration's code in memory
  int last_static = 0;         // the last iteration's, to where the code after the loop is
  std::vector<CodeRun> group;  // the code of the current group of identical iterations
  std::int64_t group_first = 0, group_size = 0;
};

// What the previous pass learnt: the code's size (the distance to the constant table after it)
// and the frame's size (the operand of ajw).
struct Sizes {
  int code_bytes = 256;
  int frame_words = 8;
  // Each loop's code (its last iteration's, from its first instruction to where the code after
  // it is), by the event that begins it: the distance a count test jumps over a loop not run.
  std::map<std::size_t, int> loop_bytes;
};

class Generator : public EmitSink {
 public:
  Generator(const Recording& r, const Target& t, Sizes previous)
      : r_(r),
        target_(t),
        previous_(previous),
        subscripts_(classify_subscripts(r)),
        shapes_(loop_shapes(r)),
        frame_(r),
        flow_(r),
        expressions_(r, *this, frame_, flow_),
        integers_(r, *this, frame_, flow_, expressions_) {
    expressions_.connect(integers_);
  }

  CodeUnit run() {
    bodies_.push_back(Body{});
    call_and_enter();
    for (std::size_t i = 0; i < r_.events().size(); ++i) event(i);
    leave();
    Body& top = bodies_.back();
    top.flush(r_.name());
    CodeUnit unit;
    unit.name = r_.name();
    unit.real64 = r_.real64();
    unit.runs = std::move(top.runs);
    unit.arrays = r_.arrays();
    unit.code_bytes = top.footprint();
    unit.constant_bytes = expressions_.constant_bytes();
    unit.constants = expressions_.constant_table();
    unit.workspace_words = frame_.words();
    unit.routines = routines_;
    return unit;
  }

  // ---- EmitSink: where the expression emitter's instructions go ----
  void emit(Instruction in) override {
    Body& b = bodies_.back();
    b.static_bytes += in.bytes();
    // A taken cj jumps over the code of the branch not taken: it is in memory all the same (the
    // loop's back offset and the unit's size count it).
    if (in.op == Op::cj && in.param) b.static_bytes += int(in.operand);
    b.open.push_back(std::move(in));
  }

  void call(const CodeUnit& routine) override {
    Body& b = bodies_.back();
    b.flush(label());
    for (const CodeRun& run : routine.runs) b.runs.push_back(run);
    // One routine in memory per name: REAL32OP serves + - * / by its operation code.
    const auto known = std::find_if(routines_.begin(), routines_.end(),
                                    [&](const CodeUnit* r) { return r->name == routine.name; });
    if (known == routines_.end()) routines_.push_back(&routine);
  }

  std::string element(int access) const override {
    const Access& a = r_.accesses()[std::size_t(access)];
    const ArrayDecl& array = r_.arrays()[std::size_t(a.array)];
    if (a.subscript >= 0) return array.name + "[" + integers_.describe(a.subscript) + "]";
    if (array.length == 1 && array.storage == ArrayStorage::workspace) return array.name;
    return array.name + "[" + subscript_text(subscripts_[std::size_t(access)]) + "]";
  }

  // An element's address on the integer stack, for the loads and stores that take one: the
  // subscript (the loop's index plus a constant, or the INT the kernel computed), checked against
  // the array's bound, scaled onto the array's base.
  void address(int access) override {
    const Access& a = r_.accesses()[std::size_t(access)];
    const ArrayDecl& array = r_.arrays()[std::size_t(a.array)];
    const Subscript& s = subscripts_[std::size_t(access)];
    const int words = element_words(array, r_.real64());
    if (subscript_and_base(access)) {
      emit({words == 2 ? Op::wsubdb : Op::wsub, 0, 0, false, {}, element(access)});
      return;
    }
    base(a.array, element(access));
    if (s.offset != 0) emit({Op::ldnlp, s.offset * words, 0, false, {}, element(access)});
  }

  bool subscript_and_base(int access) override {
    const Access& a = r_.accesses()[std::size_t(access)];
    const ArrayDecl& array = r_.arrays()[std::size_t(a.array)];
    const Subscript& s = subscripts_[std::size_t(access)];
    const std::string element = this->element(access);
    if (a.subscript >= 0 || s.by_loop) {
      if (a.subscript >= 0) {
        integers_.evaluate(a.subscript);
      } else {
        emit(
            {Op::ldl, frame_.loop_index(s.depth), 0, false, workspace(), loop_index_name(s.depth)});
        if (s.offset != 0) emit({Op::adc, s.offset, 0, false, {}, element});
      }
      if (target_.checked && !provably_in_range(a, s, array)) {
        emit({Op::ldc, array.length, 0, false, {}, "bound of " + array.name});
        emit({Op::csub0, 0, 0, false, {}, "range check"});
      }
      base(a.array, element);
      return true;
    }
    return false;
  }

  // The subscript, then the bound beside it (ldc; csub0) or the base (ldl; wsub): two registers
  // at least, more for a subscript that needs them.
  int address_need(int access) override {
    const int subscript = r_.accesses()[std::size_t(access)].subscript;
    if (subscript >= 0) return std::max(2, integers_.evaluation_need(subscript));
    return subscripts_[std::size_t(access)].by_loop ? 2 : 1;
  }

  // An INT element: a workspace variable by ldl/stl, an element with a constant subscript by
  // ldnl/stnl from its array's pointer, one with a computed subscript through its address.
  void load_word(int access) override { word(access, false); }
  void store_word(int access) override { word(access, true); }
  void store_word_at_address(int access) override {
    emit({Op::stnl, 0, 0, false, element_memory(access), element(access) + " :="});
  }

  const Target& target() const override { return target_; }

  Sizes sizes() const { return {bodies_.front().footprint(), frame_.words(), loop_bytes_}; }

 private:
  static MemoryRef workspace() { return {Region::workspace, -1}; }

  // The INMOS compiler leaves out the range check of a subscript it proves in range: the bare
  // index of a SEQ whose first index and count it knows, into an array that holds every index
  // the SEQ takes (D7205A oc; a subscript computed from the index, i + 1 or 6 - i, is checked;
  // docs/compute-model.md, "Against the INMOS compiler").
  bool provably_in_range(const Access& a, const Subscript& s, const ArrayDecl& array) const {
    int depth = -1;
    if (a.subscript >= 0) {
      const Node& n = r_.nodes()[std::size_t(a.subscript)];
      if (n.kind == NodeKind::loop_index) depth = n.depth;
    } else if (s.by_loop && s.offset == 0) {
      depth = s.depth;
    }
    if (depth < 0 || depth >= int(loops_.size())) return false;
    const OpenLoop& l = loops_[std::size_t(depth)];
    return l.known_bounds && l.shape.first >= 0 && l.shape.first + l.shape.count <= array.length;
  }

  static std::string subscript_text(const Subscript& s) {
    if (!s.by_loop) return std::to_string(s.offset);
    if (s.offset == 0) return loop_index_name(s.depth);
    return loop_index_name(s.depth) + (s.offset > 0 ? "+" : "") + std::to_string(s.offset);
  }

  // The caller passes the arrays' addresses (three in registers, the rest in its workspace) and
  // calls; the PROC opens its frame and points at its constant table.
  void call_and_enter() {
    int parameters = 0;
    for (std::size_t a = 0; a < r_.arrays().size(); ++a) {
      if (r_.arrays()[a].storage != ArrayStorage::pointer) continue;
      emit({Op::ldlp, 0, 0, false, {}, "caller: address of " + r_.arrays()[a].name});
      if (++parameters > 3)
        emit({Op::stl, parameters - 4, 0, false, workspace(), "caller: parameter"});
    }
    constexpr std::int64_t kCallDistance = 64;  // from the call's successor to the PROC
    emit({Op::call, kCallDistance, 0, false, workspace(), "call " + r_.name()});
    emit({Op::ajw, -(previous_.frame_words - 4), 0, false, {}, "enter " + r_.name()});
    if (expressions_.uses_constants()) {
      // ldpi: A := the address of ldpi's successor + A (CWG). The table is past the code and
      // word aligned: fpldnlsn/fpldnldb (and the fpldnl*op forms) address whole words, the
      // address's low two bits are not used, so a table off a word boundary would be read from
      // the wrong bytes. The unit's first byte is word aligned (as a compiled module's is), and
      // the PROC is kCallDistance bytes after the call; `here` is where this ldc is, from there.
      const std::int64_t here = bodies_.back().static_bytes + kCallDistance;
      const auto table = [&](std::int64_t distance) {  // the table's offset in the unit
        return here + isa::encoded_bytes(Op::ldc, distance) + isa::encoded_bytes(Op::ldpi) +
               distance;
      };
      std::int64_t distance = previous_.code_bytes;
      while (table(distance) % 4 != 0) ++distance;
      emit({Op::ldc, distance, 0, false, {}, "constant table"});
      emit({Op::ldpi, 0, 0, false, {}, "constant table"});
      emit({Op::stl, frame_.constant_table(), 0, false, workspace(), "constant table"});
    }
  }

  void leave() {
    emit({Op::ajw, previous_.frame_words - 4, 0, false, {}, "leave " + r_.name()});
    emit({Op::ret, 0, 0, false, workspace(), "return"});
  }

  void word(int access, bool store) {
    const Access& a = r_.accesses()[std::size_t(access)];
    const ArrayDecl& array = r_.arrays()[std::size_t(a.array)];
    const Subscript& s = subscripts_[std::size_t(access)];
    const std::string what = element(access) + (store ? " :=" : "");
    const MemoryRef data = element_memory(access);
    const bool computed = s.by_loop || a.subscript >= 0;
    if (!computed && array.storage == ArrayStorage::workspace) {
      emit(
          {store ? Op::stl : Op::ldl, frame_.array_base(a.array) + s.offset, 0, false, data, what});
      return;
    }
    std::int64_t offset = 0;
    if (computed) {
      address(access);
    } else {
      base(a.array, what);
      offset = s.offset;
    }
    emit({store ? Op::stnl : Op::ldnl, offset, 0, false, data, what});
  }

  MemoryRef element_memory(int access) const {
    const int array = r_.accesses()[std::size_t(access)].array;
    return r_.arrays()[std::size_t(array)].storage == ArrayStorage::workspace
               ? workspace()
               : MemoryRef{Region::array, array};
  }

  void base(int array, const std::string& element) {
    const ArrayDecl& d = r_.arrays()[std::size_t(array)];
    if (d.storage == ArrayStorage::workspace)
      emit({Op::ldlp, frame_.array_base(array), 0, false, {}, element});
    else
      emit({Op::ldl, frame_.array_base(array), 0, false, workspace(), d.name + " (pointer)"});
  }

  std::string label() const {
    if (loops_.empty()) return r_.name();
    std::string text = r_.name();
    for (const OpenLoop& l : loops_)
      text += ", SEQ " + loop_index_name(l.depth) + " iteration " +
              std::to_string(l.shape.first + l.iteration);
    return text;
  }

  void event(std::size_t i) {
    const Event& e = r_.events()[i];
    switch (e.kind) {
      case EventKind::value:
        if (is_int(e.node))
          integers_.define(e.node, int(i));
        else
          expressions_.define(e.node, int(i));
        break;
      case EventKind::store:
        if (is_int(e.node))
          integers_.store(e.node, e.access, int(i));
        else
          expressions_.store(e.node, e.access, int(i));
        break;
      case EventKind::test:
        if (is_int(e.node))
          integers_.test(e.node, e.taken, int(i));
        else
          expressions_.test(e.node, e.taken, int(i));
        break;
      case EventKind::integer:
        for (std::int64_t k = 0; k < e.count; ++k) integer(e.integer);
        break;
      case EventKind::loop_begin:
        loop_begin(i);
        break;
      case EventKind::iteration:
        iteration(false);
        break;
      case EventKind::loop_end:
        loop_end();
        break;
    }
  }

  bool is_int(int node) const { return r_.nodes()[std::size_t(node)].integer; }

  // The integer statements' code (compiler writer's guide): an IF on a flag loads it and jumps on
  // false; an assignment loads and stores; the FPU's error flag is tested and jumped on.
  void integer(IntegerStatement s) {
    const int flag = frame_.integer_variable();
    switch (s) {
      case IntegerStatement::test:
        emit({Op::ldl, flag, 0, false, workspace(), "IF: load the condition"});
        emit({Op::cj, 4, 0, false, {}, "IF"});
        break;
      case IntegerStatement::move:
        emit({Op::ldl, flag, 0, false, workspace(), "integer assignment"});
        emit({Op::stl, flag, 0, false, workspace(), "integer assignment"});
        break;
      case IntegerStatement::error_check:
        if (target_.fpu)
          emit({Op::fptesterror, 0, 0, false, {}, "test the FPU error flag"});
        else
          emit({Op::testerr, 0, 0, false, {}, "test the error flag"});
        emit({Op::cj, 4, 0, false, {}, "IF error"});
        break;
    }
  }

  // SEQ i = first FOR count: the control block's index and count.
  // A first index or count the PROC computes is evaluated into its word; a computed count is then
  // tested (oc: ldl count; mint; csub0 stops a negative one; cj jumps over the loop when it is 0).
  void loop_begin(std::size_t event_index) {
    OpenLoop l;
    l.depth = int(loops_.size());
    l.begin_event = event_index;
    l.shape = shapes_.at(event_index);
    const LoopBounds& bounds = r_.loop_bounds()[std::size_t(r_.events()[event_index].index)];
    l.known_bounds = !bounds.variable();
    const int control = frame_.loop_index(l.depth);
    const std::string name = "SEQ " + loop_index_name(l.depth);
    control_word(bounds.first, l.shape.first, control, name + ": first index");
    control_word(bounds.count, l.shape.count, control + 1, name + ": count");
    if (bounds.count >= 0) {
      emit({Op::ldl, control + 1, 0, false, workspace(), name + ": count"});
      if (target_.checked) {
        emit({Op::mint, 0, 0, false, {}, name + ": count not negative"});
        emit({Op::csub0, 0, 0, false, {}, name + ": count not negative"});
      }
      // Not run, the loop has no recorded code to jump over.
      const bool skip = l.shape.count == 0;
      const auto known = previous_.loop_bytes.find(event_index);
      const int over = skip || known == previous_.loop_bytes.end() ? 0 : known->second;
      emit({Op::cj, over, skip ? 1 : 0, false, {}, name + ": none"});
    }
    flow_.release_after(int(event_index), frame_);
    bodies_.back().flush(label(), l.shape.count);
    loops_.push_back(l);
    bodies_.push_back(Body{});
    started_iteration_.push_back(false);
  }

  // Ends the open iteration (if any) with its lend and starts the next.
  void iteration(bool last) {
    OpenLoop& l = loops_.back();
    if (started_iteration_.back()) {
      Body& b = bodies_.back();
      const int control = frame_.loop_index(l.depth);
      const bool looping = l.iteration + 1 < l.shape.count;
      emit({Op::ldlp, control, 0, false, {}, "SEQ " + loop_index_name(l.depth) + ": end"});
      // lend jumps back from its successor by A: the body so far, this ldc (whose length
      // depends on its own operand) and lend itself.
      const int lend_bytes = isa::encoded_bytes(Op::lend);
      std::int64_t back = b.static_bytes + lend_bytes + 1;
      while (b.static_bytes + isa::encoded_bytes(Op::ldc, back) + lend_bytes != back)
        back = b.static_bytes + isa::encoded_bytes(Op::ldc, back) + lend_bytes;
      emit({Op::ldc, back, 0, false, {}, "back to the body"});
      emit({Op::lend, 0, looping ? 1 : 0, false, workspace(), looping ? "loop" : "exit"});
      b.flush(label());
      l.max_footprint = std::max(l.max_footprint, b.footprint());
      l.last_static = b.static_bytes;
      close_iteration(l, std::move(b.runs));
      ++l.iteration;
      bodies_.back() = Body{};
    }
    started_iteration_.back() = !last;
  }

  void close_iteration(OpenLoop& l, std::vector<CodeRun> runs) {
    if (l.group_size > 0 && same_code(l.group, runs)) {
      ++l.group_size;
      return;
    }
    flush_group(l);
    l.group = std::move(runs);
    l.group_first = l.shape.first + l.iteration;
    l.group_size = 1;
  }

  // The group's runs go to the enclosing body, each run as often as the group has iterations.
  void flush_group(OpenLoop& l) {
    if (l.group_size == 0) return;
    Body& parent = bodies_[bodies_.size() - 2];
    const std::string range = "SEQ " + loop_index_name(l.depth) + " iterations " +
                              std::to_string(l.group_first) + ".." +
                              std::to_string(l.group_first + l.group_size - 1);
    for (CodeRun& run : l.group) {
      run.times *= l.group_size;
      if (l.group_size > 1) run.label += " (" + range + ")";
      parent.runs.push_back(std::move(run));
    }
    l.group.clear();
    l.group_size = 0;
  }

  void control_word(int node, std::int64_t constant, int word, const std::string& note) {
    if (node >= 0)
      integers_.evaluate(node);
    else
      emit({Op::ldc, constant, 0, false, {}, note});
    emit({Op::stl, word, 0, false, workspace(), note});
  }

  void loop_end() {
    iteration(true);
    OpenLoop& l = loops_.back();
    flush_group(l);
    const int loop_static = l.last_static, loop_footprint = l.max_footprint;
    loop_bytes_[l.begin_event] = loop_static;
    loops_.pop_back();
    bodies_.pop_back();
    started_iteration_.pop_back();
    // The enclosing body continues after the last iteration's lend (its back offset, if it is
    // an iteration itself, must reach over what that iteration's code is, CWG lend), while the
    // loop holds its largest iteration's code.
    bodies_.back().static_bytes += loop_static;
    bodies_.back().extra_bytes += loop_footprint - loop_static;
  }

  const Recording& r_;
  Target target_;
  Sizes previous_;
  std::vector<Subscript> subscripts_;
  std::map<std::size_t, LoopShape> shapes_;
  Frame frame_;
  Dataflow flow_;
  ExpressionEmitter expressions_;
  IntegerEmitter integers_;
  std::vector<Body> bodies_;
  std::vector<OpenLoop> loops_;
  std::vector<bool> started_iteration_;
  std::vector<const CodeUnit*> routines_;
  std::map<std::size_t, int> loop_bytes_;
};

}  // namespace

namespace {

void drop_notes(CodeUnit& unit) {
  for (CodeRun& run : unit.runs)
    for (isa::Instruction& in : run.code) in.note.clear();
}

}  // namespace

// Two passes: the first finds the code's and the frame's sizes, which the second writes into the
// operands that depend on them (ajw, the distance to the constant table after the code). Only the
// second pass's code is kept, so the first makes no notes.
CodeUnit generate(const Recording& recording, const Target& target) {
  Target sizing = target;
  sizing.notes = false;
  Generator first(recording, sizing, Sizes{});
  first.run();
  CodeUnit unit = Generator(recording, target, first.sizes()).run();
  if (!target.notes) drop_notes(unit);  // what is left of them (their fixed words)
  return unit;
}

std::int64_t CodeUnit::executed_instructions() const {
  std::int64_t n = 0;
  for (const CodeRun& run : runs) n += std::int64_t(run.code.size()) * run.times;
  return n;
}

}  // namespace t800::codegen
