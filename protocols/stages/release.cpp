// Stage `release`: with the walls gone, let the sheet relax until it is quiescent: the largest
// node acceleration max|F_i|/m falls below `threshold` x a_ref, a_ref = ks/(m lambda) the
// reference acceleration of the integrator's switching test (paper §3.4), and the fastest node
// moves slower than `speed` sheet sizes per second (an overdamped creep has tiny accelerations).
#include "protocols/stages/common.hpp"

#include <sstream>

namespace crumple::stages {
namespace {

class ReleaseStage : public Stage {
 public:
  explicit ReleaseStage(const StageArgs& a)
      : threshold_(a.number("threshold")), speed_(a.number("speed")),
        min_duration_(a.number("min_duration")) {
    apply_common(*this, a);
  }
  std::string type() const override { return "release"; }
  void begin(StageContext& ctx) override { t0_ = ctx.t_begin; }
  bool done(StageContext& ctx) override {
    if (ctx.state->t < t0_ + min_duration_) return false;
    return quiescent(ctx, threshold_, speed_, &last_ratio_, &last_speed_);
  }
  std::string progress(const StageContext&) const override {
    std::ostringstream os;
    os << "a_max/a_ref " << last_ratio_ << " -> " << threshold_ << ", speed " << last_speed_
       << " -> " << speed_ << " sizes/s";
    return os.str();
  }

 private:
  double threshold_, speed_, min_duration_, t0_ = 0, last_ratio_ = 1.0 / 0.0,
      last_speed_ = 1.0 / 0.0;
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
      {"speed", K::Number, "1e-3", "quiescent when every node is slower than this (sizes/s)",
       0.0, 1e30, true},
      {"min_duration", K::Number, "0.02", "relax at least this long (s)", 0.0},
  };
  for (auto& p : common_params(2.0, 0.01)) t.params.push_back(p);
  t.make = [](const StageArgs& a) { return std::make_unique<ReleaseStage>(a); };
  return t;
}

}  // namespace crumple::stages
