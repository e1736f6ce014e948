// Times generate_mesh and prints the quality figures of the result, one line per mesh; not a
// test (timings depend on the machine). Usage: mesh_timing [shape nodes [iterations [seed]]]...
// e.g. `mesh_timing square 3000 square 12000 disk 48000`.
#include "sim/mesh/generate.hpp"
#include "sim/mesh/quality.hpp"

#include <chrono>
#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  using namespace crumple;
  std::vector<MeshSpec> specs;
  for (int a = 1; a + 1 < argc; a += 2) {
    MeshSpec s;
    s.shape = argv[a];
    s.nodes = std::stoi(argv[a + 1]);
    specs.push_back(s);
  }
  if (specs.empty())
    for (const char* shape : {"square", "disk"})
      for (int n : {3000, 12000, 48000}) specs.push_back({shape, 1.0, n});
  std::printf("%-7s %7s %7s %8s %9s %8s %9s %9s\n", "shape", "target", "nodes", "seconds",
              "min_angle", "edge_cv", "area_ratio", "idx_gap");
  for (const auto& s : specs) {
    const auto t0 = std::chrono::steady_clock::now();
    const Mesh m = generate_mesh(s);
    const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const MeshQuality q = mesh_quality(m);
    std::printf("%-7s %7d %7d %8.2f %9.2f %8.4f %9.3f %9.1f\n", s.shape.c_str(), s.nodes,
                q.nodes, sec, q.min_angle_deg, q.edge_cv, q.max_area / q.min_area,
                mean_index_gap(m));
  }
}
