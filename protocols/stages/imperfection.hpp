// A smooth random out-of-plane imperfection of a flat sheet.
//
// A perfectly flat sheet under in-plane load never leaves its plane, so stages that compress a
// flat sheet seed a small normal displacement first. It must be smooth on the mesh scale:
// node-wise white noise stores bending energy ~ kb (amplitude / edge)^2 per hinge that is
// released within a few spring periods, a violent start (kinetic energies of the order of the
// whole loading's work were measured with it) that forces the integrator into the explicit mode
// at once. Real sheets have long-wavelength imperfections, so the field here is a sum of
// random plane waves w(X) = sum_k a_k cos(q_k . X + phi_k) over the flat reference positions X,
// with wavelengths between `shortest` and `longest`, scaled to the requested RMS over the nodes.
#pragma once

#include "sim/core/types.hpp"
#include "sim/mesh/mesh.hpp"

#include <random>

namespace crumple::stages {

struct ImperfectionSpec {
  double rms = 0;       ///< RMS normal displacement over the nodes [m]
  double shortest = 0;  ///< shortest wavelength [m]
  double longest = 0;   ///< longest wavelength [m]
  int modes = 16;       ///< number of plane waves
};

/// Normal (z) displacements, one per node, drawn from `rng`; all zero if spec.rms == 0.
VecX smooth_imperfection(const Mesh& mesh, const ImperfectionSpec& spec, std::mt19937_64& rng);

}  // namespace crumple::stages
