// Meshes for the benchmarks: the simulator's own Lloyd-regularised, Hilbert-ordered meshes of a
// unit square with about `nodes` nodes.
#pragma once

#include "sim/mesh/generate.hpp"

namespace crumple {

inline Mesh bench_mesh(int nodes) {
  MeshSpec spec;
  spec.shape = "square";
  spec.size = 1.0;
  spec.nodes = nodes;
  spec.seed = 1;
  return generate_mesh(spec);
}

}  // namespace crumple
