// The hybrid driver: step loop, step-size control, rejection and retry, mode switching and the
// step log (integrator.hpp; paper §3.2-3.4).
#include "sim/integrate/integrator.hpp"

#include "sim/core/errors.hpp"
#include "sim/integrate/bdf.hpp"
#include "sim/integrate/step_toward.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace crumple {

Integrator::Integrator(SheetModel& model, const IntegratorSettings& settings)
    : model_(model),
      settings_(settings),
      law_{settings.plastic_c0, settings.plastic_gamma, settings.plastic_rate, settings.plasticity},
      solver_(settings.linear_solver, settings.block_size, settings.cg_tol, settings.cg_max_iters,
              settings.coarse_nodes) {
  validate(settings_);
  model_.rebuild_pattern();
  newton_ = std::make_unique<ReducedNewton>(model_, law_);
  const double lambda = std::sqrt(model_.num_nodes() / model_.mesh().total_area());
  a_ref_ = model_.params().ks / (model_.params().mass * lambda);
  hist_.h = settings_.h_init;
  hist_.mode = settings_.mode_initial;
}

Integrator::~Integrator() = default;

void Integrator::reset_history(const State& s) {
  hist_.times.assign(1, s.t);
  hist_.xs.assign(1, s.x);
  hist_.vs.assign(1, s.v);
  hist_.ps.assign(1, s.p);
  hist_.fsal.resize(0);
  hist_.err_prev = 0;
}

void Integrator::sync_history(const State& s) {
  const bool same = !hist_.times.empty() && hist_.times[0] == s.t && hist_.xs[0] == s.x &&
                    hist_.vs[0] == s.v && hist_.ps[0] == s.p;
  if (!same) reset_history(s);
}

void Integrator::push_history(const State& s) {
  // Keep bdf_order + 1 points: the corrector of order s needs s, its predictor s + 1.
  const std::size_t keep =
      hist_.mode == IntegrationMode::Implicit ? static_cast<std::size_t>(settings_.bdf_order) + 1 : 1;
  hist_.times.insert(hist_.times.begin(), s.t);
  hist_.xs.insert(hist_.xs.begin(), s.x);
  hist_.vs.insert(hist_.vs.begin(), s.v);
  hist_.ps.insert(hist_.ps.begin(), s.p);
  if (hist_.times.size() > keep) {
    hist_.times.resize(keep);
    hist_.xs.resize(keep);
    hist_.vs.resize(keep);
    hist_.ps.resize(keep);
  }
}

void Integrator::after_accept(const State& s, const Attempt& a, double h, int rejections) {
  auto& C = hist_.counters;
  const bool implicit = hist_.mode == IntegrationMode::Implicit;
  (implicit ? C.steps_implicit : C.steps_explicit) += 1;
  ++hist_.steps_in_mode;

  LogRow row;
  row.t = s.t;
  row.h = h;
  row.mode = implicit ? 0 : 1;
  row.order = a.order;
  row.newton_iters = a.newton_iters;
  row.cg_iters = a.cg_iters;
  row.a_ratio = a.a_ratio;
  row.rejections = rejections;
  // Moving average of a_max / a_ref over the current mode's last switch_window steps (Fig. 6a).
  auto& w = hist_.a_window;
  w.push_back(a.a_ratio);
  if (static_cast<int>(w.size()) > settings_.switch_window) w.erase(w.begin());
  const double avg = std::accumulate(w.begin(), w.end(), 0.0) / static_cast<double>(w.size());
  row.a_ratio_avg = avg;
  const Energies en = model_.energies(s);
  row.e_stretch = en.stretch;
  row.e_bend = en.bend;
  row.e_contact = en.contact;
  row.e_external = en.external;
  row.e_kinetic = en.kinetic;
  log_.push_back(row);

  if (hist_.steps_in_mode < settings_.switch_min_steps) return;
  if (implicit && avg > settings_.switch_up) {
    hist_.mode = IntegrationMode::Explicit;
    // Start the explicit steps well inside RK4's stability region for the in-plane springs
    // (period 2 pi sqrt(m / ks)); the controller takes over from there.
    hist_.h = std::min(hist_.h, explicit_start_step());
  } else if (!implicit && avg < settings_.switch_down) {
    hist_.mode = IntegrationMode::Implicit;
  } else {
    return;
  }
  ++C.switches;
  hist_.steps_in_mode = 0;
  hist_.a_window.clear();  // the new mode's average starts afresh
  reset_history(s);  // the BDF order climbs again from 1; the FSAL stage is dropped
}

// Quasistatic steps of order 2-4 are held to bdf_growth_limit (zero-stability of variable-step
// BDF, order = points - 1 up to bdf_order), and every step to max_growth.
double Integrator::ratio_limit(bool implicit, std::size_t points) const {
  const int order = std::max(1, std::min(settings_.bdf_order, static_cast<int>(points) - 1));
  return implicit ? std::min(settings_.max_growth, bdf_growth_limit(order)) : settings_.max_growth;
}

