// Synthetic inputs for the analysis tests: a regularly triangulated square mesh with its edges
// and hinges (built here, independent of the simulator's mesh code), and a run file written with
// the HDF5 C++ API in the layout of docs/FILE_FORMAT.md (with /stage_ends and the cycles'
// compaction ratios when asked), optionally broken on purpose.
#pragma once

#include "analysis/io/run_data.hpp"

#include <H5Cpp.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace crumple::analysis::synth {

/// (k+1) x (k+1) nodes on [0, side]^2, every square split along the same diagonal, so the grid
/// lines x = i side/k and y = j side/k are chains of mesh edges.
inline MeshData square_grid_mesh(int k, double side) {
  MeshData m;
  const double d = side / k;
  for (int j = 0; j <= k; ++j)
    for (int i = 0; i <= k; ++i) {
      m.ref_positions.push_back({i * d, j * d, 0.0});
      m.boundary.push_back(i == 0 || j == 0 || i == k || j == k);
    }
  auto id = [k](int i, int j) { return static_cast<std::int32_t>(j * (k + 1) + i); };
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  std::map<std::pair<int, int>, std::vector<int>> opposite;  // edge -> opposite vertices
  std::map<std::pair<int, int>, int> index;
  for (const auto& t : m.triangles)
    for (int a = 0; a < 3; ++a) {
      const int u = t[a], v = t[(a + 1) % 3], w = t[(a + 2) % 3];
      const std::pair<int, int> e{std::min(u, v), std::max(u, v)};
      if (!index.count(e)) {
        index[e] = static_cast<int>(m.edges.size());
        m.edges.push_back({e.first, e.second});
        const auto& p = m.ref_positions[static_cast<std::size_t>(u)];
        const auto& q = m.ref_positions[static_cast<std::size_t>(v)];
        m.rest_lengths.push_back(std::hypot(p[0] - q[0], p[1] - q[1]));
      }
      opposite[e].push_back(w);
    }
  for (const auto& [e, opp] : opposite)
    if (opp.size() == 2) {
      m.hinges.push_back({e.first, e.second, opp[0], opp[1]});
      m.hinge_edge.push_back(index[e]);
    }
  return m;
}

/// Hinges whose edge lies on the line x = c (axis 0) or y = c (axis 1), within tol.
inline std::vector<std::size_t> hinges_on_line(const MeshData& m, int axis, double c,
                                               double tol = 1e-9) {
  std::vector<std::size_t> out;
  for (std::size_t h = 0; h < m.hinges.size(); ++h) {
    const auto& e = m.edges[static_cast<std::size_t>(m.hinge_edge[h])];
    if (std::abs(m.ref_positions[static_cast<std::size_t>(e[0])][static_cast<std::size_t>(axis)] - c) < tol &&
        std::abs(m.ref_positions[static_cast<std::size_t>(e[1])][static_cast<std::size_t>(axis)] - c) < tol)
      out.push_back(h);
  }
  return out;
}

/// Hinges whose edge lies on the straight segment from (ax, ay) to (bx, by), ends included.
inline std::vector<std::size_t> hinges_on_segment(const MeshData& m, double ax, double ay,
                                                  double bx, double by, double tol = 1e-9) {
  const double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
  auto on = [&](std::int32_t node) {
    const auto& q = m.ref_positions[static_cast<std::size_t>(node)];
    const double s = ((q[0] - ax) * dx + (q[1] - ay) * dy) / len2;
    const double cross = (q[0] - ax) * dy - (q[1] - ay) * dx;
    return std::abs(cross) < tol && s > -tol && s < 1 + tol;
  };
  std::vector<std::size_t> out;
  for (std::size_t h = 0; h < m.hinges.size(); ++h) {
    const auto& e = m.edges[static_cast<std::size_t>(m.hinge_edge[h])];
    if (on(e[0]) && on(e[1])) out.push_back(h);
  }
  return out;
}

struct WriteOptions {
  bool with_cycles_group = true;
  bool wrong_p_shape = false;
  bool omit_rest_lengths = false;
  std::string config = "protocol:\n  stages:\n    - type: roll\n    - type: compress\n"
                       "      compaction: 0.27\n";
  std::vector<StageEndData> stage_ends;  ///< written as /stage_ends when not empty
  bool stage_group_without_records = false;  ///< an empty /stage_ends group
  bool stage_end_without_cycle_attr = false; ///< malformed: the first record lacks @cycle
  /// /cycles/NNNN@compaction of cycle 1, 2, ... (NaN: no compacting stage); none written when
  /// empty, as in files from before it was recorded.
  std::vector<double> cycle_compaction;
};

