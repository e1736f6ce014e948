// Stage `fold`: fold the sheet in half along a line through its centre (paper Fig. 3b, the
// calibration of the yield curvature c0).
//
// The fold has a physical loop radius R (`radius`, in sheet sizes), independent of the mesh:
// a free strip of width A R about the fold line (A the final fold angle) is left untethered
// and bends into the loop, while the two sides are tethered as rigid flaps. One flap stays
// where it is; the other follows the end of a circular arc of fixed length A R bent to the
// current angle phi (radius A R / phi), so the strip is never stretched and closes to a loop
// of radius R at phi = A. The strip takes its own elastica shape in between.
// Why a fixed physical radius: a hinge in the loop bends by about (hinge spacing) / R, which
// scales as 1 / (lambda R) with lambda the linear node density; yield (c > c0) and the plastic
// set therefore depend on lambda c0, the collapse variable of Fig. 3b (beta = 0.04 lambda).
// A fold pinched to a single line of hinges would instead yield the same at every resolution.
// radius 0 is that pinched fold: every node tethered, the flap laid exactly onto the other half
// (used to press layers into contact).
// The fold is reached over `duration` (smooth ramp), then held for `hold` so the plastic flow
// can settle; a following `release` lets it spring back to the final angle.
#include "protocols/stages/common.hpp"
#include "protocols/terms/tether_term.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace crumple::stages {
namespace {

class FoldStage : public Stage {
 public:
  explicit FoldStage(const StageArgs& a)
      : angle_(a.number("angle") * M_PI / 180.0), line_(a.number("line_angle") * M_PI / 180.0),
        duration_(a.number("duration")), hold_(a.number("hold")), radius_(a.number("radius")),
        stiffness_(a.number("stiffness")) {
    apply_common(*this, a);
  }
  std::string type() const override { return "fold"; }
  void begin(StageContext& ctx) override {
    const Mesh& m = ctx.model->mesh();
    t0_ = ctx.t_begin;
    const Vec3 c = reference_centroid(m);
    const Vec3 a(std::cos(line_), std::sin(line_), 0.0);  // fold line direction
    const Vec3 b(-a.y(), a.x(), 0.0);                      // across the line; a x b = +z
    const double half = 0.5 * angle_ * radius_ * ctx.sheet.size;  // half-width of the free strip
    std::vector<Index> nodes;
    std::vector<bool> moving;
    std::vector<Vec3> start;
    for (Index i = 0; i < m.num_nodes(); ++i) {
      const double across = (m.ref.col(i) - c).dot(b);
      if (std::abs(across) <= half) continue;
      nodes.push_back(i);
      moving.push_back(across > 0);
      start.push_back(node(ctx.state->x, i));
    }
    const Vec3 hinge_start = c + half * b;  // where the moving flap meets the strip
    const double t0 = t0_, T = duration_, A = angle_;
    auto targets = [=](double t, Eigen::Matrix3Xd& out) {
      const double phi = A * smooth_ramp((t - t0) / T);
      // End of the strip: an arc of length 2 half from c - half b, tangent to b, bent by phi.
      // sin(phi)/phi and (1 - cos(phi))/phi written to stay exact as phi -> 0.
      const double s_over = phi > 1e-6 ? std::sin(phi) / phi : 1.0 - phi * phi / 6.0;
      const double c_over = phi > 1e-6 ? (1.0 - std::cos(phi)) / phi : 0.5 * phi;
      const Vec3 end = c - half * b + 2.0 * half * (s_over * b + c_over * Vec3::UnitZ());
      const Eigen::AngleAxisd rot(phi, a);
      out.resize(3, static_cast<Index>(start.size()));
      for (std::size_t k = 0; k < start.size(); ++k)
        out.col(k) = moving[k] ? Vec3(end + rot * (start[k] - hinge_start)) : start[k];
    };
    tethers_ = std::make_shared<TetherTerm>(std::move(nodes), targets, stiffness_ * ctx.sheet.ks,
                                            t0_, 0.0);
    own(ctx, tethers_);
  }
  bool done(StageContext& ctx) override { return ctx.state->t >= t0_ + duration_ + hold_; }
  std::string progress(const StageContext& ctx) const override {
    std::ostringstream os;
    os << "fold " << angle_ * smooth_ramp((ctx.state->t - t0_) / duration_) * 180.0 / M_PI
       << " of " << angle_ * 180.0 / M_PI << " deg";
    if (ctx.state->t > t0_ + duration_) os << ", holding";
    return os.str();
  }

  double fraction(const StageContext& ctx) const override {
    return std::clamp((ctx.state->t - t0_) / (duration_ + hold_), 0.0, 1.0);
  }

 private:
  double angle_, line_, duration_, hold_, radius_, stiffness_, t0_ = 0;
  std::shared_ptr<TetherTerm> tethers_;
};

}  // namespace

StageType fold_stage_type() {
  using K = ParamSpec::Kind;
  StageType t;
  t.name = "fold";
  t.help = "fold the sheet in half about a line through its centre, loop of a set radius (paper Fig. 3b)";
  t.params = {
      {"angle", K::Number, "180", "fold angle in degrees", 0.0, 180.0, true},
      {"line_angle", K::Number, "90", "direction of the fold line from the x axis, degrees"},
      {"duration", K::Number, "0.2", "time to fold (s)", 0.0, 1e30, true},
      {"hold", K::Number, "0", "time the fold is held after reaching the angle (s)", 0.0},
      {"radius", K::Number, "0.05",
       "radius of the fold's loop in sheet sizes; a strip of width angle x radius is left free; "
       "0: a pinched fold, the flap laid exactly onto the other half",
       0.0, 0.25},
      {"stiffness", K::Number, "0.05", "tether stiffness per node, in units of ks", 0.0, 1e30,
       true},
  };
  for (auto& p : common_params(1e30, 0.01)) t.params.push_back(p);
  t.make = [](const StageArgs& a) { return std::make_unique<FoldStage>(a); };
  return t;
}
CRUMPLE_REGISTER_STAGE(fold_stage_type);

}  // namespace crumple::stages
