// The run file (docs/FILE_FORMAT.md): everything a run produced, kept in memory and written as
// a whole to PATH.tmp.new, then renamed to PATH.tmp, at every checkpoint; renamed to PATH only
// when the run is complete. A killed run therefore leaves a consistent PATH.tmp to resume from
// and never a file under the final name.
#pragma once

#include "sim/integrate/step_log.hpp"
#include "sim/mesh/mesh.hpp"
#include "sim/model/restart_data.hpp"

#include <limits>
#include <optional>

namespace crumple {

struct RunMeta {
  std::string program_version, git_revision, start_time, end_time, status = "running";
  std::uint64_t seed = 0;
  int threads = 1;
  double ks = 0, kb = 0, mass = 0, h_eff = 0, length_unit_m = 1.0;
  /// material.mass_scale: the node masses' factor, which slows the simulated clock's inertia
  /// (docs/MODEL.md §8); NaN in files written before it was stored.
  double mass_scale = std::numeric_limits<double>::quiet_NaN();
  /// |p| above which the `crease` masks mark a hinge (crease_threshold in sim/model/crease_rule.hpp:
  /// the config's output.crease_angle, else kCreaseThresholdFactor c0); NaN in files
  /// written before the masks were stored.
  double crease_threshold = std::numeric_limits<double>::quiet_NaN();
};

struct FrameRecord {
  State state;
  std::string stage;
  int cycle = 0;
  long step = 0;
};

struct CycleRecord {
  int cycle = 0;
  double t = 0;
  VecX x, p;  ///< which hinges count as creased is the analysis's call (analysis/README.md)
  /// The compaction ratio the cycle's compacting stage imposed (cycle_compaction()); NaN when no
  /// stage of the cycle compacts the sheet, and in files written before it was recorded.
  double compaction = std::numeric_limits<double>::quiet_NaN();
};

/// The plastic field at the end of one stage of one cycle (per-stage crease accounting).
struct StageEndRecord {
  int cycle = 0;        ///< 1-based
  int stage_index = 0;  ///< 0-based position of the stage in the cycle
  std::string stage;    ///< stage type
  double t = 0;
  VecX p;
  /// Wall seconds of the stage, less the run-file writing in it (FileSink::stage_end); NaN in
  /// files written before it was stored.
  double wall = std::numeric_limits<double>::quiet_NaN();
  /// The compaction ratio the stage imposed (Stage::compaction()); absent for stages that do
  /// not compact the sheet and in files written before it was recorded.
  std::optional<double> compaction;
  /// The axis the stage rolled the sheet about (Stage::roll_axis_deg()), degrees in [0, 180);
  /// absent for stages that do not roll it and in files written before it was recorded.
  std::optional<double> roll_axis_deg;
};

/// The compaction ratio of cycle `cycle` from its stage ends: the smallest (the strongest
/// compaction) among the stages of the cycle that report one, or NaN when none does. A run's
/// compress stages all measure the gap against the height of the same roll, so the smallest
/// ratio is how far the sheet was compacted in the cycle.
double cycle_compaction(const std::vector<StageEndRecord>& stage_ends, int cycle);

/// What a run spent outside the integrator's own counters, for benchmarks (attributes of /log):
/// contact handling, from ContactTerm::stats() of the pairwise contact term, and the writing of
/// the run file. Summed over resumes like the integrator's counters.
struct RunCosts {
  double contact_search_s = 0;  ///< wall s in candidate-pair searches
  double contact_eval_s = 0;    ///< wall s evaluating contact energy, force and Jacobian
  long contact_searches = 0;    ///< searches run
  double output_s = 0;          ///< wall s in the FileSink: frames, checkpoints, the final write
};

/// A resume of the run (--resume): when, on how many threads, and the configuration keys it
/// changed ("integrator.h_min: 1e-08 -> 1e-10"; sim/apps/resume.hpp lists those that may).
struct ResumeRecord {
  double t = 0;        ///< simulated time the changes took effect
  std::string time;    ///< UTC wall-clock time of the resume
  int threads = 1;
  std::vector<std::string> changes;
  /// The program that ran the run up to here (version and git revision; /meta names the last
  /// piece's); empty in files written before it was recorded.
  std::string program_before;
};

struct RunRecord {
  RunMeta meta;
  std::string config;  ///< resolved YAML
  Mesh mesh;
  std::vector<FrameRecord> frames;
  std::vector<CycleRecord> cycles;
  std::vector<StageEndRecord> stage_ends;  ///< absent (empty) in older files
  std::vector<LogRow> log;
  /// The integrator's counters over the whole run (attributes of /log); absent in files
  /// written before they were stored.
  std::optional<IntegratorSummary> summary;
  std::optional<RunCosts> costs;  ///< absent in files written before they were stored
  /// The restart entries of an unfinished run (/checkpoint), as the parts that own them wrote
  /// them (protocols/checkpoint.hpp); the file only checks each state against the mesh.
  std::optional<RestartData> checkpoint;
  std::vector<ResumeRecord> resumes;  ///< absent (empty) in older files and unresumed runs
};

/// Writes the whole record to `path` (overwriting). Throws OutputError naming the path when the
/// file cannot be written (missing directory, permissions, a full disk).
void write_run_file(const std::string& path, const RunRecord& r);
/// Reads a run file back (resume, tests). Throws InputError naming the file, and the dataset
/// where one is at fault (a shape, an index out of range, a non-finite value), on any problem.
RunRecord read_run_file(const std::string& path);
/// Writes PATH atomically: to PATH.new, then renamed. On failure PATH.new is removed and PATH
/// is left as it was.
void write_run_file_atomic(const std::string& path, const RunRecord& r);
/// Renames `from` to `to` or throws OutputError (removing `from`).
void rename_or_throw(const std::string& from, const std::string& to);
/// A group's name in the file: `k` zero-padded to `width` digits (/frames/000012, /cycles/0003).
std::string numbered(long k, int width);

}  // namespace crumple
