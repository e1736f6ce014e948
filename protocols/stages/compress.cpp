// Stage `compress`: axial compression of the rolled sheet between two pistons inside a
// cylindrical container, to a target compaction ratio (the experiment's knob:
// compaction = final / initial piston gap, docs/STATISTICS.md §1).
//
// The container is a cylinder wall (allowed inside) about the roll's axis. It starts just outside
// the sheet's current radial extent and closes to (1 + clearance) times the roll radius over
// `close_time`, so the rolled sheet is caught before it can spring open. The pistons are plane
// walls normal to the axis, starting just beyond the sheet's ends (gap H0 = the roll's height)
// and each moving inwards at speed/2 until their gap is compaction * H0; the stage then holds
// for `hold` seconds. With `retract` (the default) the pistons then move back out at the same
// speed to where they started, and the container opens back to its starting radius in the same
// time, so the sheet springs back quasistatically against retreating walls, as under a piston
// lifted by hand, instead of all at once when the walls vanish: a sudden release rings the sheet
// and bends hinges past yield after the crushing is over.
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
      : schedule_(a.numbers("compaction")),
        compaction_(schedule_.front()),
        speed_(a.number("speed")),
        clearance_(a.number("clearance")),
        close_time_(a.number("close_time")),
        stiffness_(a.number("stiffness")),
        range_(a.number("range")),
        hold_(a.number("hold")),
        retract_(a.flag("retract")) {
    apply_common(*this, a);
  }
  std::string type() const override { return "compress"; }

  void begin(StageContext& ctx) override {
    // A list gives one ratio per cycle; cycles beyond its end keep its last value.
    compaction_ = schedule_[std::min(schedule_.size(), static_cast<std::size_t>(ctx.cycle)) - 1];
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
    k_ = k, range_len_ = range;
    own_walls(ctx);
    reached_ = -1;
    // The retraction starts on the stage's check grid (a chunk ends there, so the walls are
    // swapped exactly when they stand still at the target) after the pistons have arrived and
    // held; its time depends on the wall motions only, so a resumed run rebuilds it the same.
    const double travel = std::max(-half - lo, hi - half);
    const double t_hold_end = t0_ + travel / (0.5 * speed_) + hold_;
    t_retract_ = t0_ + std::ceil((t_hold_end - t0_) / check_interval - 1e-9) * check_interval;
    retract_duration_ = travel / (0.5 * speed_);
    r_start_ = r_start, r_final_ = r_final;
    retracting_ = false;
  }

  /// Adds the container and the two pistons as they stand (container_, bottom_, top_).
  void own_walls(StageContext& ctx) {
    const Index n = ctx.model->num_nodes();
    walls_ = {std::make_shared<WallTerm>(container_, n, k_, range_len_),
              std::make_shared<WallTerm>(bottom_, n, k_, range_len_),
              std::make_shared<WallTerm>(top_, n, k_, range_len_)};
    for (const auto& w : walls_) own(ctx, w);
  }

  void start_retraction(StageContext& ctx) {
    const Vec3 a = ctx.apparatus.axis_dir, c = ctx.apparatus.axis_point;
    const double tr = t_retract_, v = 0.5 * speed_;
    const double fb = bottom_->offset(tr), ft = top_->offset(tr);
    for (const auto& w : walls_) ctx.model->remove_term(w.get());
    const double rate = retract_duration_ > 0 ? (r_start_ - r_final_) / retract_duration_ : 0.0;
    container_ = std::make_shared<CylinderWall>(
        c, a, LinearMotion{r_final_, rate, tr, r_start_}, true);
    bottom_ = std::make_shared<PlaneWall>(c + lo_ * a, a, LinearMotion{fb, -v, tr, 0.0});
    top_ = std::make_shared<PlaneWall>(c + hi_ * a, -a, LinearMotion{ft, -v, tr, 0.0});
    own_walls(ctx);
    retracting_ = true;
  }

  double gap(double t) const { return (hi_ - top_->offset(t)) - (lo_ + bottom_->offset(t)); }

  bool done(StageContext& ctx) override {
    const double t = ctx.state->t;
    if (reached_ < 0 && gap(t) <= compaction_ * h0_ * (1 + 1e-12)) reached_ = t;
    if (!retract_) return reached_ >= 0 && t >= reached_ + hold_;
    if (!retracting_ && t >= t_retract_ - 1e-12) start_retraction(ctx);
    return retracting_ && t >= t_retract_ + retract_duration_ - 1e-12;
  }

  std::string progress(const StageContext& ctx) const override {
    std::ostringstream os;
    if (retracting_)
      os << "retracting, piston gap " << gap(ctx.state->t) / h0_ << " of H0";
    else
      os << "compaction " << gap(ctx.state->t) / h0_ << " -> " << compaction_;
    return os.str();
  }

  std::optional<double> compaction() const override { return compaction_; }

  double fraction(const StageContext& ctx) const override {
    if (retract_)
      return std::clamp((ctx.state->t - t0_) / (t_retract_ + retract_duration_ - t0_), 0.0, 1.0);
    return std::clamp((1.0 - gap(ctx.state->t) / h0_) / (1.0 - compaction_), 0.0, 1.0);
  }

 private:
  std::vector<double> schedule_;
  double compaction_, speed_, clearance_, close_time_, stiffness_, range_, hold_;
  bool retract_;
  double h0_ = 0, t0_ = 0, lo_ = 0, hi_ = 0, reached_ = -1;
  double t_retract_ = 0, retract_duration_ = 0, r_start_ = 0, r_final_ = 0, k_ = 0,
         range_len_ = 0;
  bool retracting_ = false;
  std::vector<std::shared_ptr<WallTerm>> walls_;
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
      {"compaction", K::Numbers, "",
       "target ratio of final to initial piston gap (0, 1]; a list gives one per cycle (cycle n "
       "takes element n, later cycles the last), for histories of changing compaction",
       0.0, 1.0, true},
      {"speed", K::Number, "0.05", "closing speed of the two pistons together (length/s)", 0.0,
       1e30, true},
      {"clearance", K::Number, "0.15", "container radius = (1 + clearance) x roll radius", 0.0},
      {"close_time", K::Number, "0.02", "time for the container to close onto the roll (s)", 0.0},
      {"stiffness", K::Number, "1", "wall stiffness: force at contact, in units of ks x range",
       0.0, 1e30, true},
      {"range", K::Number, "1", "reach of the wall potential, in units of h_eff", 0.0, 1e30, true},
      {"hold", K::Number, "0", "time to hold at the target compaction (s)", 0.0},
      {"retract", K::Flag, "true",
       "then move the pistons back out and open the container at the same speed"},
  };
  for (auto& p : common_params(100.0, 0.01)) t.params.push_back(p);
  t.make = [](const StageArgs& a) { return std::make_unique<CompressStage>(a); };
  t.needs = {"rolled"};
  return t;
}
CRUMPLE_REGISTER_STAGE(compress_stage_type);

}  // namespace crumple::stages
