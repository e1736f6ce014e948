// The protocol runner: cycles of stages driving a time stepper (docs/MODEL.md §11.1; issue 5).
//
// The runner owns no physics and no files. It builds each stage from its parameters, lets it add
// its terms, advances the stepper in chunks on a fixed time grid (the stage's check interval
// from its start, and the frame interval from t = 0), asks the stage whether it is done, and
// hands frames, cycle ends and checkpoints to a RunSink. Because chunk ends lie on a fixed grid
// and stages are rebuilt from the context at their start, a run resumed from a checkpoint takes
// exactly the steps of an uninterrupted one.
#pragma once

#include "protocols/checkpoint.hpp"
#include "protocols/registry.hpp"

#include <chrono>
#include <functional>
#include <map>

namespace crumple {

/// What the runner needs of a time integrator.
class Stepper {
 public:
  virtual ~Stepper() = default;
  /// Advances s to exactly t_end; throws NumericalFailure, leaving s at the last accepted step.
  virtual void advance_to(State& s, double t_end) = 0;
  /// Forget the multistep history (the forces changed discontinuously: a stage began or ended).
  virtual void restart() = 0;
  /// The stepper's history as numbers, for checkpoints, and its restoration.
  virtual std::vector<double> save() const = 0;
  virtual void restore(const std::vector<double>& data) = 0;
  /// Short status for the progress line (mode, step size) and the accepted step count.
  virtual std::string status() const = 0;
  virtual long steps() const = 0;
};

class RunSink {
 public:
  virtual ~RunSink() = default;
  virtual void frame(const State& s, const std::string& stage, int cycle) = 0;
  /// End of stage `index` (0-based) of cycle `cycle`, after the stage removed its terms; the
  /// stage says what it was (type()) and what it imposed (compaction()).
  virtual void stage_end(int /*cycle*/, int /*index*/, const Stage& /*stage*/,
                         const State& /*s*/) {}
  /// End of cycle `cycle` (after its last stage): the plastic field and geometry to keep.
  virtual void cycle_end(int cycle, const State& s) = 0;
  /// Persist everything so far together with the checkpoint (atomically).
  virtual void checkpoint(const Checkpoint& c) = 0;
  /// The checkpoint at a numerical failure: the state the failing step started from. A sink
  /// that keeps files keeps its previous checkpoint too (a resume from the failing state repeats
  /// the failure; one from before it can try other settings).
  virtual void failure_checkpoint(const Checkpoint& c) { checkpoint(c); }
};

struct RunnerSettings {
  int cycles = 1;
  double t_max = 1e30;            ///< cap on the simulated time of the whole run
  double frame_dt = 0.01;         ///< simulated time between frames
  double checkpoint_wall_s = 300; ///< wall seconds between checkpoints inside a stage
  double progress_wall_s = 2;     ///< wall seconds between progress lines
  bool quiet = false;
  /// Names the run on its progress lines (crumple-sim: the run file's folder and stem), so that
  /// runs side by side on one console can be told apart; empty: no name.
  std::string label;
  /// Progress lines overwrite each other in place (a terminal); stage ends stay. Otherwise
  /// every line is its own, every progress_wall_s.
  bool in_place = false;
  std::uint64_t seed = 1;
  /// Polled after every chunk of steps: a signal number asks the runner to write a checkpoint
  /// and throw Interrupted (sim/core/stop_signal.hpp); 0 goes on.
  std::function<int()> stop_requested = [] { return 0; };
};

class ProtocolRunner {
 public:
  /// make(k): the k-th stage of a cycle, freshly built.
  using StageFactory = std::function<std::unique_ptr<Stage>(int index)>;

  ProtocolRunner(SheetModel& model, Stepper& stepper, StageFactory make, int num_stages,
                 SheetInfo sheet, RunnerSettings settings);

  /// Self-contact switches used by stages (unfold); default: no contact.
  void set_contact_switch(std::function<void(bool)> set, std::function<bool()> get);

  /// Runs the protocol from the start or from a checkpoint. Returns false if it stopped at
  /// t_max before the last cycle ended. Throws NumericalFailure (after a checkpoint) with the
  /// stage, cycle and time in the message, and Interrupted (after a checkpoint) when
  /// settings.stop_requested() asks it to stop.
  bool run(State& s, RunSink& sink, const Checkpoint* resume = nullptr);
  /// Wall seconds spent in each stage type during run() (for the cycle benchmark).
  const std::map<std::string, double>& stage_wall() const { return stage_wall_; }

 private:
  /// What a stage began from: the state, the random generator and the contact switch (a
  /// checkpoint inside the stage rebuilds the stage from these).
  struct StageStart {
    State state;
    std::string rng;
    bool contact = true;
  };
  // The steps of run(), per stage: begin (fresh, or rebuilt from a checkpoint), advance in
  // chunks to its end, finish.
  StageStart begin_stage(Stage& stage, StageContext& ctx, State& s, const Checkpoint* resume);
  /// False when the run reached t_max inside the stage (after a checkpoint).
  bool advance_stage(Stage& stage, StageContext& ctx, State& s, RunSink& sink, int c, int k,
                     const StageStart& start);
  void finish_stage(Stage& stage, StageContext& ctx, State& s, RunSink& sink, int c, int k,
                    const StageStart& start);
  /// `ended`: the stage is over (whatever its own fraction says).
  void progress(const Stage& stage, const StageContext& ctx, int k, bool force, bool ended = false);
  /// Share of the whole run done: cycles and stages counted equal, a stage by its fraction.
  double share_done(const Stage& stage, const StageContext& ctx, int k, bool ended = false) const;
  /// Ends an in-place progress line before anything else is printed.
  void end_progress_line();
  bool run_cycles(State& s, RunSink& sink, const Checkpoint* resume, StageContext& ctx, int c0, int k0);
  Checkpoint make_checkpoint(const StageContext& ctx, int cycle, int stage, bool in_stage,
                             const State& stage_begin, const std::string& rng_begin,
                             bool contact_begin) const;

  SheetModel& model_;
  Stepper& stepper_;
  StageFactory make_;
  int num_stages_;
  SheetInfo sheet_;
  RunnerSettings cfg_;
  std::function<void(bool)> set_contact_ = [](bool) {};
  std::function<bool()> contact_on_ = [] { return false; };
  double next_frame_ = 0;
  // The stage and cycle running, for the final frame (the run's last state).
  std::string current_stage_;
  int current_cycle_ = 0;
  std::map<std::string, double> stage_wall_;
  std::chrono::steady_clock::time_point start_, last_progress_, stage_wall_start_,
      last_checkpoint_;
  double done_at_start_ = 0;  ///< share of the run done when this process started (a resume)
  bool line_open_ = false;    ///< an in-place progress line waits for its newline
};

/// mt19937_64 state as text and back (checkpoints).
std::string rng_state(const std::mt19937_64& rng);
void set_rng_state(std::mt19937_64& rng, const std::string& text);

}  // namespace crumple
