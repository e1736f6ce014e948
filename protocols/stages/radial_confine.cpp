// Stage `radial_confine`: the paper's radial confinement (Fig. 5a): an inward force on every
// node farther than a cutoff radius R(t) from the centre, R shrinking at `speed` for `duration`.
// The force is bounded, as the paper's "inward force" reads and as self-contact (whose force
// per pair is bounded too) requires to hold the crumpled ball: it builds up smoothly to
// `force` (in units of ks h_eff) over a penetration of `width` h_eff beyond the cutoff
// (a sphere wall with the saturating profile of wall_term.hpp). A perfectly flat sheet under
// in-plane load never leaves its plane, so the stage first gives the sheet a smooth random
// normal displacement of RMS `perturbation` h_eff (imperfection.hpp; from the run's random
// stream), with wavelengths between 1/8 and 1/2 of the sheet size: the imperfection every
// real sheet has.
#include "protocols/stages/common.hpp"
#include "protocols/stages/imperfection.hpp"
#include "protocols/terms/wall_term.hpp"

#include <algorithm>
#include <random>
#include <sstream>

namespace crumple::stages {
namespace {

class RadialConfineStage : public Stage {
 public:
  explicit RadialConfineStage(const StageArgs& a)
      : radius_(a.number("radius")), speed_(a.number("speed")), duration_(a.number("duration")),
        final_(a.number("final_radius")), force_(a.number("force")), width_(a.number("width")),
        perturbation_(a.number("perturbation")) {
    apply_common(*this, a);
  }
  std::string type() const override { return "radial_confine"; }
  void begin(StageContext& ctx) override {
    t0_ = ctx.t_begin;
    ImperfectionSpec imp;
    imp.rms = perturbation_ * ctx.sheet.h_eff;
    imp.shortest = ctx.sheet.size / 8.0;
    imp.longest = ctx.sheet.size / 2.0;
    const VecX w = smooth_imperfection(ctx.model->mesh(), imp, ctx.rng);
    for (Index i = 0; i < ctx.model->num_nodes(); ++i) ctx.state->x[3 * i + 2] += w[i];
    const Vec3 c = reference_centroid(ctx.model->mesh());
    // By default the cutoff starts at the farthest node, so that no node is pushed at t = 0:
    // the disk's nominal radius is not it (the node centroid is off the disk's centre by a
    // fraction of an edge), and a start inside the sheet applies the full force to the rim
    // at once, a shock that the quasistatic mode turns into rim speeds of F / b_iso.
    double r_far = 0;
    for (Index i = 0; i < ctx.model->num_nodes(); ++i)
      r_far = std::max(r_far, (ctx.model->mesh().ref.col(i) - c).norm());
    const double r0 = radius_ > 0 ? radius_ : r_far;
    wall_ = std::make_shared<SphereWall>(c, LinearMotion{r0, -speed_, t0_, final_}, true);
    const double h = ctx.sheet.h_eff;
    WallProfile prof;
    prof.kind = WallProfile::Kind::Saturating;
    prof.f_max = force_ * ctx.sheet.ks * h;
    prof.width = width_ * h;
    own(ctx, std::make_shared<WallTerm>(wall_, ctx.model->num_nodes(), prof, 0.0));
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
  double radius_, speed_, duration_, final_, force_, width_, perturbation_, t0_ = 0;
  std::shared_ptr<SphereWall> wall_;
};

}  // namespace

StageType radial_confine_stage_type() {
  using K = ParamSpec::Kind;
  StageType t;
  t.name = "radial_confine";
  t.help = "inward force on nodes beyond a shrinking cutoff radius (paper Fig. 5)";
  t.params = {
      {"radius", K::Number, "0", "initial cutoff radius; 0: the distance of the farthest node from the centre", 0.0},
      {"speed", K::Number, "0.01", "shrinking speed of the cutoff radius (length/s)", 0.0},
      {"duration", K::Number, "5", "duration of the stage (s)", 0.0, 1e30, true},
      {"final_radius", K::Number, "0", "the cutoff radius stops shrinking here", 0.0},
      {"force", K::Number, "0.2", "inward force per node beyond the cutoff, in units of ks h_eff",
       0.0, 1e30, true},
      {"perturbation", K::Number, "0.1",
       "RMS of the smooth random normal displacement given at the start, in units of h_eff", 0.0},
      {"width", K::Number, "4", "penetration over which the force builds up, in units of h_eff",
       0.0, 1e30, true},
  };
  for (auto& p : common_params(1e30, 0.01)) t.params.push_back(p);
  t.make = [](const StageArgs& a) { return std::make_unique<RadialConfineStage>(a); };
  t.check = [](const StageArgs& a) {  // radius 0 is the farthest node's distance, known later
    if (a.number("radius") > 0 && a.number("final_radius") > a.number("radius"))
      a.fail_both("final_radius", "radius", "the cutoff shrinks: final_radius must not exceed radius");
  };
  return t;
}
CRUMPLE_REGISTER_STAGE(radial_confine_stage_type);

}  // namespace crumple::stages
