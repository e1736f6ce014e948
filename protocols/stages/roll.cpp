// Stage `roll`: wrap the flat sheet into a cylinder of radius R about an in-plane axis
// (docs/MODEL.md §11.3, the first step of each axial-crumpling cycle; paper Fig. 9a).
//
// Every node is tethered to a target that follows an isometric bending of the reference sheet:
// with u the reference coordinate across the axis (centred) and w along it, the target at
// curvature k is  o + w a + (sin(k u)/k) b + ((1 - cos(k u))/k) z,  and k grows smoothly from 0
// to 1/R over `duration`. Bending a flat sheet this way stretches nothing, so the tethers only
// lead the sheet. They are soft, an elastic foundation that bends the sheet on length scales
// above `flatten_length` (as in unfold; common.hpp), because a sheet re-rolled after an unfold
// carries creases: stiff tethers would force every creased hinge to the roll's curvature and
// bend those with |p| > c0 back past yield, erasing the creases of earlier cycles (measured at
// 1500 nodes with the earlier 0.1 ks tethers: the roll cut the crease length at 0.5 c0 by up to
// 55 L0 and left no |p| above 0.37). The axis direction is drawn at random each cycle (the
// experiment re-rolls the flattened sheet by hand) unless `axis: fixed`, or drawn between the
// sheet's two sides with `axis: side` (rolled edge to edge; the sources do not say which way the
// experimenters rolled, docs/studies/roll_axis/). On completion the stage
// records the roll's axis, radius and height H0 for the compress stage and removes its tethers;
// the run file records the axis at the stage's end (Stage::roll_axis_deg).
#include "protocols/stages/common.hpp"
#include "protocols/terms/tether_term.hpp"

#include <cmath>
#include <random>
#include <algorithm>
#include <sstream>
#include <string>

namespace crumple::stages {
namespace {

class RollStage : public Stage {
 public:
  explicit RollStage(const StageArgs& a)
      : radius_(a.number("radius")),
        wrap_(a.number("wrap")),
        axis_mode_(a.text("axis")),
        angle_(a.number("angle") * M_PI / 180.0),
        duration_(a.number("duration")),
        flatten_length_(a.number("flatten_length")),
        tolerance_(a.number("tolerance")),
        threshold_(a.number("threshold")),
        speed_(a.number("speed")) {
    apply_common(*this, a);
  }
  std::string type() const override { return "roll"; }

  void begin(StageContext& ctx) override {
    const Mesh& m = ctx.model->mesh();
    double phi = angle_;
    if (axis_mode_ == "random") {
      phi = std::uniform_real_distribution<double>(0.0, M_PI)(ctx.rng);
    } else if (axis_mode_ == "side") {
      // One of the square sheet's two sides, as a hand rolls it edge to edge (phi and phi + pi
      // give the same roll).
      if (std::uniform_real_distribution<double>(0.0, 1.0)(ctx.rng) < 0.5) phi += 0.5 * M_PI;
    }
    const double deg = std::fmod(phi * 180.0 / M_PI, 180.0);
    phi_deg_ = deg < 0 ? deg + 180.0 : deg;
    a_ = Vec3(std::cos(phi), std::sin(phi), 0.0);
    b_ = Vec3(-std::sin(phi), std::cos(phi), 0.0);
    const Vec3 c = reference_centroid(m);
    const Index n = m.num_nodes();
    u_.resize(n);
    w_.resize(n);
    double umin = 1e300, umax = -1e300, wmin = 1e300, wmax = -1e300;
    for (Index i = 0; i < n; ++i) {
      const Vec3 r = m.ref.col(i) - c;
      u_[i] = r.dot(b_);
      w_[i] = r.dot(a_);
      umin = std::min(umin, u_[i]), umax = std::max(umax, u_[i]);
      wmin = std::min(wmin, w_[i]), wmax = std::max(wmax, w_[i]);
    }
    const double umid = 0.5 * (umin + umax);
    for (auto& u : u_) u -= umid;
    // The roll is built where the sheet lies now: a sheet that an earlier unfold laid out away
    // from its reference position (unfold keeps the sheet's centre where it is) would otherwise
    // be dragged there by the stiff tethers within the ramp time, a jerk that flaps the sheet and
    // bends creased hinges back past yield.
    const Vec3 shift =
        Eigen::Map<const Eigen::Matrix3Xd>(ctx.state->x.data(), 3, n).rowwise().mean() - c;
    origin_ = c + shift + umid * b_;
    R_ = radius_ > 0 ? radius_ : (umax - umin) / (2.0 * M_PI * wrap_);
    height_ = wmax - wmin;
    wmid_ = 0.5 * (wmin + wmax);
    t0_ = ctx.t_begin;
    std::vector<Index> nodes(n);
    for (Index i = 0; i < n; ++i) nodes[i] = i;
    auto targets = [this](double t, Eigen::Matrix3Xd& out) {
      const double k = smooth_ramp((t - t0_) / duration_) / R_;
      for (Index i = 0; i < out.cols(); ++i) {
        const double u = u_[i];
        // sin(ku)/k and (1-cos(ku))/k written to stay accurate as k -> 0.
        const double ku = k * u;
        const double s = std::abs(ku) < 1e-8 ? u : std::sin(ku) / k;
        const double q = std::abs(ku) < 1e-8 ? 0.5 * k * u * u : (1.0 - std::cos(ku)) / k;
        out.col(i) = origin_ + w_[i] * a_ + s * b_ + q * Vec3::UnitZ();
      }
    };
    // The stiffness ramps over a tenth of the duration so a sheet that is not exactly at its
    // reference position (after an unfold) is not yanked.
    xi_ = flatten_length_ * ctx.sheet.size;
    tethers_ = std::make_shared<TetherTerm>(std::move(nodes), targets,
                                            foundation_tether_stiffness(ctx, flatten_length_),
                                            t0_, 0.1 * duration_);
    own(ctx, tethers_);
  }

