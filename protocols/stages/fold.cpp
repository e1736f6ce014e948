// Stage `fold`: fold the sheet in half along a line through its centre (paper Fig. 3b, the
// calibration of the yield curvature c0). Nodes on one side are tethered where they are; nodes
// on the other side follow a rigid rotation about the fold line, raised by half the fold `gap`
// (in units of h_eff) so the folded half comes to rest on the other one, up to `angle`
// degrees over `duration`. A following `release` stage lets the fold spring back; its final
// angle measures the plastic set.
#include "protocols/stages/common.hpp"
#include "protocols/terms/tether_term.hpp"

#include <cmath>
#include <algorithm>
#include <sstream>

namespace crumple::stages {
namespace {

class FoldStage : public Stage {
 public:
  explicit FoldStage(const StageArgs& a)
      : angle_(a.number("angle") * M_PI / 180.0), line_(a.number("line_angle") * M_PI / 180.0),
        duration_(a.number("duration")), gap_(a.number("gap")),
        stiffness_(a.number("stiffness")) {
    apply_common(*this, a);
  }
  std::string type() const override { return "fold"; }
  void begin(StageContext& ctx) override {
    const Mesh& m = ctx.model->mesh();
    t0_ = ctx.t_begin;
    const Vec3 c = reference_centroid(m);
    const Vec3 a(std::cos(line_), std::sin(line_), 0.0);  // fold line direction
    const Vec3 b(-a.y(), a.x(), 0.0);                      // across the line
    const Index n = m.num_nodes();
    std::vector<Index> nodes(n);
    Eigen::Matrix3Xd start(3, n);
    std::vector<double> across(n);
    for (Index i = 0; i < n; ++i) {
      nodes[i] = i;
      start.col(i) = node(ctx.state->x, i);
      across[i] = (m.ref.col(i) - c).dot(b);
    }
    const double lift = 0.5 * gap_ * ctx.sheet.h_eff;
    const double t0 = t0_, T = duration_, A = angle_;
    auto targets = [=](double t, Eigen::Matrix3Xd& out) {
      const double phi = A * smooth_ramp((t - t0) / T);
      const Eigen::AngleAxisd rot(-phi, a);
      const Vec3 pivot = c + lift * Vec3::UnitZ();
      out = start;
      for (Index i = 0; i < out.cols(); ++i)
        if (across[i] > 0) out.col(i) = pivot + rot * (start.col(i) - pivot);
    };
    tethers_ = std::make_shared<TetherTerm>(std::move(nodes), targets, stiffness_ * ctx.sheet.ks,
                                            t0_, 0.0);
    own(ctx, tethers_);
  }
  bool done(StageContext& ctx) override { return ctx.state->t >= t0_ + duration_; }
  std::string progress(const StageContext& ctx) const override {
    std::ostringstream os;
    os << "fold " << angle_ * smooth_ramp((ctx.state->t - t0_) / duration_) * 180.0 / M_PI
       << " of " << angle_ * 180.0 / M_PI << " deg";
    return os.str();
  }

  double fraction(const StageContext& ctx) const override {
    return std::clamp((ctx.state->t - t0_) / duration_, 0.0, 1.0);
  }

 private:
  double angle_, line_, duration_, gap_, stiffness_, t0_ = 0;
  std::shared_ptr<TetherTerm> tethers_;
};

}  // namespace

StageType fold_stage_type() {
  using K = ParamSpec::Kind;
  StageType t;
  t.name = "fold";
  t.help = "fold the sheet in half about a line through its centre (paper Fig. 3b)";
  t.params = {
      {"angle", K::Number, "180", "fold angle in degrees", 0.0, 180.0, true},
      {"line_angle", K::Number, "90", "direction of the fold line from the x axis, degrees"},
      {"duration", K::Number, "0.2", "time to fold (s)", 0.0, 1e30, true},
      {"gap", K::Number, "1", "the folded half lands this many h_eff above the other", 0.0},
      {"stiffness", K::Number, "0.05", "tether stiffness per node, in units of ks", 0.0, 1e30,
       true},
  };
  for (auto& p : common_params(1e30, 0.01)) t.params.push_back(p);
  t.make = [](const StageArgs& a) { return std::make_unique<FoldStage>(a); };
  return t;
}

}  // namespace crumple::stages