void Integrator::prepare_attempt(const State& s, bool implicit) {
  if (before_step) {
    const double wb = omp_get_wtime();
    const bool changed = before_step(s);
    hist_.counters.wall_before_step += omp_get_wtime() - wb;
    if (changed) hist_.fsal.resize(0);
  }
  // Only the quasistatic step assembles Jacobians: explicit steps leave the pattern stale
  // through contact changes (its rebuild, a sort of every coupled node pair and a rebind of
  // every term, would otherwise follow each change of the candidate list). The Newton
  // system rebinds itself to a rebuilt pattern.
  if (implicit) model_.rebuild_pattern();
}

// The controller's proposal, held to the zero-stability growth limit of variable-step BDF
// (bdf_growth_limit) over the last step, which may have been shortened to land on an
// interval's end; the steps onto this interval's end are planned so that none is a sliver
// (step_toward.hpp).
double Integrator::plan_step(const State& s, double t_end, bool implicit, int rejections,
                             double proposal, double wall0) {
  const double max_ratio = ratio_limit(implicit, hist_.times.size());
  double first = proposal;
  if (implicit && hist_.times.size() >= 2)
    first = std::min(first, max_ratio * (hist_.times[0] - hist_.times[1]));
  const double h = step_toward(t_end - s.t, first, proposal, max_ratio,
                               rejections > 0 ? 0.0 : landing_tolerance(t_end));
  // A step that t cannot resolve would repeat forever: fail instead (the config's floor on
  // h_min makes this unreachable at the times of a protocol; it guards any other caller).
  if (!(s.t + h > s.t)) {
    std::ostringstream msg;
    msg << "step size h = " << h << " does not advance t = " << s.t
        << " (below its rounding); raise integrator.h_min";
    hist_.counters.wall_total += omp_get_wtime() - wall0;
    throw NumericalFailure(msg.str());
  }
  return h;
}

void Integrator::attempt(const State& s, double h, bool implicit, Attempt& a) {
  a = Attempt{};
  const double wa = omp_get_wtime();
  if (implicit) {
    ++hist_.counters.implicit_attempts;
    implicit_attempt(s, h, a);
    hist_.counters.wall_implicit += omp_get_wtime() - wa;
  } else {
    explicit_attempt(s, h, a);
    hist_.counters.wall_explicit += omp_get_wtime() - wa;
  }
}

void Integrator::grow_after_accept(const Attempt& a, double h, double proposal, bool implicit,
                                   int rejections) {
  const double exponent = implicit ? 1.0 / (a.order + 1) : 0.25;
  // The next step's history gains this step's point.
  const double growth = ratio_limit(implicit, hist_.times.size() + 1);
  // A step cut short of the proposal (to land on t_end, or by the growth limit) has a smaller
  // error than the proposal would have had (see `next` below).
  const bool shortened = h < proposal * (1 - 1e-12);
  double fac = a.err > 0 ? 0.9 * std::pow(a.err, -exponent) : growth;
  if (!implicit && !shortened) {
    // Explicit steps are mostly limited by stability (the stiff in-plane springs), where
    // the elementary controller above oscillates about the limit and rejects about every
    // other step. The PI controller (Gustafsson; Hairer-Wanner II, §IV.2) damps that with
    // the previous error: h_new = h 0.9 err^(-0.7/k) err_prev^(0.4/k), k = 4. (A shortened
    // step's error would pull both factors down: it uses the elementary one.)
    const double e = std::max(a.err, 1e-10);
    if (hist_.err_prev > 0) fac = 0.9 * std::pow(e, -0.7 / 4) * std::pow(hist_.err_prev, 0.4 / 4);
    hist_.err_prev = e;
  }
  if (rejections > 0) fac = std::min(fac, 1.0);  // no growth right after a rejection
  // Newton's contraction worsens as h grows: a step that took more than the target number
  // of iterations is close to the h where Newton fails, and doubling h from there costs a
  // failed attempt (up to newton_max_iters linear solves) and a cut by 4. Hold h one
  // iteration over the target, shrink it beyond (the error estimate alone cannot see this).
  if (implicit && a.newton_iters > settings_.newton_target)
    fac = std::min(fac, a.newton_iters == settings_.newton_target + 1 ? 1.0 : 0.7);
  // After a shortened step the proposal is the smaller of h * fac (the error-limited step
  // by the elementary controller, or h held / cut after slow Newton) and the proposal
  // grown by `growth`, not a growth from the shortened step; the next quasistatic step is
  // held to the growth limit over this one when it is taken (plan_step). Otherwise the step
  // grows from itself.
  const double next = shortened ? std::min(h * fac, proposal * growth) : h * std::min(fac, growth);
  hist_.h = std::clamp(next, settings_.h_min, settings_.h_max);
}

