// diag_intersections RUN.h5 [RUN.h5 ...]: counts, in every stored frame of a run file, the pairs
// of non-adjacent triangles that intersect (tests/support/self_intersection, CGAL's exact
// predicates), and prints per run and stage the frames checked, the frames with an intersection
// and the largest count. Exit 0 when no frame of any run has one, 1 otherwise, 2 on bad input.
// The check of the issue on crease statistics: no layer passes through another in any stage.
#include "sim/core/errors.hpp"
#include "sim/io/run_file.hpp"
#include "tests/support/self_intersection.hpp"

#include <cstdio>
#include <map>

int main(int argc, char** argv) {
  using namespace crumple;
  if (argc < 2) {
    std::fprintf(stderr, "usage: diag_intersections RUN.h5 [RUN.h5 ...]\n");
    return 2;
  }
  bool any = false;
  for (int a = 1; a < argc; ++a) {
    RunRecord r;
    try {
      r = read_run_file(argv[a]);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "diag_intersections: %s\n", e.what());
      return 2;
    }
    struct Tally {
      int frames = 0, bad = 0;
      std::size_t worst = 0;
    };
    std::map<std::string, Tally> by_stage;
    for (const FrameRecord& f : r.frames) {
      const std::size_t n = testing::count_self_intersections(r.mesh, f.state.x);
      Tally& t = by_stage[f.stage];
      ++t.frames;
      t.bad += n > 0;
      t.worst = std::max(t.worst, n);
      any = any || n > 0;
    }
    for (const auto& [stage, t] : by_stage)
      std::printf("%s  %-10s frames %4d  with intersections %4d  largest count %zu\n", argv[a],
                  stage.c_str(), t.frames, t.bad, t.worst);
  }
  return any ? 1 : 0;
}
