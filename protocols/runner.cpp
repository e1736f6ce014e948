// The protocol runner (runner.hpp).
#include "protocols/runner.hpp"

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <iomanip>
#include <sstream>

namespace crumple {

std::string rng_state(const std::mt19937_64& rng) {
  std::ostringstream os;
  os << rng;
  return os.str();
}

void set_rng_state(std::mt19937_64& rng, const std::string& text) {
  std::istringstream is(text);
  is >> rng;
  if (!is) throw InputError("checkpoint: corrupt random-number state");
}

namespace {
std::string stopped_message(int signo, const Stage& stage, int cycle, double t) {
  std::ostringstream os;
  os << "stopped by signal " << signo << (signo == SIGTERM ? " (SIGTERM)" : signo == SIGINT ? " (SIGINT)" : "")
     << " in stage " << stage.type() << " (cycle " << cycle << "), t = " << t << " s";
  return os.str();
}
}  // namespace

ProtocolRunner::ProtocolRunner(SheetModel& model, Stepper& stepper, StageFactory make,
                               int num_stages, SheetInfo sheet, RunnerSettings settings)
    : model_(model), stepper_(stepper), make_(std::move(make)), num_stages_(num_stages),
      sheet_(sheet), cfg_(settings) {}

void ProtocolRunner::set_contact_switch(std::function<void(bool)> set, std::function<bool()> get) {
  set_contact_ = std::move(set);
  contact_on_ = std::move(get);
}

Checkpoint ProtocolRunner::make_checkpoint(const StageContext& ctx, int cycle, int stage,
                                           bool in_stage, const State& stage_begin,
                                           const std::string& rng_begin,
                                           bool contact_begin) const {
  Checkpoint c;
  c.cycle = cycle;
  c.stage = stage;
  c.in_stage = in_stage;
  c.stage_t_begin = ctx.t_begin;
  if (in_stage) c.stage_begin = stage_begin;
  c.rng_at_stage_begin = in_stage ? rng_begin : rng_state(ctx.rng);
  c.contact_at_stage_begin = in_stage ? contact_begin : contact_on_();
  c.apparatus = ctx.apparatus;
  c.state = *ctx.state;
  c.stepper = stepper_.save();
  c.next_frame_t = next_frame_;
  return c;
}

namespace {
/// "42 s", "7 min", "2.3 h": an ETA a reader takes in at a glance.
std::string rough_duration(double s) {
  std::ostringstream os;
  if (s < 100)
    os << static_cast<long>(s) << " s";
  else if (s < 6000)
    os << static_cast<long>(s / 60 + 0.5) << " min";
  else
    os << std::fixed << std::setprecision(1) << s / 3600 << " h";
  return os.str();
}
}  // namespace

double ProtocolRunner::share_done(const Stage& stage, const StageContext& ctx, int k,
                                  bool ended) const {
  const double f = ended ? 1.0 : std::clamp(stage.fraction(ctx), 0.0, 1.0);
  return std::clamp(((ctx.cycle - 1) + (k + f) / num_stages_) / cfg_.cycles, 0.0, 1.0);
}

void ProtocolRunner::end_progress_line() {
  if (line_open_) std::fputc('\n', stderr);
  line_open_ = false;
}

void ProtocolRunner::progress(const Stage& stage, const StageContext& ctx, int k, bool force,
                              bool ended) {
  if (cfg_.quiet) return;
  const auto now = std::chrono::steady_clock::now();
  if (!force && std::chrono::duration<double>(now - last_progress_).count() < cfg_.progress_wall_s)
    return;
  last_progress_ = now;
  const double wall = std::chrono::duration<double>(now - start_).count();
  const double stage_wall = std::chrono::duration<double>(now - stage_wall_start_).count();
  std::ostringstream os;
  if (!cfg_.label.empty()) os << cfg_.label << ": ";
  // The whole run: share done (stages counted equal, each by its own fraction where it has
  // one) and the wall still to go at this process's pace.
  const double done = share_done(stage, ctx, k, ended);
  os << static_cast<int>(100 * done) << " %";
  if (done - done_at_start_ > 0.005 && done < 1)
    os << " ETA " << rough_duration(wall * (1 - done) / (done - done_at_start_));
  os << " | cycle " << ctx.cycle << "/" << cfg_.cycles << "  stage " << k + 1 << "/" << num_stages_
     << " " << stage.type() << "  t=" << ctx.state->t << " s";
  const std::string p = stage.progress(ctx);
  if (!p.empty()) os << "  [" << p << "]";
  os << "  " << stepper_.status() << "  " << static_cast<long>(stepper_.steps() / std::max(wall, 1e-9))
     << " steps/s";
  const double f = stage.fraction(ctx);
  if (f > 0.01 && f < 1.0) os << "  stage ETA " << static_cast<long>(stage_wall * (1 - f) / f) << " s";
  os << "  wall " << static_cast<long>(wall) << " s";
  if (cfg_.in_place) {
    // Carriage return and clear to the end of the line: the next line takes this one's place.
    std::fprintf(stderr, "\r\033[K%s%s", os.str().c_str(), force ? "\n" : "");
    line_open_ = !force;
  } else {
    std::fprintf(stderr, "%s\n", os.str().c_str());
  }
  std::fflush(stderr);
}

namespace {
constexpr double kEps = 1e-12;  // simulated-time slack of the stage and frame boundaries
}  // namespace

// `resume` is the checkpoint when this stage is the one it was taken in (or before).
ProtocolRunner::StageStart ProtocolRunner::begin_stage(Stage& stage, StageContext& ctx, State& s,
                                                       const Checkpoint* resume) {
  StageStart start;
  stage_wall_start_ = std::chrono::steady_clock::now();
  if (resume && resume->in_stage) {
    // Rebuild the stage exactly as it was built, then return to the checkpointed state.
    set_rng_state(ctx.rng, resume->rng_at_stage_begin);
    set_contact_(resume->contact_at_stage_begin);
    start = {resume->stage_begin, resume->rng_at_stage_begin, resume->contact_at_stage_begin};
    s = start.state;
    ctx.t_begin = resume->stage_t_begin;
    stage.begin(ctx);
    s = resume->state;
    stage.done(ctx);  // replays the last check: stage-internal phases as they were
    model_.rebuild_pattern();
    stepper_.restore(resume->stepper);
    return start;
  }
  if (resume) {  // taken at this stage's start
    set_rng_state(ctx.rng, resume->rng_at_stage_begin);
    set_contact_(resume->contact_at_stage_begin);
    s = resume->state;
    stepper_.restore(resume->stepper);
  }
  start = {s, rng_state(ctx.rng), contact_on_()};
  ctx.t_begin = s.t;
  stage.begin(ctx);
  model_.rebuild_pattern();
  stepper_.restart();
  return start;
}

// Chunks end on the fixed grid of checks and frames (and at t_max and max_duration), so a run
// resumed from a checkpoint takes the steps the uninterrupted one takes.
bool ProtocolRunner::advance_stage(Stage& stage, StageContext& ctx, State& s, RunSink& sink,
                                   int c, int k, const StageStart& start) {
  const auto checkpoint_here = [&] {
    return make_checkpoint(ctx, c, k, true, start.state, start.rng, start.contact);
  };
  for (;;) {
    if (s.t >= cfg_.t_max - kEps) {
      stage.end(ctx);
      stage_wall_[stage.type()] += std::chrono::duration<double>(
          std::chrono::steady_clock::now() - stage_wall_start_).count();
      if (!cfg_.quiet) std::fprintf(stderr, "stopped at t_max = %g s\n", cfg_.t_max);
      sink.checkpoint(make_checkpoint(ctx, c, k, false, s, start.rng, start.contact));
      return false;
    }
    const double ci = stage.check_interval;
    const double since = s.t - ctx.t_begin;
    const double next_check = ctx.t_begin + (std::floor(since / ci + 1e-9) + 1.0) * ci;
    const double t_end =
        std::min({next_check, next_frame_, cfg_.t_max, ctx.t_begin + stage.max_duration});
    try {
      stepper_.advance_to(s, t_end);
    } catch (const NumericalFailure& e) {
      sink.failure_checkpoint(checkpoint_here());
      std::ostringstream os;
      os << "stage " << stage.type() << " (cycle " << c << ", stage " << k + 1 << "), t = " << s.t
         << " s: " << e.what();
      throw NumericalFailure(os.str());
    }
    if (s.t >= next_frame_ - kEps) {
      sink.frame(s, stage.type(), c);
      next_frame_ += cfg_.frame_dt;
    }
    bool finished = stage.done(ctx);
    progress(stage, ctx, k, false);
    if (!finished && s.t >= ctx.t_begin + stage.max_duration - kEps) {
      end_progress_line();
      if (!cfg_.quiet)
        std::fprintf(stderr, "warning: stage %s (cycle %d) reached max_duration %g s before "
                             "its target [%s]\n",
                     stage.type().c_str(), c, stage.max_duration, stage.progress(ctx).c_str());
      finished = true;
    }
    if (finished) return true;
    const auto now = std::chrono::steady_clock::now();
    const int stop = cfg_.stop_requested();
    if (stop || std::chrono::duration<double>(now - last_checkpoint_).count() >=
                    cfg_.checkpoint_wall_s) {
      sink.checkpoint(checkpoint_here());
      last_checkpoint_ = now;
    }
    if (stop) throw Interrupted(stop, stopped_message(stop, stage, c, s.t));
  }
}

void ProtocolRunner::finish_stage(Stage& stage, StageContext& ctx, State& s, RunSink& sink,
                                  int c, int k, const StageStart& start) {
  stage.end(ctx);
  progress(stage, ctx, k, true, true);
  stage_wall_[stage.type()] +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - stage_wall_start_).count();
  stepper_.restart();
  sink.stage_end(c, k, stage, s);
  if (k + 1 == num_stages_) {
    sink.cycle_end(c, s);
    ctx.cycle = c + 1;
    sink.checkpoint(make_checkpoint(ctx, c + 1, 0, false, s, start.rng, start.contact));
  } else {
    sink.checkpoint(make_checkpoint(ctx, c, k + 1, false, s, start.rng, start.contact));
  }
  last_checkpoint_ = std::chrono::steady_clock::now();
}

