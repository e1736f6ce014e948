// Stage `unfold`: open the crumpled sheet and flatten it back onto a plane, keeping its plastic
// deformation p (the experiment opens the sheet by hand and flattens it for the scan).
//
// Three phases: (1) open: every node is tethered to a target moving smoothly from its crumpled
// position to its flat reference position (centred where the sheet is) over `open_time`;
// self-contact is off by default in this phase (hands pull layers past each other); (2) press:
// two plates close onto the plane to a gap of `press_gap` x h_eff while the tethers hold;
// (3) relax: the tethers let go and the sheet relaxes between the plates until quiescent; the
// plates are removed when the stage ends. New plastic flow happens only where flattening bends
// a hinge beyond the yield band around its p.
#include "protocols/stages/common.hpp"
#include "protocols/terms/tether_term.hpp"
#include "protocols/terms/wall_term.hpp"

#include <sstream>

namespace crumple::stages {
namespace {

class UnfoldStage : public Stage {
 public:
  explicit UnfoldStage(const StageArgs& a)
      : open_time_(a.number("open_time")),
        press_time_(a.number("press_time")),
        press_gap_(a.number("press_gap")),
        stiffness_(a.number("stiffness")),
        contact_(a.flag("contact")),
        threshold_(a.number("threshold")),
        speed_(a.number("speed")) {
    apply_common(*this, a);
  }
  std::string type() const override { return "unfold"; }

  void begin(StageContext& ctx) override {
    const Mesh& m = ctx.model->mesh();
    const Index n = m.num_nodes();
    t0_ = ctx.t_begin;
    start_ = Eigen::Map<const Eigen::Matrix3Xd>(ctx.state->x.data(), 3, n);
    // The flat target keeps the sheet's in-plane centre where it is now, at z = 0.
    const Vec3 shift = start_.rowwise().mean() - reference_centroid(m);
    flat_ = m.ref;
    flat_.row(0).array() += shift.x();
    flat_.row(1).array() += shift.y();
    std::vector<Index> nodes(n);
    for (Index i = 0; i < n; ++i) nodes[i] = i;
    auto targets = [this](double t, Eigen::Matrix3Xd& out) {
      const double s = smooth_ramp((t - t0_) / open_time_);
      out = (1.0 - s) * start_ + s * flat_;
    };
    tethers_ = std::make_shared<TetherTerm>(std::move(nodes), targets, stiffness_ * ctx.sheet.ks,
                                            t0_, 0.1 * open_time_);
    own(ctx, tethers_);
    if (!contact_) ctx.set_contact(false);
    phase_ = 0;
  }

  // Phase changes happen at fixed times (t0 + open_time, then + press_time), whatever the
  // check grid, so a resumed run that replays done() at its checkpoint rebuilds the same terms.
  bool done(StageContext& ctx) override {
    const double t = ctx.state->t;
    const double t_press = t0_ + open_time_, t_relax = t_press + press_time_;
    if (phase_ == 0 && t >= t_press) {
      // Press: plates start 5 h_eff above and below the plane and close to the gap.
      const double h = ctx.sheet.h_eff;
      const double start = 5.0 * h, end = 0.5 * press_gap_ * h;
      const double speed = press_time_ > 0 ? (start - end) / press_time_ : 1e30;
      const double k = ctx.sheet.ks / h;
      const Index n = ctx.model->num_nodes();
      own(ctx, std::make_shared<WallTerm>(
                   std::make_shared<PlaneWall>(Vec3(0, 0, -start), Vec3::UnitZ(),
                                               LinearMotion{0.0, speed, t_press, start - end}),
                   n, k, h));
      own(ctx, std::make_shared<WallTerm>(
                   std::make_shared<PlaneWall>(Vec3(0, 0, start), -Vec3::UnitZ(),
                                               LinearMotion{0.0, speed, t_press, start - end}),
                   n, k, h));
      phase_ = 1;
    }
    if (phase_ == 1 && t >= t_relax) {
      // Relax between the plates: the tethers let go, the plates stay until the end, as for a
      // sheet held flat to be scanned.
      ctx.model->remove_term(tethers_.get());
      if (!contact_) ctx.set_contact(true);
      phase_ = 2;
    }
    if (phase_ == 2 && t >= t_relax + 0.1 * open_time_) {
      return quiescent(ctx, threshold_, speed_, &last_ratio_);
    }
    return false;
  }

  void end(StageContext& ctx) override {
    release_terms(ctx);
    if (!contact_ && phase_ < 2) ctx.set_contact(true);
  }

  std::string progress(const StageContext& ctx) const override {
    static const char* names[] = {"opening", "pressing", "relaxing"};
    std::ostringstream os;
    os << names[phase_];
    if (phase_ == 2) os << ", a_max/a_ref " << last_ratio_ << " -> " << threshold_;
    return os.str();
  }

 private:
  double open_time_, press_time_, press_gap_, stiffness_;
  bool contact_;
  double threshold_, speed_;
  double t0_ = 0, last_ratio_ = 1.0 / 0.0;
  int phase_ = 0;
  Eigen::Matrix3Xd start_, flat_;
  std::shared_ptr<TetherTerm> tethers_;
};

}  // namespace

StageType unfold_stage_type() {
  using K = ParamSpec::Kind;
  StageType t;
  t.name = "unfold";
  t.help = "open the sheet, press it flat between two plates, release (plastic p is kept)";
  t.params = {
      {"open_time", K::Number, "0.3", "time to lead the sheet from crumpled to flat (s)", 0.0,
       1e30, true},
      {"press_time", K::Number, "0.05", "time for the plates to close (s)", 0.0},
      {"press_gap", K::Number, "2", "final plate gap in units of h_eff", 0.0, 1e30, true},
      {"stiffness", K::Number, "0.05", "tether stiffness per node, in units of ks", 0.0, 1e30,
       true},
      {"contact", K::Flag, "false", "keep self-contact on while opening"},
      {"threshold", K::Number, "1e-6", "quiescence threshold of the final relaxation", 0.0, 1e30,
       true},
      {"speed", K::Number, "1e-3", "... and largest node speed (sheet sizes/s)", 0.0, 1e30, true},
  };
  for (auto& p : common_params(10.0, 0.01)) t.params.push_back(p);
  t.make = [](const StageArgs& a) { return std::make_unique<UnfoldStage>(a); };
  return t;
}

}  // namespace crumple::stages
