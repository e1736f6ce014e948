// Cuts across the necks of crease-bounded regions: the marker watershed on the distance to the
// nearest crease that the experiments' automated facet segmentation uses (docs/STATISTICS.md §1,
// "Facet segmentation", option --watershed-h-px).
//
// A crease that yields along only part of its length leaves a gap, and plain connected
// components then merge the two facets on either side of it into one. The watershed puts the
// missing boundary back where the region pinches: every dome of the distance map higher than h
// above the saddle that joins it to another (an h-maximum) seeds a region, the regions are
// flooded from their tops down, and where two floods meet the pixels become a cut. A convex
// facet has a single dome and is left whole; h sets how deep a pinch must be to count.
#pragma once

#include <opencv2/core.hpp>

namespace crumple::analysis {

/// The h-maxima markers of `height` (CV_32F) as a CV_8U mask: the regional maxima of the
/// reconstruction by dilation of height - h under height, i.e. one plateau per dome that rises
/// more than h above the saddle joining it to a higher one (shallower domes join a neighbour's
/// plateau). h > 0.
cv::Mat h_maxima(const cv::Mat& height, double h);

/// Cut pixels (CV_8U, nonzero = cut) that split the nonzero pixels of `free` (CV_8U) at their
/// necks, from a marker watershed of the Euclidean distance to the nearest zero pixel with the
/// h-maxima of depth h_px as markers. The cuts are one pixel wide and separate the flooded
/// regions under 4-connectivity. Regions without a dome higher than h_px get no cuts.
cv::Mat watershed_neck_cuts(const cv::Mat& free, double h_px);

}  // namespace crumple::analysis
