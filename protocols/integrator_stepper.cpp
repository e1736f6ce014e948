// Integrator adapter and history serialisation (integrator_stepper.hpp).
#include "protocols/integrator_stepper.hpp"

#include <cstdio>

namespace crumple {

namespace {
constexpr double kFormat = 3.0;  // bump when the layout below changes

struct Reader {
  const std::vector<double>& d;
  std::size_t i = 0;
  double next() {
    if (i >= d.size()) throw InputError("checkpoint: integrator history is truncated");
    return d[i++];
  }
  long count() { return static_cast<long>(next()); }
  VecX vec() {
    const long n = count();
    if (n < 0 || i + n > d.size()) throw InputError("checkpoint: integrator history is corrupt");
    VecX v = Eigen::Map<const VecX>(d.data() + i, n);
    i += n;
    return v;
  }
};

void put_vec(std::vector<double>& out, const VecX& v) {
  out.push_back(static_cast<double>(v.size()));
  out.insert(out.end(), v.data(), v.data() + v.size());
}
}  // namespace

std::vector<double> flatten(const IntegratorHistory& h) {
  std::vector<double> out{kFormat, static_cast<double>(h.times.size())};
  for (std::size_t k = 0; k < h.times.size(); ++k) {
    out.push_back(h.times[k]);
    put_vec(out, h.xs[k]);
    put_vec(out, h.vs[k]);
    put_vec(out, h.ps[k]);
  }
  out.push_back(h.h);
  out.push_back(static_cast<double>(h.mode));
  out.push_back(h.steps_in_mode);
  out.push_back(static_cast<double>(h.a_window.size()));
  out.insert(out.end(), h.a_window.begin(), h.a_window.end());
  put_vec(out, h.fsal);
  out.push_back(h.err_prev);
  const auto& c = h.counters;
  for (double v : {double(c.steps_implicit), double(c.steps_explicit), double(c.switches),
                   double(c.newton_iters), double(c.cg_iters), double(c.implicit_attempts),
                   double(c.rejected_error), double(c.rejected_newton), double(c.rejected_not_spd),
                   double(c.rejected_other), c.wall_assembly, c.wall_linear, c.wall_total,
                   c.wall_implicit, c.wall_explicit, c.wall_before_step})
    out.push_back(v);
  return out;
}

IntegratorHistory unflatten_history(const std::vector<double>& data) {
  Reader r{data};
  if (r.next() != kFormat) throw InputError("checkpoint: integrator history of another format");
  IntegratorHistory h;
  const long n = r.count();
  for (long k = 0; k < n; ++k) {
    h.times.push_back(r.next());
    h.xs.push_back(r.vec());
    h.vs.push_back(r.vec());
    h.ps.push_back(r.vec());
  }
  h.h = r.next();
  h.mode = static_cast<IntegrationMode>(r.count());
  h.steps_in_mode = static_cast<int>(r.count());
  const long w = r.count();
  for (long k = 0; k < w; ++k) h.a_window.push_back(r.next());
  h.fsal = r.vec();
  h.err_prev = r.next();
  auto& c = h.counters;
  c.steps_implicit = r.count(), c.steps_explicit = r.count(), c.switches = r.count();
  c.newton_iters = r.count(), c.cg_iters = r.count(), c.implicit_attempts = r.count();
  c.rejected_error = r.count(), c.rejected_newton = r.count(), c.rejected_not_spd = r.count();
  c.rejected_other = r.count();
  c.wall_assembly = r.next(), c.wall_linear = r.next(), c.wall_total = r.next();
  c.wall_implicit = r.next(), c.wall_explicit = r.next(), c.wall_before_step = r.next();
  return h;
}

void IntegratorStepper::restart() {
  IntegratorHistory h = integ_.history();
  h.times.clear();
  h.xs.clear();
  h.vs.clear();
  h.ps.clear();
  h.fsal.resize(0);
  h.err_prev = 0;
  integ_.restore(h);
}

std::vector<double> IntegratorStepper::save() const { return flatten(integ_.history()); }

void IntegratorStepper::restore(const std::vector<double>& data) {
  integ_.restore(unflatten_history(data));
}

std::string IntegratorStepper::status() const {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s h=%.2e", integ_.mode() == IntegrationMode::Implicit ? "implicit" : "explicit",
                integ_.history().h);
  return buf;
}

}  // namespace crumple
