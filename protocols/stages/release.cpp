// Stage `release`: with the walls gone, let the sheet relax until it is quiescent: the largest
// node acceleration max|F_i|/m falls below `threshold` x a_ref, a_ref = ks/(m lambda) the
// reference acceleration of the integrator's switching test (paper §3.4), and the fastest node
// moves slower than `speed` sheet sizes per second (an overdamped creep has tiny accelerations),
// measured relative to the sheet's best-fit rigid motion: a released sheet may drift or spin
// slowly as a whole, which is no change of its shape; and the plastic field has stopped
// flowing (max |dp/dt| between two checks below `flow`). A free crumpled sheet keeps creeping
// open along its floppy modes for a very long time under drag (relaxation time b/k of the softest
// bending modes, hours of simulated time), and hinges held just past yield creep with it, so the
// defaults ask for a creep much slower than the loading (0.05 sizes/s against the piston's
// 1 size/s; plastic flow below 0.1 curvature units per second), not for rest: what must be over
// before the sheet is opened is the spring-back and the fast plastic flow.
#include "protocols/stages/common.hpp"

#include <sstream>

namespace crumple::stages {
namespace {

class ReleaseStage : public Stage {
 public:
  explicit ReleaseStage(const StageArgs& a)
      : threshold_(a.number("threshold")), speed_(a.number("speed")),
        flow_(a.number("flow")), min_duration_(a.number("min_duration")) {
    apply_common(*this, a);
  }
  std::string type() const override { return "release"; }
  void begin(StageContext& ctx) override { t0_ = ctx.t_begin; }
  // The flow rate compares p with the previous check; after a resume the replayed check only
  // records p, as the uninterrupted run's check at that time (which returned false) did.
  bool done(StageContext& ctx) override {
    const State& s = *ctx.state;
    const bool have_prev = prev_p_.size() == s.p.size() && s.t > prev_t_;
    last_flow_ = have_prev ? (s.p - prev_p_).cwiseAbs().maxCoeff() / (s.t - prev_t_) : 1.0 / 0.0;
    if (s.p.size() == 0) last_flow_ = 0;
    prev_p_ = s.p;
    prev_t_ = s.t;
    if (s.t < t0_ + min_duration_) return false;
    const bool still = quiescent(ctx, threshold_, speed_, &last_ratio_, &last_speed_);
    return still && last_flow_ < flow_;
  }
  std::string progress(const StageContext&) const override {
    std::ostringstream os;
    os << "a_max/a_ref " << last_ratio_ << " -> " << threshold_ << ", speed " << last_speed_
       << " -> " << speed_ << " sizes/s, max|dp/dt| " << last_flow_ << " -> " << flow_ << " /s";
    return os.str();
  }

 private:
  double threshold_, speed_, flow_, min_duration_, t0_ = 0, last_ratio_ = 1.0 / 0.0,
      last_speed_ = 1.0 / 0.0, last_flow_ = 1.0 / 0.0, prev_t_ = -1.0 / 0.0;
  VecX prev_p_;
};

}  // namespace

StageType release_stage_type() {
  using K = ParamSpec::Kind;
  StageType t;
  t.name = "release";
  t.help = "relax the free sheet until it is quiescent";
  t.params = {
      {"threshold", K::Number, "1e-6", "quiescent when max|F|/m < threshold x ks/(m lambda)", 0.0,
       1e30, true},
      {"speed", K::Number, "0.05",
       "... every node is slower than this relative to the rigid motion (sizes/s)", 0.0, 1e30,
       true},
      {"flow", K::Number, "0.1", "... and the plastic field flows slower than this (1/s)", 0.0,
       1e30, true},
      {"min_duration", K::Number, "0.02", "relax at least this long (s)", 0.0},
  };
  for (auto& p : common_params(2.0, 0.01)) t.params.push_back(p);
  t.make = [](const StageArgs& a) { return std::make_unique<ReleaseStage>(a); };
  t.check = [](const StageArgs& a) {
    if (a.number("min_duration") > a.number("max_duration"))
      a.fail_both("min_duration", "max_duration", "min_duration must not exceed max_duration");
  };
  return t;
}
CRUMPLE_REGISTER_STAGE(release_stage_type);

}  // namespace crumple::stages
