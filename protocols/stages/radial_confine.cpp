// Stage `radial_confine`: the paper's radial confinement (Fig. 5a): an inward force on every
// node farther than a cutoff radius R(t) from the centre, R shrinking at `speed` for `duration`.
// The force is that of a sphere wall (allowed inside) with zero range: U = k/3 (r - R)^3 for
// r > R, which is C^2 at the cutoff.
#include "protocols/stages/common.hpp"
#include "protocols/terms/wall_term.hpp"

#include <algorithm>
#include <sstream>

namespace crumple::stages {
namespace {

class RadialConfineStage : public Stage {
 public:
  explicit RadialConfineStage(const StageArgs& a)
      : radius_(a.number("radius")), speed_(a.number("speed")), duration_(a.number("duration")),
        final_(a.number("final_radius")), stiffness_(a.number("stiffness")) {
    apply_common(*this, a);
  }
  std::string type() const override { return "radial_confine"; }
  void begin(StageContext& ctx) override {
    t0_ = ctx.t_begin;
    const double r0 = radius_ > 0 ? radius_ : 0.5 * ctx.sheet.size;
    const Vec3 c = reference_centroid(ctx.model->mesh());
    wall_ = std::make_shared<SphereWall>(c, LinearMotion{r0, -speed_, t0_, final_}, true);
    const double h = ctx.sheet.h_eff;
    own(ctx, std::make_shared<WallTerm>(wall_, ctx.model->num_nodes(),
                                        stiffness_ * ctx.sheet.ks / h, 0.0));
  }
  bool done(StageContext& ctx) override { return ctx.state->t >= t0_ + duration_; }
  std::string progress(const StageContext& ctx) const override {
    std::ostringstream os;
    os << "cutoff radius " << wall_->radius(ctx.state->t);
    return os.str();
  }

  double fraction(const StageContext& ctx) const override {
    return std::clamp((ctx.state->t - t0_) / duration_, 0.0, 1.0);
  }

 private:
  double radius_, speed_, duration_, final_, stiffness_, t0_ = 0;
  std::shared_ptr<SphereWall> wall_;
};

}  // namespace

StageType radial_confine_stage_type() {
  using K = ParamSpec::Kind;
  StageType t;
  t.name = "radial_confine";
  t.help = "inward force on nodes beyond a shrinking cutoff radius (paper Fig. 5)";
  t.params = {
      {"radius", K::Number, "0", "initial cutoff radius; 0: half the sheet size", 0.0},
      {"speed", K::Number, "0.01", "shrinking speed of the cutoff radius (length/s)", 0.0},
      {"duration", K::Number, "5", "duration of the stage (s)", 0.0, 1e30, true},
      {"final_radius", K::Number, "0", "the cutoff radius stops shrinking here", 0.0},
      {"stiffness", K::Number, "0.1",
       "k of U = k/3 (r-R)^3, in units of ks/h_eff", 0.0, 1e30, true},
  };
  for (auto& p : common_params(1e30, 0.01)) t.params.push_back(p);
  t.make = [](const StageArgs& a) { return std::make_unique<RadialConfineStage>(a); };
  return t;
}

}  // namespace crumple::stages
