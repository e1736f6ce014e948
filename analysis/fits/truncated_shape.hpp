// The fragmentation-model facet-area law cut at the mesh's resolution floor (docs/STATISTICS.md
// §3.7, "resolution floor": fit a phi truncated on the left). A mesh cannot make facets much
// smaller than a few of its triangles, so the small-area end of the distribution, and with it
// the one-parameter fit of a (fits/facet_shape.hpp) and its KS test, measure the mesh there.
// Here only the facets at or above the floor x_min enter, and the law is fitted with its scale
// free, because the mean of the untruncated law is no longer the mean of the data:
//   sqrt(x) ~ Gamma(a, theta),  theta = sqrt(s / (a(a+1))),  conditioned on x >= x_min,
// where s is the law's mean area (the phi of docs/STATISTICS.md §3.3 with xi = x / s). The
// likelihood of y = sqrt(x) is
//   ln L = (a-1) sum ln y - sum y / theta - n [a ln theta + ln Gamma(a) + ln Q(a, y_min / theta)],
// maximised over (ln a, ln theta) by nested one-dimensional searches (fits/minimize_1d.hpp).
// The fitted (a, s) is compared with the universal curve at that s, a_univ(s).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace crumple::analysis {

/// Where a fit stopped on the edge of its search instead of at an interior maximum.
/// a_min: the facets above the floor fall off more steeply than any member of the family with
/// a > 0 allows (the likelihood still rises towards a = 0; the family has no member there).
/// a_max: the law would be narrower than a = kTruncAMax. theta: the scale's search range.
enum class FitEdge { none, a_min, a_max, theta };

/// "a_min", "a_max", "theta", or "" for none.
const char* fit_edge_name(FitEdge e);

struct TruncatedShapeFit {
  double a = 0;        ///< shape of the untruncated law
  double mean_x = 0;   ///< its mean area s (same units as x)
  double x_min = 0;    ///< the floor the law was cut at
  std::size_t n = 0;   ///< areas at or above the floor
  double loglik = 0;   ///< ln L at the optimum (y = sqrt x, constants dropped)
  /// The law's share of facets below the floor, P(a, y_min / theta): what the fitted law says
  /// the mesh could not make.
  double share_below = 0;
  FitEdge edge = FitEdge::none;  ///< on an edge of the search: (a, mean_x) are not estimates
};

/// Searched ranges: a in [kTruncAMin, kTruncAMax]; ln theta from below both the untruncated
/// estimate ln(mean(y) / a) - 6 and the tail's ln((mean(y) - y_min) / (a + 1)) - 3 up to the
/// former + 6.
inline constexpr double kTruncAMin = 0.02, kTruncAMax = 50.0;

/// Maximum-likelihood (a, s) of the areas x >= x_min (others are ignored). Throws
/// std::invalid_argument when fewer than 5 areas lie at or above x_min or x_min <= 0, and
/// std::runtime_error when no (a, theta) in range gives the data a finite likelihood.
TruncatedShapeFit fit_truncated_shape(const std::vector<double>& x, double x_min);

/// CDF of the truncated law at x: (Q(a, y_min/theta) - Q(a, y/theta)) / Q(a, y_min/theta).
double truncated_cdf(double x, const TruncatedShapeFit& fit);

/// KS distance between the areas at or above the floor and the truncated law.
double truncated_ks_distance(const std::vector<double>& x, const TruncatedShapeFit& fit);

/// n areas drawn from the truncated law: by rejection from the untruncated law where it keeps at
/// least 5 % of its mass above the floor, else by inverting the cut CDF (bisection on ln Q).
std::vector<double> sample_truncated(std::size_t n, const TruncatedShapeFit& fit,
                                     std::uint64_t seed);

/// Parametric-bootstrap p-value of the KS distance d_obs: samples of fit.n areas from the fitted
/// truncated law, each refitted (a and s) at the same floor, counted as (1 + hits) / (1 +
/// resamples), as ks_pvalue_parametric (fits/shape_bootstrap.hpp). Resample b draws from a
/// generator seeded by a hash of (seed, b), so that nearby seeds share no resamples. At an edge
/// of the search the fitted law is the edge's and the test approximate (the refits of the
/// resamples land on the edge only in part).
double truncated_ks_pvalue(const TruncatedShapeFit& fit, double d_obs, int resamples,
                           std::uint64_t seed);

}  // namespace crumple::analysis
