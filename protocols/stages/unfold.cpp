// Stage `unfold`: open the crumpled sheet and lay it out near flat without creasing it further,
// keeping its plastic deformation p (the experiment opens the sheet by hand and lays it out flat
// for the scan; the creases stay visible).
//
// Every node is tethered to a target that moves smoothly from the node's crumpled position to its
// flat reference position (centred where the sheet is) over `open_time`; then the targets stay
// flat and the sheet settles until it is quiescent. Self-contact stays on, so layers slide over
// each other instead of passing through.
//
// The tethers are soft on purpose. Together they act on the sheet like an elastic foundation of
// modulus K = k_t n / A (per unit area), which flattens undulations longer than the length
//     xi = (kappa / K)^(1/4),      kappa = sqrt(3) kb / 2  (paper eq. 6),
// and barely opens a crease, which is sharper than xi. So `flatten_length` (xi in units of the
// sheet size) sets k_t = kappa A / (n xi^4). Stiff tethers (or plates pressing the sheet flat)
// would instead force every hinge to c = 0: with a dead band c0 around p that bends each hinge
// with |p| > c0 back past yield, unmaking the creases the compression made and making new ones
// where the forced path buckles the sheet (docs/MODEL.md §7).
#include "protocols/stages/common.hpp"
#include "protocols/terms/tether_term.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace crumple::stages {
namespace {

class UnfoldStage : public Stage {
 public:
  explicit UnfoldStage(const StageArgs& a)
      : open_time_(a.number("open_time")),
        flatten_length_(a.number("flatten_length")),
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
    k_tether_ = foundation_tether_stiffness(ctx, flatten_length_);
    tethers_ = std::make_shared<TetherTerm>(std::move(nodes), targets, k_tether_, t0_,
                                            0.1 * open_time_);
    own(ctx, tethers_);
    if (!contact_) ctx.set_contact(false);
  }

  bool done(StageContext& ctx) override {
    if (ctx.state->t < t0_ + 1.1 * open_time_) return false;
    return quiescent(ctx, threshold_, speed_, &last_ratio_, &last_speed_);
  }

  void end(StageContext& ctx) override {
    release_terms(ctx);
    if (!contact_) ctx.set_contact(true);
  }

  std::string progress(const StageContext& ctx) const override {
    std::ostringstream os;
    if (ctx.state->t < t0_ + open_time_) {
      os << "opening, " << static_cast<int>(100 * (ctx.state->t - t0_) / open_time_) << " %";
    } else {
      os << "settling, a_max/a_ref " << last_ratio_ << " -> " << threshold_ << ", speed "
         << last_speed_ << " -> " << speed_ << " sizes/s";
    }
    return os.str();
  }

 private:
  double open_time_, flatten_length_;
  bool contact_;
  double threshold_, speed_;
  double t0_ = 0, k_tether_ = 0, last_ratio_ = 1.0 / 0.0, last_speed_ = 1.0 / 0.0;
  Eigen::Matrix3Xd start_, flat_;
  std::shared_ptr<TetherTerm> tethers_;
};

}  // namespace

StageType unfold_stage_type() {
  using K = ParamSpec::Kind;
  StageType t;
  t.name = "unfold";
  t.help = "open the sheet gently towards flat on soft tethers, contact on (plastic p is kept)";
  t.params = {
      {"open_time", K::Number, "0.4", "time to lead the sheet from crumpled to flat (s)", 0.0,
       1e30, true},
      {"flatten_length", K::Number, "0.05",
       "the tethers flatten undulations longer than this, in sheet sizes (sets their stiffness)",
       0.0, 1e30, true},
      {"contact", K::Flag, "true", "self-contact on while opening"},
      {"threshold", K::Number, "1e-6", "quiescent when max|F|/m < threshold x ks/(m lambda)", 0.0,
       1e30, true},
      {"speed", K::Number, "1e-3",
       "... and every node is slower than this relative to the rigid motion (sizes/s)", 0.0, 1e30,
       true},
  };
  for (auto& p : common_params(3.0, 0.01)) t.params.push_back(p);
  t.make = [](const StageArgs& a) { return std::make_unique<UnfoldStage>(a); };
  return t;
}
CRUMPLE_REGISTER_STAGE(unfold_stage_type);

}  // namespace crumple::stages
