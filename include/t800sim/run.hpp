// Running a scene from a program's own executable, without t800sim's command line: what
// `t800sim run SCENE --json` does, in this process. Link t800sim::run (find_package(t800sim)).
//
//   int sc_main(int argc, char* argv[]) {   // libsystemc.so provides main() and calls sc_main()
//     const t800sim::SceneRun r = t800sim::run_scene(argv[1]);
//     std::cout << r.report_json;
//     return r.exit_code;
//   }
//
// Programs the executable registers itself (T800SIM_WORKLOAD in its own sources) are available to
// its scenes, as are the built-in kinds. SystemC runs one simulation per process: call it once.
#pragma once

#include <string>
#include <vector>

namespace t800sim {

struct SceneRun {
  // As `t800sim run`: 0 ran, 1 deadlocked, 2 bad input (nothing ran), 3 results are not results,
  // 4 a limit stopped it.
  int exit_code = 0;
  std::string report_json;  // the report (`t800sim run --json`); empty when nothing ran
  std::string error;        // why exit_code is not 0 ("scene.toml:4:1: error: ...")
};

// overrides: "KEY=VALUE" as `--set` takes them ("workload.loops=1000").
SceneRun run_scene(const std::string& scene_file, const std::vector<std::string>& overrides = {});

}  // namespace t800sim

// The executable's entry point: libsystemc.so provides main() and calls sc_main (declared here as
// SystemC declares it, so that a definition without SystemC's headers links).
extern "C" int sc_main(int argc, char* argv[]);
