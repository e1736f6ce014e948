// Stage `conical_pack`: pull the sheet's centre down through a conical funnel (paper Fig. 7,
// conical packing). The nodes within `grip` (fraction of the sheet size) of the centre are
// tethered to targets moving down at `speed`; a cone (allowed inside, apex below the sheet,
// half-angle `angle`) guides the rest of the sheet in. Stops after a pull of `depth`.
#include "protocols/stages/common.hpp"
#include "protocols/terms/tether_term.hpp"
#include "protocols/terms/wall_term.hpp"

#include <cmath>
#include <algorithm>
#include <sstream>

namespace crumple::stages {
namespace {

class ConicalPackStage : public Stage {
 public:
  explicit ConicalPackStage(const StageArgs& a)
      : angle_(a.number("angle") * M_PI / 180.0), speed_(a.number("speed")),
        depth_(a.number("depth")), grip_(a.number("grip")), stiffness_(a.number("stiffness")) {
    apply_common(*this, a);
  }
  std::string type() const override { return "conical_pack"; }
  void begin(StageContext& ctx) override {
    const Mesh& m = ctx.model->mesh();
    t0_ = ctx.t_begin;
    const double h = ctx.sheet.h_eff, L = ctx.sheet.size;
    const Vec3 c = reference_centroid(m);
    // The cone's surface passes 2 h_eff below the sheet at half the sheet size from the axis.
    const double apex_z = -2.0 * h - 0.5 * L / std::tan(angle_);
    own(ctx, std::make_shared<WallTerm>(
                 std::make_shared<ConeWall>(Vec3(c.x(), c.y(), apex_z), Vec3::UnitZ(), angle_,
                                            true),
                 m.num_nodes(), stiffness_ * ctx.sheet.ks / h, h));
    // At least 1.5 edges, so that coarse meshes still have a gripped centre.
    const double grip_radius = std::max(grip_ * L, 1.5 * ctx.sheet.spacing);
    std::vector<Index> grip;
    for (Index i = 0; i < m.num_nodes(); ++i)
      if ((m.ref.col(i) - c).norm() <= grip_radius) grip.push_back(i);
    if (grip.empty()) throw InputError("conical_pack: grip radius holds no node; increase grip");
    Eigen::Matrix3Xd start(3, grip.size());
    for (std::size_t k = 0; k < grip.size(); ++k) start.col(k) = node(ctx.state->x, grip[k]);
    const double t0 = t0_, v = speed_, d = depth_ * L;
    own(ctx, std::make_shared<TetherTerm>(
                 grip,
                 [start, t0, v, d](double t, Eigen::Matrix3Xd& out) {
                   out = start;
                   out.row(2).array() -= std::min(d, v * std::max(0.0, t - t0));
                 },
                 ctx.sheet.ks, t0_, 0.0));
    travel_ = d;
  }
  bool done(StageContext& ctx) override { return ctx.state->t >= t0_ + travel_ / speed_; }
  std::string progress(const StageContext& ctx) const override {
    std::ostringstream os;
    os << "pull " << std::min(travel_, speed_ * (ctx.state->t - t0_)) << " of " << travel_;
    return os.str();
  }

  double fraction(const StageContext& ctx) const override {
    return std::clamp(speed_ * (ctx.state->t - t0_) / travel_, 0.0, 1.0);
  }

 private:
  double angle_, speed_, depth_, grip_, stiffness_, t0_ = 0, travel_ = 0;
};

}  // namespace

StageType conical_pack_stage_type() {
  using K = ParamSpec::Kind;
  StageType t;
  t.name = "conical_pack";
  t.help = "pull the sheet's centre down through a conical funnel (paper Fig. 7)";
  t.params = {
      {"angle", K::Number, "30", "half-angle of the cone in degrees", 0.0, 89.0, true},
      {"speed", K::Number, "0.05", "pulling speed (length/s)", 0.0, 1e30, true},
      {"depth", K::Number, "0.4", "pull distance in units of the sheet size", 0.0, 1e30, true},
      {"grip", K::Number, "0.05",
       "radius of the gripped centre, in units of the sheet size (at least 1.5 edges)", 0.0,
       0.5, true},
      {"stiffness", K::Number, "1", "cone wall stiffness in units of ks/h_eff", 0.0, 1e30, true},
  };
  for (auto& p : common_params(1e30, 0.01)) t.params.push_back(p);
  t.make = [](const StageArgs& a) { return std::make_unique<ConicalPackStage>(a); };
  return t;
}
CRUMPLE_REGISTER_STAGE(conical_pack_stage_type);

}  // namespace crumple::stages