bool ProtocolRunner::run(State& s, RunSink& sink, const Checkpoint* resume) {
  start_ = last_progress_ = stage_wall_start_ = last_checkpoint_ = std::chrono::steady_clock::now();
  StageContext ctx;
  ctx.model = &model_;
  ctx.state = &s;
  ctx.sheet = sheet_;
  ctx.rng.seed(cfg_.seed);
  ctx.set_contact = set_contact_;

  int c0 = 1, k0 = 0;
  if (resume) {
    c0 = resume->cycle;
    k0 = resume->stage;
    ctx.apparatus = resume->apparatus;
    next_frame_ = resume->next_frame_t;
  } else {
    next_frame_ = s.t;
    if (s.t >= next_frame_) {
      sink.frame(s, "initial", 0);
      next_frame_ += cfg_.frame_dt;
    }
  }
  try {
    const bool complete = run_cycles(s, sink, resume, ctx, c0, k0);
    // The run's last state is its last frame (a viewer's last time step is the end of the run),
    // unless a frame on the frame grid already fell on it.
    if (!current_stage_.empty() && s.t > next_frame_ - cfg_.frame_dt + kEps)
      sink.frame(s, current_stage_, current_cycle_);
    end_progress_line();
    return complete;
  } catch (...) {
    end_progress_line();  // the failure's message starts on a line of its own
    throw;
  }
}

bool ProtocolRunner::run_cycles(State& s, RunSink& sink, const Checkpoint* resume,
                                StageContext& ctx, int c0, int k0) {
  for (int c = c0; c <= cfg_.cycles; ++c) {
    ctx.cycle = c;
    if (!(resume && c == c0)) ctx.apparatus = Apparatus{};
    for (int k = (c == c0 ? k0 : 0); k < num_stages_; ++k) {
      std::unique_ptr<Stage> stage = make_(k);
      const bool resumed_here = resume && c == c0 && k == k0;
      const StageStart start = begin_stage(*stage, ctx, s, resumed_here ? resume : nullptr);
      if (c == c0 && k == k0) done_at_start_ = share_done(*stage, ctx, k);
      current_stage_ = stage->type();
      current_cycle_ = c;
      progress(*stage, ctx, k, true);
      if (!advance_stage(*stage, ctx, s, sink, c, k, start)) return false;
      finish_stage(*stage, ctx, s, sink, c, k, start);
      const bool last = c == cfg_.cycles && k + 1 == num_stages_;
      if (const int stop = cfg_.stop_requested(); stop && !last)
        throw Interrupted(stop, stopped_message(stop, *stage, c, s.t));
    }
  }
  return true;
}

}  // namespace crumple