template <class T, std::size_t K>
void write_rows(H5::Group& g, const std::string& name, const std::vector<std::array<T, K>>& rows,
                const H5::PredType& type) {
  const hsize_t dims[2] = {rows.size(), K};
  H5::DataSpace sp(2, dims);
  g.createDataSet(name, type, sp).write(rows.data(), type);
}

template <class T>
void write_vec(H5::Group& g, const std::string& name, const std::vector<T>& v,
               const H5::PredType& type) {
  const hsize_t dims[1] = {v.size()};
  H5::DataSpace sp(1, dims);
  g.createDataSet(name, type, sp).write(v.data(), type);
}

/// Writes a run file with one /cycles/NNNN group per entry of `cycles_p` (cycle 1, 2, ...).
inline void write_run(const std::string& path, const MeshData& m,
                      const std::vector<std::vector<double>>& cycles_p,
                      const WriteOptions& o = {}) {
  H5::H5File f(path, H5F_ACC_TRUNC);
  H5::Group meta = f.createGroup("meta");
  const double unit = 1.0;
  meta.createAttribute("length_unit_m", H5::PredType::NATIVE_DOUBLE, H5::DataSpace())
      .write(H5::PredType::NATIVE_DOUBLE, &unit);
  H5::StrType st(H5::PredType::C_S1, H5T_VARIABLE);
  meta.createAttribute("program_version", st, H5::DataSpace()).write(st, std::string("test"));
  f.createDataSet("config", st, H5::DataSpace()).write(o.config, st);
  H5::Group g = f.createGroup("mesh");
  write_rows(g, "ref_positions", m.ref_positions, H5::PredType::NATIVE_DOUBLE);
  write_rows(g, "triangles", m.triangles, H5::PredType::NATIVE_INT32);
  write_rows(g, "edges", m.edges, H5::PredType::NATIVE_INT32);
  if (!o.omit_rest_lengths) write_vec(g, "rest_lengths", m.rest_lengths, H5::PredType::NATIVE_DOUBLE);
  write_rows(g, "hinges", m.hinges, H5::PredType::NATIVE_INT32);
  write_vec(g, "hinge_edge", m.hinge_edge, H5::PredType::NATIVE_INT32);
  write_vec(g, "boundary", m.boundary, H5::PredType::NATIVE_UINT8);
  if (!o.with_cycles_group) return;
  H5::Group cg = f.createGroup("cycles");
  for (std::size_t c = 0; c < cycles_p.size(); ++c) {
    char name[24];
    std::snprintf(name, sizeof name, "%04zu", c + 1);
    H5::Group g1 = cg.createGroup(name);
    auto p = cycles_p[c];
    if (o.wrong_p_shape) p.pop_back();
    write_vec(g1, "p", p, H5::PredType::NATIVE_DOUBLE);
    write_rows(g1, "x", m.ref_positions, H5::PredType::NATIVE_DOUBLE);
    if (c < o.cycle_compaction.size())
      g1.createAttribute("compaction", H5::PredType::NATIVE_DOUBLE, H5::DataSpace())
          .write(H5::PredType::NATIVE_DOUBLE, &o.cycle_compaction[c]);
  }
  if (o.stage_ends.empty() && !o.stage_group_without_records) return;
  H5::Group sg = f.createGroup("stage_ends");
  for (std::size_t k = 0; k < o.stage_ends.size(); ++k) {
    const StageEndData& s = o.stage_ends[k];
    char name[24];
    std::snprintf(name, sizeof name, "%06zu", k);
    H5::Group g1 = sg.createGroup(name);
    write_vec(g1, "p", s.p, H5::PredType::NATIVE_DOUBLE);
    const H5::DataSpace scalar;
    g1.createAttribute("t", H5::PredType::NATIVE_DOUBLE, scalar)
        .write(H5::PredType::NATIVE_DOUBLE, &s.t);
    if (!(o.stage_end_without_cycle_attr && k == 0))
      g1.createAttribute("cycle", H5::PredType::NATIVE_INT32, scalar)
          .write(H5::PredType::NATIVE_INT32, &s.cycle);
    g1.createAttribute("stage_index", H5::PredType::NATIVE_INT32, scalar)
        .write(H5::PredType::NATIVE_INT32, &s.stage_index);
    g1.createAttribute("stage", st, scalar).write(st, s.stage);
  }
}

}  // namespace crumple::analysis::synth
