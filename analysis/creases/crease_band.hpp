// Creases as folds summed across a band of the flat sheet (crumple-analyze --crease-width-mm).
//
// The default rule (crease_edges.hpp) counts a hinge as a crease when its own permanent fold
// angle exceeds the threshold. A finer mesh spreads one physical fold over two or three parallel
// rows of hinges, each with a part of the angle, so that rule loses the fold where it spreads
// (docs/SCIENCE.md, "The facets"). This rule sums the permanent fold angles
// theta = 2 asin(|p| / 2) of the hinges that run beside a hinge, within a band of width w centred
// on its edge in the flat reference sheet, and fold the same way as it (mountain or valley: the
// sign of p), and counts the hinge as a crease when that sum exceeds the threshold angle. A
// mountain fold beside a valley fold stays two folds, each on its own angle. "Beside" means: the other edge is
// within 30 degrees of parallel, its midpoint lies within w / 2 of this edge's line, and its
// projection onto that line falls within this edge. A fold carried by one row is a crease under
// both rules; a fold of angle A spread over k rows of A / k each is a crease on all k rows here
// (when they lie within the band) and on none by the default rule when A / k is below the
// threshold. Each row of such a band is drawn, so the crease map should be closed over the same
// width (crumple-analyze does so unless --close-mm is given) to draw the band as one crease.
#pragma once

#include "analysis/io/run_data.hpp"

#include <vector>

namespace crumple::analysis {

class CreaseBand {
 public:
  /// width in the mesh's length units (> 0).
  CreaseBand(const MeshData& mesh, double width);

  double width() const { return width_; }
  /// Hinges beside hinge h within the band (h itself included), ascending.
  const std::vector<int>& beside(std::size_t h) const { return beside_[h]; }
  /// 1 for each hinge whose fold angle summed over the hinges of the band that fold its way
  /// exceeds the threshold angle 2 asin(threshold / 2) (p and threshold in the model's curvature
  /// units 2 sin(theta / 2)).
  std::vector<char> creased(const std::vector<double>& p, double threshold) const;

 private:
  double width_;
  std::vector<std::vector<int>> beside_;
};

/// The creases of p at threshold: the band rule when band is given, else hinge by hinge.
std::vector<char> select_creases(const std::vector<double>& p, double threshold,
                                 const CreaseBand* band);

}  // namespace crumple::analysis
