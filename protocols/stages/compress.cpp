// Stage `compress`: axial compression of the rolled sheet between two pistons inside a
// cylindrical container, to a target compaction ratio (the experiment's knob:
// compaction = final / initial piston gap, docs/STATISTICS.md §1).
//
// The container is a cylinder wall (allowed inside) about the roll's axis. It starts just outside
// the sheet's current radial extent and closes to (1 + clearance) times the roll radius over
// `close_time`, so the rolled sheet is caught before it can spring open. The pistons are plane
// walls normal to the axis, starting just beyond the sheet's ends (gap H0 = the roll's height)
// and each moving inwards at speed/2 until their gap is compaction * H0; the stage then holds
// for `hold` seconds.
#include "protocols/stages/common.hpp"
#include "protocols/terms/wall_term.hpp"

#include <cmath>
#include <algorithm>
#include <sstream>

namespace crumple::stages {
namespace {

class CompressStage : public Stage {
 public:
  explicit CompressStage(const StageArgs& a)
      : compaction_(a.number("compaction")),
        speed_(a.number("speed")),
        clearance_(a.number("clearance")),
        close_time_(a.number("close_time")),
        stiffness_(a.number("stiffness")),
        range_(a.number("range")),
        hold_(a.number("hold")) {
    apply_common(*this, a);
  }
  std::string type() const override { return "compress"; }

  void begin(StageContext& ctx) override {
    const Apparatus& ap = ctx.apparatus;
    if (!ap.rolled)
      throw InputError("protocol: a compress stage needs a roll stage before it in the cycle");
    const Vec3 a = ap.axis_dir, c = ap.axis_point;
    const double range = range_ * ctx.sheet.h_eff;
    const double k = stiffness_ * ctx.sheet.ks / range;  // force k range^2 = stiffness ks range
    double wmin = 1e300, wmax = -1e300, rmax = 0;
    for (Index i = 0; i < ctx.model->num_nodes(); ++i) {
      const Vec3 r = node(ctx.state->x, i) - c;
      const double w = r.dot(a);
      wmin = std::min(wmin, w), wmax = std::max(wmax, w);
      rmax = std::max(rmax, (r - w * a).norm());
    }
    h0_ = ap.height;
    const double r_final = ap.radius * (1.0 + clearance_);
    const double r_start = std::max(rmax + range, r_final);
    const double rate = close_time_ > 0 ? (r_start - r_final) / close_time_ : 0.0;
    t0_ = ctx.t_begin;
    container_ = std::make_shared<CylinderWall>(
        c, a, LinearMotion{r_start, -rate, t0_, r_final}, true);
    const double lo = std::min(wmin - range, -0.5 * h0_), hi = std::max(wmax + range, 0.5 * h0_);
    const double half = 0.5 * compaction_ * h0_;
    bottom_ = std::make_shared<PlaneWall>(c + lo * a, a,
                                          LinearMotion{0.0, 0.5 * speed_, t0_, -half - lo});
    top_ = std::make_shared<PlaneWall>(c + hi * a, -a,
                                       LinearMotion{0.0, 0.5 * speed_, t0_, hi - half});
    lo_ = lo, hi_ = hi;
    const Index n = ctx.model->num_nodes();
    own(ctx, std::make_shared<WallTerm>(container_, n, k, range));
    own(ctx, std::make_shared<WallTerm>(bottom_, n, k, range));
    own(ctx, std::make_shared<WallTerm>(top_, n, k, range));
    reached_ = -1;
  }

  double gap(double t) const { return (hi_ - top_->offset(t)) - (lo_ + bottom_->offset(t)); }

  bool done(StageContext& ctx) override {
    const double t = ctx.state->t;
    if (reached_ < 0 && gap(t) <= compaction_ * h0_ * (1 + 1e-12)) reached_ = t;
    return reached_ >= 0 && t >= reached_ + hold_;
  }

  std::string progress(const StageContext& ctx) const override {
    std::ostringstream os;
    os << "compaction " << gap(ctx.state->t) / h0_ << " -> " << compaction_;
    return os.str();
  }

  double fraction(const StageContext& ctx) const override {
    return std::clamp((1.0 - gap(ctx.state->t) / h0_) / (1.0 - compaction_), 0.0, 1.0);
  }

 private:
  double compaction_, speed_, clearance_, close_time_, stiffness_, range_, hold_;
  double h0_ = 0, t0_ = 0, lo_ = 0, hi_ = 0, reached_ = -1;
  std::shared_ptr<CylinderWall> container_;
  std::shared_ptr<PlaneWall> bottom_, top_;
};

}  // namespace

StageType compress_stage_type() {
  using K = ParamSpec::Kind;
  StageType t;
  t.name = "compress";
  t.help = "compress the rolled sheet along its axis between two pistons in a cylinder";
  t.params = {
      {"compaction", K::Number, "", "target ratio of final to initial piston gap (0, 1]", 0.0, 1.0,
       true},
      {"speed", K::Number, "0.05", "closing speed of the two pistons together (length/s)", 0.0,
       1e30, true},
      {"clearance", K::Number, "0.15", "container radius = (1 + clearance) x roll radius", 0.0},
      {"close_time", K::Number, "0.02", "time for the container to close onto the roll (s)", 0.0},
      {"stiffness", K::Number, "1", "wall stiffness: force at contact, in units of ks x range",
       0.0, 1e30, true},
      {"range", K::Number, "1", "reach of the wall potential, in units of h_eff", 0.0, 1e30, true},
      {"hold", K::Number, "0", "time to hold at the target compaction (s)", 0.0},
  };
  for (auto& p : common_params(100.0, 0.01)) t.params.push_back(p);
  t.make = [](const StageArgs& a) { return std::make_unique<CompressStage>(a); };
  return t;
}

}  // namespace crumple::stages
