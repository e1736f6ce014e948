// A protocol stage: what acts on the sheet between two stop conditions (docs/MODEL.md §11.1).
//
// A stage never touches solver internals. In begin() it adds external terms to the model
// (walls, pistons, tethers: see protocols/terms) through own(); done() is asked after every
// chunk of simulated time and says whether the stop condition (time, a geometric target, or
// quiescence) is met; end() removes the stage's terms. Stages of one cycle hand geometry to each
// other through the Apparatus (the roll stage leaves the roll's axis and radius for compress).
#pragma once

#include "protocols/apparatus.hpp"
#include "sim/model/sheet_model.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <random>
#include <string>

namespace crumple {

/// Facts about the sheet that stages need: sizes and constants in simulation units.
struct SheetInfo {
  double size = 0;    ///< side length (square) or diameter (disk)
  double area = 0;    ///< reference area
  double h_eff = 0;   ///< effective thickness sqrt(8 kb/ks)
  double ks = 0, kb = 0, mass = 0;
  double spacing = 0; ///< mean edge length
};

struct StageContext {
  SheetModel* model = nullptr;
  State* state = nullptr;
  SheetInfo sheet;
  Apparatus apparatus;
  int cycle = 1;          ///< 1-based
  double t_begin = 0;     ///< simulated time when the stage began
  std::mt19937_64 rng;    ///< the protocol's random stream (seeded by the run seed)
  /// Turns self-contact on or off (no-op when the run has no contact); stages that switch it
  /// off must switch it back on in end().
  std::function<void(bool)> set_contact = [](bool) {};

  /// Largest node speed relative to the best-fit rigid motion of the sheet (rigid_motion.hpp):
  /// a free sheet that drifts or spins as a whole is still quiescent in its shape.
  double max_deformation_speed() const;
  /// Kinetic energy of the current state.
  double kinetic_energy() const;
  /// Largest |F_i|/m over nodes: the acceleration the quasistatic solver leaves.
  double max_acceleration() const;
};

/// Stages are rebuilt from their parameters for every cycle. Everything a stage decides in
/// begin() must depend only on the context at its start (state, time, apparatus, random stream)
/// and its state changes in done() only on the time and state at that check: a resumed run
/// replays begin() and the last done() to rebuild it exactly.
class Stage {
 public:
  virtual ~Stage() = default;
  virtual std::string type() const = 0;
  virtual void begin(StageContext& ctx) = 0;
  /// Whether the stop condition is met; called after every chunk of simulated time.
  virtual bool done(StageContext& ctx) = 0;
  /// Removes the stage's terms (override to do more, e.g. record the apparatus).
  virtual void end(StageContext& ctx) { release_terms(ctx); }
  /// One line for the progress display: the stage's measure and its target.
  virtual std::string progress(const StageContext& ctx) const { return ""; }
  /// Fraction of the stage done, in [0, 1], or a negative number when unknown (for the ETA).
  virtual double fraction(const StageContext& ctx) const { return -1.0; }
  /// The compaction ratio (final / initial gap, the experiment's knob, docs/STATISTICS.md §1)
  /// that this stage imposes, from its resolved parameters, for stages that compact the sheet;
  /// nullopt for the others. Valid from begin() on (a protocol whose compaction changes from
  /// cycle to cycle may resolve it there). The run file records it per stage end and per cycle,
  /// so the analysis never has to find it in the stored configuration.
  virtual std::optional<double> compaction() const { return std::nullopt; }
  /// The in-plane axis a stage rolled the sheet about, in degrees from the x axis in [0, 180)
  /// (a and -a are the same roll), for stages that roll it; nullopt for the others. Valid from
  /// begin() on. Recorded per stage end: the roll's axis is a random draw of the protocol, and
  /// which orientations a sheet was rolled in drives its crease growth (docs/studies/roll_side/).
  virtual std::optional<double> roll_axis_deg() const { return std::nullopt; }
  /// Cap on the stage's simulated duration (the stage ends there even if its target is not
  /// reached; the runner warns).
  double max_duration = 1e30;
  /// Simulated time between two done() checks.
  double check_interval = 0.01;

 protected:
  void own(StageContext& ctx, std::shared_ptr<ForceTerm> term, TermKind kind = TermKind::External);
  void release_terms(StageContext& ctx);

 private:
  std::vector<std::shared_ptr<ForceTerm>> terms_;
};

}  // namespace crumple
