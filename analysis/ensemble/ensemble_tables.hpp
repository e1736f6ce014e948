// Pieces of the ensemble document (ensemble/ensemble.hpp) that group the runs' numbers other
// than by cycle: the per-stage table (where each cycle's new crease length was made) and the
// crease-threshold sensitivity table, plus the small JSON helpers the ensemble code shares.
// Internal to the analysis library.
#pragma once

#include "analysis/ensemble/ensemble.hpp"

#include <optional>
#include <string>
#include <vector>

namespace crumple::analysis::ensemble_detail {

/// obj[key] as a number; nullopt when obj is not an object, lacks the key, or holds null, a
/// string, a boolean or anything else that is not a number.
std::optional<double> number(const EnsembleJson& obj, const std::string& key);

/// A number or null.
EnsembleJson or_null(const std::optional<double>& v);

/// row[key_mean], row[key_std], row[key_sem] of the values (sample_stats); returns the stats.
SampleStats put(EnsembleJson& row, const std::string& key,
                const std::vector<std::optional<double>>& values);

/// The weights of the law fits: each point's seed-to-seed s.e.m. moderated toward the series'
/// root-mean-square s.e.m., s_i^2 -> (s_i^2 + mean_j s_j^2) / 2. A s.e.m. from three seeds
/// rests on a variance with two degrees of freedom and is sometimes small by chance (three
/// seeds whose increments happen to agree to 1 %), which would hand one point nearly all the
/// weight and pin the fit to it with errors far too small. Averaging each variance half and
/// half with the series' mean is a moderated variance (empirical-Bayes shrinkage with as many
/// prior degrees of freedom as the sample's); it keeps the ordering of the weights and bounds
/// any point's weight at twice that of a point with the mean variance.
std::vector<double> moderated_sems(const std::vector<double>& sems);

/// Per cycle and stage (index, type): the ensemble statistics of the stage's new, cumulative
/// and lost crease length, and of the cycle's share made after its last compress stage, over
/// the runs that have per-stage data. `runs`: the run records of ensemble.json ("cycles",
/// "has_stages").
EnsembleJson stage_table(const std::vector<EnsembleJson>& runs);

/// Per cycle and threshold (keyed by the factor of c0, or by the absolute threshold where the
/// factors are missing): the ensemble means and s.e.m. of l/L0, P and the facet count.
EnsembleJson sensitivity_table(const std::vector<EnsembleJson>& runs);

}  // namespace crumple::analysis::ensemble_detail
