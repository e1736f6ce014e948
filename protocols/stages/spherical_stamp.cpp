// Stage `spherical_stamp`: a rigid sphere pressed into the sheet whose rim is held (paper
// Fig. 7, spherical stamping): the wrinkle-to-crumple transition under a curved indenter.
// The rim (boundary nodes) is tethered to where it is; the sphere (allowed outside) starts just
// above the sheet's centre and moves down at `speed` until it has indented by `depth`.
#include "protocols/stages/common.hpp"
#include "protocols/terms/tether_term.hpp"
#include "protocols/terms/wall_term.hpp"

#include <algorithm>
#include <sstream>

namespace crumple::stages {
namespace {

class SphericalStampStage : public Stage {
 public:
  explicit SphericalStampStage(const StageArgs& a)
      : radius_(a.number("radius")), speed_(a.number("speed")), depth_(a.number("depth")),
        stiffness_(a.number("stiffness")) {
    apply_common(*this, a);
  }
  std::string type() const override { return "spherical_stamp"; }
  void begin(StageContext& ctx) override {
    const Mesh& m = ctx.model->mesh();
    t0_ = ctx.t_begin;
    const double h = ctx.sheet.h_eff;
    const double R = radius_ * ctx.sheet.size;
    const Vec3 c = reference_centroid(m);
    double ztop = -1e300;
    for (Index i = 0; i < m.num_nodes(); ++i) ztop = std::max(ztop, ctx.state->x[3 * i + 2]);
    const Vec3 start = Vec3(c.x(), c.y(), ztop + R + h);
    travel_ = h + depth_ * ctx.sheet.size;
    sphere_ = std::make_shared<SphereWall>(start, LinearMotion{R, 0.0, t0_}, false,
                                           -Vec3::UnitZ(), LinearMotion{0.0, speed_, t0_, travel_});
    own(ctx, std::make_shared<WallTerm>(sphere_, m.num_nodes(), stiffness_ * ctx.sheet.ks / h, h));
    std::vector<Index> rim;
    for (Index i = 0; i < m.num_nodes(); ++i)
      if (m.boundary[i]) rim.push_back(i);
    Eigen::Matrix3Xd fixed(3, rim.size());
    for (std::size_t k = 0; k < rim.size(); ++k) fixed.col(k) = node(ctx.state->x, rim[k]);
    own(ctx, std::make_shared<TetherTerm>(
                 rim, [fixed](double, Eigen::Matrix3Xd& out) { out = fixed; }, ctx.sheet.ks, t0_,
                 0.0));
  }
  bool done(StageContext& ctx) override { return ctx.state->t >= t0_ + travel_ / speed_; }
  std::string progress(const StageContext& ctx) const override {
    std::ostringstream os;
    os << "stamp travel " << std::min(travel_, speed_ * (ctx.state->t - t0_)) << " of " << travel_;
    return os.str();
  }

  double fraction(const StageContext& ctx) const override {
    return std::clamp(speed_ * (ctx.state->t - t0_) / travel_, 0.0, 1.0);
  }

 private:
  double radius_, speed_, depth_, stiffness_, t0_ = 0, travel_ = 0;
  std::shared_ptr<SphereWall> sphere_;
};

}  // namespace

StageType spherical_stamp_stage_type() {
  using K = ParamSpec::Kind;
  StageType t;
  t.name = "spherical_stamp";
  t.help = "press a rigid sphere into the sheet with its rim held (paper Fig. 7)";
  t.params = {
      {"radius", K::Number, "0.3", "sphere radius in units of the sheet size", 0.0, 1e30, true},
      {"speed", K::Number, "0.05", "stamp speed (length/s)", 0.0, 1e30, true},
      {"depth", K::Number, "0.2", "indentation in units of the sheet size", 0.0, 1e30, true},
      {"stiffness", K::Number, "1", "wall stiffness in units of ks/h_eff", 0.0, 1e30, true},
  };
  for (auto& p : common_params(1e30, 0.01)) t.params.push_back(p);
  t.make = [](const StageArgs& a) { return std::make_unique<SphericalStampStage>(a); };
  return t;
}
CRUMPLE_REGISTER_STAGE(spherical_stamp_stage_type);

}  // namespace crumple::stages