std::vector<std::pair<std::string, VecX>> Integrator::forces_by_term(const State& s) const {
  std::vector<std::pair<std::string, VecX>> out;
  for (const auto& e : model_.terms()) {
    VecX f = VecX::Zero(model_.num_dofs());
    e.term->add_force(s, f);
    out.emplace_back(e.term->name(), std::move(f));
  }
  return out;
}

std::string Integrator::forces_on_node(const State& s, Index node) const {
  if (node < 0 || 3 * node + 2 >= model_.num_dofs()) return {};
  std::vector<std::pair<double, std::string>> by_term;
  for (const auto& [name, f] : forces_by_term(s))
    by_term.emplace_back(f.segment<3>(3 * node).norm(), name);
  // Largest first, a NaN before any number (it is where the failure is).
  std::stable_sort(by_term.begin(), by_term.end(), [](const auto& a, const auto& b) {
    if (std::isnan(a.first) || std::isnan(b.first))
      return std::isnan(a.first) && !std::isnan(b.first);
    return a.first > b.first;
  });
  std::ostringstream out;
  out.precision(3);
  for (std::size_t i = 0; i < by_term.size(); ++i)
    out << (i ? ", " : "") << by_term[i].second << " " << by_term[i].first << " N";
  return out.str();
}

void Integrator::retry_after_rejection(const State& s, const Attempt& a, double h, bool implicit,
                                       double wall0) {
  auto& C = hist_.counters;
  double hn;
  std::string reason;
  if (a.ok) {
    ++C.rejected_error;
    const double exponent = implicit ? 1.0 / (a.order + 1) : 0.25;
    hn = h * std::clamp(0.9 * std::pow(a.err, -exponent), 0.1, 0.9);
    reason = "local error test failed repeatedly";
  } else {
    if (a.not_spd)
      ++C.rejected_not_spd;
    else if (a.newton_failed)
      ++C.rejected_newton;
    else
      ++C.rejected_other;
    hn = h / 4.0;
    reason = a.failure;
  }
  // A quasistatic step that fails (not SPD, Newton) even below the explicit step size
  // cannot be rescued by shrinking h further (the indefinite part of Hv does not vanish
  // as h -> 0 when springs are strongly compressed): hand over to the explicit mode, which
  // needs no SPD matrix, whatever switch_min_steps says.
  if (implicit && !a.ok && hn < explicit_start_step()) {
    hist_.mode = IntegrationMode::Explicit;
    hist_.steps_in_mode = 0;
    hist_.a_window.clear();
    ++C.switches;
    reset_history(s);
    hist_.h = std::min(h, explicit_start_step());
    return;
  }
  // A retry below h_min is made at h_min once; a step at h_min that fails ends the run.
  if (h <= settings_.h_min * (1 + 1e-12)) {
    std::ostringstream msg;
    msg << "integration failed at t = " << s.t << " with h = " << h << " (h_min "
        << settings_.h_min << ", " << (implicit ? "implicit" : "explicit")
        << " mode): " << reason << "; largest residual force at node " << a.worst_node;
    if (const std::string by_term = forces_on_node(s, a.worst_node); !by_term.empty())
      msg << " (by term at the step's start: " << by_term << ")";
    C.wall_total += omp_get_wtime() - wall0;
    throw NumericalFailure(msg.str());
  }
  hist_.h = std::max(hn, settings_.h_min);
}

// One accepted step after another until t_end: each step is prepared (contact refreshed),
// planned (controller, growth limits, landing on t_end), attempted, and either accepted (the
// next step size from its error) or retried smaller (or handed to the explicit mode).
void Integrator::advance_to(State& s, double t_end) {
  const double wall0 = omp_get_wtime();
  sync_history(s);
  const double t_eps = 1e-13 * std::max(1.0, std::abs(t_end));
  while (t_end - s.t > t_eps) {
    int rejections = 0;
    Attempt a;
    double h = 0;
    for (;;) {
      const bool implicit = hist_.mode == IntegrationMode::Implicit;
      prepare_attempt(s, implicit);
      const double proposal = hist_.h;
      h = plan_step(s, t_end, implicit, rejections, proposal, wall0);
      attempt(s, h, implicit, a);
      if (a.ok && a.err <= 1.0) {
        grow_after_accept(a, h, proposal, implicit, rejections);
        break;
      }
      ++rejections;
      retry_after_rejection(s, a, h, implicit, wall0);
    }
    s = std::move(a.next);
    if (hist_.mode == IntegrationMode::Explicit) hist_.fsal = std::move(a.fsal);
    push_history(s);
    after_accept(s, a, h, rejections);
  }
  hist_.counters.wall_total += omp_get_wtime() - wall0;
}

}  // namespace crumple
