// A tiny physical sheet and an in-memory RunSink for runner tests: a 10 cm square grid with the
// paper's material (0.25 mm, Y = 1 GPa) and mass scaling, as the protocol files use.
#pragma once

#include "protocols/integrator_stepper.hpp"
#include "protocols/runner.hpp"
#include "tests/support/grid_mesh.hpp"

#include <cmath>
#include <optional>

namespace crumple::testing {

struct TinySheet {
  Mesh mesh;
  ModelParams params;
  SheetInfo info;
  IntegratorSettings settings;

  explicit TinySheet(int side = 10, double size = 0.1) {
    mesh = grid_mesh(side, side, size, size, 0.15, 2);
    const double h = 2.5e-4, Y = 1e9, rho = 1400, mass_scale = 1e4;
    const double kappa = Y * h * h * h / (12.0 * (1.0 - 1.0 / 9.0));
    params.ks = std::sqrt(3.0) / 2.0 * Y * h;
    params.kb = 2.0 * kappa / std::sqrt(3.0);
    params.mass = mass_scale * rho * h * size * size / mesh.num_nodes();
    params.b_iso = 0.05 * std::sqrt(params.ks * params.mass);
    params.b_int = 0.1 * std::sqrt(params.ks * params.mass);
    info.size = size;
    info.area = mesh.total_area();
    info.h_eff = std::sqrt(8.0 * params.kb / params.ks);
    info.ks = params.ks, info.kb = params.kb, info.mass = params.mass;
    info.spacing = mesh.mean_edge_length();
    settings.plastic_c0 = 0.1;
    settings.plastic_rate = 1e4;  // the protocols' rate-independent regime (docs/CONFIG.md)
  }
};

struct MemorySink : RunSink {
  std::vector<State> frames;
  std::vector<std::string> frame_stages;
  std::vector<State> cycles;
  std::vector<Checkpoint> checkpoints;
  struct StageEnd {
    int cycle, index;
    std::string type;
    State state;
    std::optional<double> compaction;  ///< what the stage reported (Stage::compaction())
    std::optional<double> roll_axis_deg;  ///< likewise (Stage::roll_axis_deg())
  };
  std::vector<StageEnd> stage_ends;
  int kill_after = -1;  ///< throw Killed after this many checkpoints (simulates SIGKILL)
  struct Killed {};
  void frame(const State& s, const std::string& stage, int) override {
    frames.push_back(s);
    frame_stages.push_back(stage);
  }
  void stage_end(int cycle, int index, const Stage& stage, const State& s) override {
    stage_ends.push_back({cycle, index, stage.type(), s, stage.compaction(), stage.roll_axis_deg()});
  }
  void cycle_end(int, const State& s) override { cycles.push_back(s); }
  void checkpoint(const Checkpoint& c) override {
    checkpoints.push_back(c);
    if (kill_after >= 0 && static_cast<int>(checkpoints.size()) >= kill_after) throw Killed{};
  }
};

}  // namespace crumple::testing
