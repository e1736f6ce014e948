// The size of the next step towards the end of an advance_to interval (integrator.cpp).
//
// Callers advance in chunks (output frames, stage checks, progress lines), and each chunk end
// must be reached exactly. Clipping the step that would overshoot leaves a short last step,
// often a sliver of the controller's h, and variable-step BDF may then grow h back by at most
// bdf_growth_limit per step (1.22 at order 4): several extra steps after every chunk end
// (radial benchmark at 12000 nodes, 0.1 s all quasistatic advanced in ten chunks: 54 steps
// where one call took 30; 41 with the planned steps below).
// Instead, once the rest of the interval fits in a few steps, the steps onto it are planned:
// the fastest admissible sequence (the first step `first`, each next one growing by at most
// `growth` up to the controller's `proposal`) is scaled down until it ends exactly on the end.
// With growth 1 (or first = proposal) these are n equal steps, each at least (n - 1) / n of the
// controller's step; no step is a sliver, and no ratio of consecutive steps exceeds `growth`.
//
// `tol` is an absolute time: the rest is t_end - t, rounded to about an ulp of t, and a plan
// that fits within tol is taken as exact. (A tolerance relative to the rest is not enough at
// large t: an exact two-step fit then looked like three, the shortened last step held the next
// chunk's first step, and the steps shrank chunk after chunk.) It must stay a few ulps: a rest
// within tol of a step is taken whole, so a tolerance of many steps' size would make a retry
// after a rejection take the same step again (the integrator passes 0 on retries).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace crumple {

/// The rounding tolerance of t_end - t for times up to |t_end|: 16 ulps (a plan of up to four
/// steps, each landing t = t + h rounded, stays well inside it).
inline double landing_tolerance(double t_end) {
  return 16 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(t_end));
}

/// Step towards an end `remaining` ahead (> 0). `first` (<= `proposal`) is the largest
/// admissible next step, `proposal` the controller's step, `growth` (>= 1) the largest ratio of
/// consecutive steps, `tol` the absolute rounding tolerance of `remaining`. Returns the whole
/// rest if it fits in one step (at most first + tol); else, if it fits in n <= max_steps planned
/// steps, the first of them scaled so that the n end on it; else `first`.
inline double step_toward(double remaining, double first, double proposal, double growth,
                          double tol, int max_steps = 4) {
  if (remaining <= first + tol) return remaining;
  double planned = first, sum = first;
  for (int n = 1; n < max_steps; ++n) {
    planned = std::min(proposal, growth * planned);
    sum += planned;
    // A plan short of the end by rounding only takes `first`; the last step absorbs the rest.
    if (sum >= remaining - tol) return first * std::min(1.0, remaining / sum);
  }
  return first;
}

}  // namespace crumple