  bool done(StageContext& ctx) override {
    const double t = ctx.state->t;
    if (t < t0_ + duration_) return false;
    // A creased sheet does not lie on the isometric roll of the flat one: it is done once it
    // has settled on its tethers, or is close to the roll.
    return tethers_->max_deviation(*ctx.state) <= tolerance_ * std::max(xi_, ctx.sheet.spacing) ||
           quiescent(ctx, threshold_, speed_);
  }

  void end(StageContext& ctx) override {
    ctx.apparatus.rolled = true;
    ctx.apparatus.axis_dir = a_;
    ctx.apparatus.axis_point = origin_ + R_ * Vec3::UnitZ() + wmid_ * a_;
    ctx.apparatus.radius = R_;
    ctx.apparatus.height = height_;
    release_terms(ctx);
  }

  std::string progress(const StageContext& ctx) const override {
    std::ostringstream os;
    const double k = smooth_ramp((ctx.state->t - t0_) / duration_) / R_;
    os << "curvature " << k * R_ << " of 1/R, R = " << R_;
    return os.str();
  }

  double fraction(const StageContext& ctx) const override {
    return std::clamp((ctx.state->t - t0_) / duration_, 0.0, 1.0);
  }

  std::optional<double> roll_axis_deg() const override { return phi_deg_; }

 private:
  double radius_, wrap_;
  std::string axis_mode_;  // random, fixed or side
  std::optional<double> phi_deg_;  // the axis drawn in begin()
  double angle_, duration_, flatten_length_, tolerance_, threshold_, speed_, xi_ = 0;
  Vec3 a_, b_, origin_;
  double R_ = 0, height_ = 0, wmid_ = 0, t0_ = 0;
  std::vector<double> u_, w_;
  std::shared_ptr<TetherTerm> tethers_;
};

}  // namespace

StageType roll_stage_type() {
  using K = ParamSpec::Kind;
  StageType t;
  t.name = "roll";
  t.help = "wrap the flat sheet into a cylinder about an in-plane axis (random each cycle)";
  t.params = {
      {"radius", K::Number, "0", "roll radius; 0: the sheet's width/(2 pi wrap)", 0.0},
      {"wrap", K::Number, "0.9", "fraction of a full turn the sheet covers when radius = 0", 0.05,
       1.0},
      {"axis", K::Text, "random",
       "roll axis: drawn uniformly each cycle, fixed at `angle`, or side: `angle` or `angle` + 90 "
       "degrees, drawn each cycle",
       0, 0, false, {"random", "fixed", "side"}},
      {"angle", K::Number, "0", "axis angle from the x axis in degrees (axis: fixed or side)"},
      {"duration", K::Number, "0.2", "time to bend from flat to the full roll (s)", 0.0, 1e30,
       true},
      {"flatten_length", K::Number, "0.05",
       "the tethers bend the sheet on lengths above this, in sheet sizes (sets their stiffness)",
       0.0, 1e30, true},
      {"tolerance", K::Number, "0.5",
       "done when every node is within this many flatten lengths (or edges) of its target...",
       0.0, 1e30, true},
      {"threshold", K::Number, "1e-6",
       "... or quiescent: max|F|/m < threshold x ks/(m lambda)", 0.0, 1e30, true},
      {"speed", K::Number, "1e-3",
       "... and every node slower than this relative to the rigid motion (sizes/s)", 0.0, 1e30,
       true},
  };
  for (auto& p : common_params(10.0, 0.01)) t.params.push_back(p);
  t.make = [](const StageArgs& a) { return std::make_unique<RollStage>(a); };
  t.provides = {"rolled"};
  return t;
}
CRUMPLE_REGISTER_STAGE(roll_stage_type);

}  // namespace crumple::stages
