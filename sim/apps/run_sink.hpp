// The run file as the runner's RunSink: frames, cycle ends and the step log are kept in memory
// and the whole file is rewritten atomically (PATH.tmp) at every checkpoint (run_file.hpp).
// It also measures what a benchmark reads from the file: the wall time of each stage, and the
// costs of contact handling and of its own writing (RunCosts).
#pragma once

#include "protocols/runner.hpp"
#include "sim/contact/contact_term.hpp"
#include "sim/integrate/integrator.hpp"
#include "sim/io/run_file.hpp"

#include <chrono>
#include <filesystem>

namespace crumple {

/// Where a run that failed numerically keeps its last checkpoint before the failure: beside the
/// checkpoint file TMP (RUN.h5.tmp), as TMP.before-failure.
inline std::string before_failure_path(const std::string& tmp) { return tmp + ".before-failure"; }

class FileSink : public RunSink {
 public:
  /// `contact`: the pairwise contact term whose stats() go into RunCosts (null: no contact). The
  /// costs a resumed record brought along are the base that this process's costs add to.
  FileSink(RunRecord& record, std::string tmp_path, Integrator& integ,
           const ContactTerm* contact = nullptr)
      : rec_(record),
        path_(std::move(tmp_path)),
        integ_(integ),
        contact_(contact),
        base_(record.costs.value_or(RunCosts{})),
        last_stage_end_(Clock::now()) {}

  void frame(const State& s, const std::string& stage, int cycle) override {
    const auto t0 = Clock::now();
    rec_.frames.push_back({s, stage, cycle, integ_.summary().steps()});
    output_s_ += since(t0);
  }
  /// The stage's wall time is the wall clock since the previous stage end (or, for the first
  /// stage of this process, since the sink was made: a resumed run counts from the resume), less
  /// the sink's own writing in between, so that stage walls and output_s add up to the run's.
  void stage_end(int cycle, int index, const Stage& stage, const State& s) override {
    const double wall = since(last_stage_end_) - (output_s_ - output_at_stage_end_);
    last_stage_end_ = Clock::now();
    output_at_stage_end_ = output_s_;
    rec_.stage_ends.push_back(
        {cycle, index, stage.type(), s.t, s.p, wall, stage.compaction(), stage.roll_axis_deg()});
  }
  void cycle_end(int cycle, const State& s) override {
    CycleRecord c;
    c.cycle = cycle;
    c.t = s.t;
    c.x = s.x;
    c.p = s.p;
    // From the stage ends the record holds, which a resumed run read back from its checkpoint
    // file: the stages of this cycle that ran before the resume count too.
    c.compaction = cycle_compaction(rec_.stage_ends, cycle);
    rec_.cycles.push_back(std::move(c));
  }
  /// A checkpoint's write is counted in the next write's output_s (a file cannot hold the time
  /// of its own writing).
  void checkpoint(const Checkpoint& c) override {
    const auto t0 = Clock::now();
    flush_log();
    rec_.checkpoint = save_restart(c);
    write_run_file_atomic(path_, rec_);
    output_s_ += since(t0);
  }
  /// The previous checkpoint file, if any, becomes before_failure_path(PATH), then the failing
  /// state is written to PATH as any checkpoint.
  void failure_checkpoint(const Checkpoint& c) override {
    std::error_code ec;
    if (std::filesystem::exists(path_, ec))
      std::filesystem::rename(path_, before_failure_path(path_), ec);
    checkpoint(c);
  }
  void flush_log() {
    rec_.log.insert(rec_.log.end(), integ_.log().begin(), integ_.log().end());
    integ_.clear_log();
    rec_.summary = integ_.summary();  // cumulative: a resumed integrator restores its counters
    rec_.costs = costs();
  }
  /// The last write of the run (to the tmp path). /log@output_s covers every write before it
  /// (a file cannot hold the time of its own writing; the last one is as long as a checkpoint's).
  void write_final() {
    flush_log();
    write_run_file_atomic(path_, rec_);
  }

 private:
  using Clock = std::chrono::steady_clock;
  static double since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
  }
  /// The costs so far: those of earlier processes (a resumed run) plus this one's.
  RunCosts costs() const {
    RunCosts c = base_;
    if (contact_) {
      const ContactStats& st = contact_->stats();
      c.contact_search_s += st.search_seconds;
      c.contact_eval_s += st.eval_seconds;
      c.contact_searches += static_cast<long>(st.searches);
    }
    c.output_s += output_s_;
    return c;
  }

  RunRecord& rec_;
  std::string path_;
  Integrator& integ_;
  const ContactTerm* contact_;
  RunCosts base_;
  double output_s_ = 0;            // this process's writing so far
  double output_at_stage_end_ = 0;  // output_s_ at the last stage end
  Clock::time_point last_stage_end_;
};

}  // namespace crumple
