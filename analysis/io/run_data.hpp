// The part of a run file (docs/FILE_FORMAT.md) that the analysis needs, held in memory.
//
// Filled by read_run() (io/run_reader.hpp); everything downstream works on this struct only, so
// the analysis never depends on the simulator's writer (sim/io).
#pragma once

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace crumple::analysis {

/// The flat reference mesh. Lengths are in simulation units (see RunData::length_unit_m).
struct MeshData {
  std::vector<std::array<double, 3>> ref_positions;    ///< n x 3 flat reference positions
  std::vector<std::array<std::int32_t, 3>> triangles;  ///< t x 3 node indices
  std::vector<std::array<std::int32_t, 2>> edges;      ///< e x 2 node indices
  std::vector<double> rest_lengths;                    ///< e rest lengths
  std::vector<std::array<std::int32_t, 4>> hinges;     ///< h x 4: shared edge x0,x1, then x2,x3
  std::vector<std::int32_t> hinge_edge;                ///< h: edge index of each hinge
  std::vector<std::uint8_t> boundary;                  ///< n: 1 on the sheet border
};

/// The plastic field at the end of one completed protocol cycle (/cycles/NNNN).
struct CycleData {
  int cycle = 0;          ///< cycle number, from 1
  std::vector<double> p;  ///< h plastic rest curvatures (2 sin(theta/2) units)
  /// /cycles/NNNN@compaction: the compaction ratio the cycle's compacting stage imposed;
  /// nullopt when the attribute is NaN (no stage of the cycle compacts the sheet) or absent.
  std::optional<double> compaction;
  bool compaction_recorded = false;  ///< the attribute exists (files before it lack it)
};

/// The plastic field at the end of one finished protocol stage (/stage_ends/NNNNNN).
struct StageEndData {
  int cycle = 0;          ///< cycle the stage belongs to, from 1
  int stage_index = 0;    ///< 0-based position of the stage in its cycle
  std::string stage;      ///< stage type: "roll", "compress", "release", "unfold", ...
  double t = 0.0;         ///< simulation time at the end of the stage
  std::vector<double> p;  ///< h plastic rest curvatures
};

struct RunData {
  std::string path;
  nlohmann::json meta = nlohmann::json::object();  ///< /meta attributes (scalars only)
  std::string config_yaml;                         ///< /config text, empty when absent
  double length_unit_m = 1.0;                      ///< metres per simulation length unit
  MeshData mesh;
  std::vector<CycleData> cycles;  ///< sorted by cycle number, never empty after read_run()
  std::vector<StageEndData> stage_ends;  ///< in run order; empty in files without /stage_ends
  bool has_stage_ends = false;           ///< the file has a /stage_ends group
  std::vector<std::string> warnings;  ///< non-fatal problems found while reading
};

}  // namespace crumple::analysis
