// The HDF5 run file (run_file.hpp, docs/FILE_FORMAT.md); its XDMF sidecars are xdmf.cpp.
#include "sim/io/run_file.hpp"

#include "sim/core/errors.hpp"
#include "sim/io/h5.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

namespace crumple {

namespace {

std::vector<double> to_vec(const VecX& v) { return {v.data(), v.data() + v.size()}; }
VecX to_eigen(const std::vector<double>& v) { return Eigen::Map<const VecX>(v.data(), v.size()); }
std::vector<hsize_t> nx3(const VecX& v) { return {static_cast<hsize_t>(v.size() / 3), 3}; }

// The units of the datasets (docs/FILE_FORMAT.md): SI, lengths in the mesh's unit, which is
// the metre (/meta@length_unit_m = 1); a dimensionless number, count, index or flag is "1".
struct Units {
  std::string length, velocity, energy;
  explicit Units(double length_unit_m) {
    if (length_unit_m == 1.0) {
      length = "m", velocity = "m/s", energy = "J";
    } else {  // never so today; said in full rather than mislabelled
      std::ostringstream os;
      os << "(" << std::setprecision(12) << length_unit_m << " m)";
      length = os.str(), velocity = length + "/s", energy = "kg " + length + "^2/s^2";
    }
  }
};
constexpr const char* kDimensionless = "1";

// The hinges a viewer sees as creases: |p| > threshold (sim/model/crease_rule.hpp). With no
// threshold (NaN: a record from before the masks) every hinge is marked 0.
std::vector<std::uint8_t> crease_mask(const VecX& p, double threshold) {
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(p.size()), 0);
  for (Index i = 0; i < p.size(); ++i) mask[static_cast<std::size_t>(i)] = std::abs(p[i]) > threshold;
  return mask;
}

void write_state(H5::Group& g, const State& s, const Units& u) {
  h5::write(g, "x", to_vec(s.x), nx3(s.x));
  h5::units(g, "x", u.length);
  h5::write(g, "v", to_vec(s.v), nx3(s.v));
  h5::units(g, "v", u.velocity);
  h5::write(g, "p", to_vec(s.p));
  h5::units(g, "p", kDimensionless);
  h5::attr(g, "t", s.t);
}
/// Every shape, index and value read from a file is checked against the mesh before use: a
/// malformed file is an InputError naming the file and the dataset, never an out-of-bounds read.
struct Checker {
  const std::string& file;
  [[noreturn]] void fail(const std::string& dataset, const std::string& what) const {
    throw InputError(file + ": " + dataset + ": " + what);
  }
  void finite(const std::string& dataset, const VecX& v) const {
    if (!v.allFinite()) fail(dataset, "holds non-finite values");
  }
  void length(const std::string& dataset, const VecX& v, Index n, const char* what) const {
    if (v.size() != n)
      fail(dataset, std::to_string(v.size()) + " values, expected " + std::to_string(n) + " (" +
                        what + ")");
  }
};

/// A stored state at `name` (a group path for messages), checked against n nodes and m hinges.
State read_state(const H5::Group& g, const std::string& name, const Checker& check, Index n,
                 Index m) {
  State s;
  s.x = to_eigen(h5::read_doubles(g, "x"));
  s.v = to_eigen(h5::read_doubles(g, "v"));
  s.p = to_eigen(h5::read_doubles(g, "p"));
  s.t = h5::attr_double(g, "t");
  check.length(name + "/x", s.x, 3 * n, "3 per mesh node");
  check.length(name + "/v", s.v, 3 * n, "3 per mesh node");
  check.length(name + "/p", s.p, m, "one per hinge");
  check.finite(name + "/x", s.x);
  check.finite(name + "/v", s.v);
  check.finite(name + "/p", s.p);
  if (!std::isfinite(s.t)) check.fail(name + "@t", "not finite");
  return s;
}
}  // namespace

std::string numbered(long k, int width) {
  std::ostringstream os;
  os << std::setw(width) << std::setfill('0') << k;
  return os.str();
}

namespace {

void write_mesh(H5::Group& root, const Mesh& m, const Units& u) {
  H5::Group g = h5::group(root, "mesh");
  const Index n = m.num_nodes();
  std::vector<double> ref(3 * n);
  for (Index i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) ref[3 * i + d] = m.ref(d, i);
  h5::write(g, "ref_positions", ref, {static_cast<hsize_t>(n), 3});
  std::vector<std::int32_t> tri, edges, hinges, hinge_edge;
  for (const auto& t : m.triangles) tri.insert(tri.end(), t.begin(), t.end());
  for (const auto& e : m.edges) edges.insert(edges.end(), e.begin(), e.end());
  std::vector<double> factor;
  for (const auto& h : m.hinges) {
    hinges.insert(hinges.end(), h.nodes.begin(), h.nodes.end());
    hinge_edge.push_back(h.edge);
    factor.push_back(h.rest_factor);
  }
  h5::write(g, "triangles", tri, {m.triangles.size(), 3});
  h5::write(g, "edges", edges, {m.edges.size(), 2});
  h5::write(g, "rest_lengths", to_vec(m.rest_length));
  h5::write(g, "hinges", hinges, {m.hinges.size(), 4});
  h5::write(g, "hinge_edge", hinge_edge);
  h5::write(g, "hinge_factor", factor);
  h5::write(g, "boundary", m.boundary);
  for (const char* name : {"triangles", "edges", "hinges", "hinge_edge", "hinge_factor", "boundary"})
    h5::units(g, name, kDimensionless);
  h5::units(g, "ref_positions", u.length);
  h5::units(g, "rest_lengths", u.length);
  h5::attr(g, "shape", m.shape);
}

Mesh read_mesh(const H5::Group& root, const Checker& check) {
  H5::Group g = root.openGroup("mesh");
  std::vector<hsize_t> d;
  const auto ref = h5::read_doubles(g, "ref_positions", &d);
  if (d.size() != 2 || d[1] != 3 || d[0] < 3)
    check.fail("/mesh/ref_positions", "expected an N x 3 array of N >= 3 node positions");
  Eigen::Matrix3Xd pos(3, d[0]);
  for (hsize_t i = 0; i < d[0]; ++i)
    for (int k = 0; k < 3; ++k) pos(k, i) = ref[3 * i + k];
  if (!pos.allFinite()) check.fail("/mesh/ref_positions", "holds non-finite values");
  std::vector<hsize_t> dt;
  const auto tri = h5::read_ints(g, "triangles", &dt);
  if (dt.size() != 2 || dt[1] != 3 || dt[0] == 0)
    check.fail("/mesh/triangles", "expected an M x 3 array of M >= 1 triangles");
  const auto n = static_cast<std::int64_t>(d[0]);
  for (const std::int32_t v : tri)
    if (v < 0 || v >= n)
      check.fail("/mesh/triangles", "node index " + std::to_string(v) + " out of range [0, " +
                                        std::to_string(n) + ")");
  std::vector<std::array<Index, 3>> tris(tri.size() / 3);
  for (std::size_t t = 0; t < tris.size(); ++t) tris[t] = {tri[3 * t], tri[3 * t + 1], tri[3 * t + 2]};
  try {
    return build_mesh(std::move(pos), std::move(tris), h5::attr_string(g, "shape"));
  } catch (const std::invalid_argument& e) {  // e.g. an edge shared by three triangles
    check.fail("/mesh/triangles", e.what());
  }
}

// A restart block (sim/model/restart_data.hpp) as the group `name`: numbers and texts as
// attributes, arrays as datasets, states as groups. Whose entries they are is not the file's
// concern; reading takes each attribute by its HDF5 type class.
// Its arrays are the owners' encodings (the integrator's history mixes positions, velocities
// and step sizes), so their units say so rather than guess.
void write_restart(H5::Group& root, const std::string& name, const RestartData& d,
                   const Units& u) {
  H5::Group g = h5::group(root, name);
  for (const auto& [k, v] : d.ints) h5::attr(g, k, v);
  for (const auto& [k, v] : d.reals) h5::attr(g, k, v);
  for (const auto& [k, v] : d.texts) h5::attr(g, k, v);
  for (const auto& [k, v] : d.arrays) {
    h5::write(g, k, v);
    h5::units(g, k, "mixed (restart data)");
  }
  for (const auto& [k, v] : d.states) {
    H5::Group sg = h5::group(g, k);
    write_state(sg, v, u);
  }
}

RestartData read_restart(const H5::Group& root, const std::string& name, const Checker& check,
                         Index n, Index m) {
  H5::Group g = root.openGroup(name);
  const std::string at = "/" + name;
  RestartData d;
  d.origin = check.file + ": " + at;
  for (int k = 0; k < g.getNumAttrs(); ++k) {
    const H5::Attribute a = g.openAttribute(static_cast<unsigned>(k));
    const std::string key = a.getName();
    switch (a.getTypeClass()) {
      case H5T_INTEGER: d.ints[key] = h5::attr_int(g, key); break;
      case H5T_FLOAT: d.reals[key] = h5::attr_double(g, key); break;
      case H5T_STRING: d.texts[key] = h5::attr_string(g, key); break;
      default: check.fail(at + "@" + key, "neither a number nor a text");
    }
  }
  for (const auto& key : h5::members(g)) {
    if (g.childObjType(key) == H5O_TYPE_GROUP)
      d.states[key] = read_state(g.openGroup(key), at + "/" + key, check, n, m);
    else
      d.arrays[key] = h5::read_doubles(g, key);
  }
  return d;
}

// The integrator's counters as attributes of /log, one name per field.
struct SummaryField {
  const char* name;
  long IntegratorSummary::*count;
  double IntegratorSummary::*seconds;
};
constexpr SummaryField kSummaryFields[] = {
    {"steps_implicit", &IntegratorSummary::steps_implicit, nullptr},
    {"steps_explicit", &IntegratorSummary::steps_explicit, nullptr},
    {"switches", &IntegratorSummary::switches, nullptr},
    {"implicit_attempts", &IntegratorSummary::implicit_attempts, nullptr},
    {"newton_iters", &IntegratorSummary::newton_iters, nullptr},
    {"cg_iters", &IntegratorSummary::cg_iters, nullptr},
    {"rejected_error", &IntegratorSummary::rejected_error, nullptr},
    {"rejected_newton", &IntegratorSummary::rejected_newton, nullptr},
    {"rejected_not_spd", &IntegratorSummary::rejected_not_spd, nullptr},
    {"rejected_other", &IntegratorSummary::rejected_other, nullptr},
    {"wall_total", nullptr, &IntegratorSummary::wall_total},
    {"wall_implicit", nullptr, &IntegratorSummary::wall_implicit},
    {"wall_explicit", nullptr, &IntegratorSummary::wall_explicit},
    {"wall_linear", nullptr, &IntegratorSummary::wall_linear},
    {"wall_assembly", nullptr, &IntegratorSummary::wall_assembly},
    {"wall_before_step", nullptr, &IntegratorSummary::wall_before_step},
};

void write_summary(H5::Group& log, const IntegratorSummary& s) {
  for (const SummaryField& f : kSummaryFields) {
    if (f.count) h5::attr(log, f.name, std::int64_t{s.*f.count});
    else h5::attr(log, f.name, s.*f.seconds);
  }
  h5::attr(log, "summary", s.text());
}

std::optional<IntegratorSummary> read_summary(const H5::Group& log) {
  if (!log.attrExists(kSummaryFields[0].name)) return std::nullopt;
  IntegratorSummary s;
  for (const SummaryField& f : kSummaryFields) {
    if (f.count) s.*f.count = static_cast<long>(h5::attr_int(log, f.name));
    else s.*f.seconds = h5::attr_double(log, f.name);
  }
  return s;
}

// Contact and output costs as attributes of /log, beside the integrator's counters.
void write_costs(H5::Group& log, const RunCosts& c) {
  h5::attr(log, "contact_search_s", c.contact_search_s);
  h5::attr(log, "contact_eval_s", c.contact_eval_s);
  h5::attr(log, "contact_searches", std::int64_t{c.contact_searches});
  h5::attr(log, "output_s", c.output_s);
}

std::optional<RunCosts> read_costs(const H5::Group& log) {
  if (!log.attrExists("output_s")) return std::nullopt;
  RunCosts c;
  c.contact_search_s = h5::attr_double(log, "contact_search_s");
  c.contact_eval_s = h5::attr_double(log, "contact_eval_s");
  c.contact_searches = static_cast<long>(h5::attr_int(log, "contact_searches"));
  c.output_s = h5::attr_double(log, "output_s");
  return c;
}

template <class F>
std::vector<double> log_column(const std::vector<LogRow>& log, F f) {
  std::vector<double> v;
  v.reserve(log.size());
  for (const auto& r : log) v.push_back(f(r));
  return v;
}

}  // namespace

// The file is built in memory (HDF5's core driver, no backing store) and written out with
// plain POSIX calls: HDF5 1.10 crashes closing a file whose writes failed (a full disk, a file
// size limit), while a failed write() is simply an error to report.
namespace {

// A guess of the file's size, the core driver's allocation increment (so that it grows a few
// times, not once per megabyte).
std::size_t size_estimate(const RunRecord& r) {
  const std::size_t n = r.mesh.num_nodes(), m = r.mesh.num_hinges();
  const std::size_t state = 8 * (6 * n + m);
  return (1u << 20) + r.frames.size() * state + r.cycles.size() * (8 * (3 * n + m) + m) +
         r.stage_ends.size() * 8 * m + r.log.size() * 100 + 3 * state;
}

void write_all(H5::H5File& file, const RunRecord& r);

void write_bytes(const std::string& path, const std::vector<char>& bytes) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) throw OutputError(path + ": cannot create the file (" + std::strerror(errno) + ")");
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t k = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) {
      const std::string why = k < 0 ? std::strerror(errno) : "no progress";
      ::close(fd);
      ::unlink(path.c_str());
      throw OutputError(path + ": cannot write the run file (" + why + ", " +
                        std::to_string(done) + " of " + std::to_string(bytes.size()) +
                        " bytes written)");
    }
    done += static_cast<std::size_t>(k);
  }
  if (::close(fd) != 0) {
    const std::string why = std::strerror(errno);
    ::unlink(path.c_str());
    throw OutputError(path + ": cannot write the run file (" + why + " on close)");
  }
}
}  // namespace

double cycle_compaction(const std::vector<StageEndRecord>& stage_ends, int cycle) {
  double out = std::numeric_limits<double>::quiet_NaN();
  for (const auto& e : stage_ends)
    if (e.cycle == cycle && e.compaction && (std::isnan(out) || *e.compaction < out))
      out = *e.compaction;
  return out;
}

void write_run_file(const std::string& path, const RunRecord& r) {
  H5::Exception::dontPrint();
  std::vector<char> image;
  try {
    H5::FileAccPropList fapl;
    fapl.setCore(size_estimate(r), false);
    H5::H5File file(path, H5F_ACC_TRUNC, H5::FileCreatPropList::DEFAULT, fapl);
    write_all(file, r);
    file.flush(H5F_SCOPE_GLOBAL);
    const ssize_t size = H5Fget_file_image(file.getId(), nullptr, 0);
    if (size < 0) throw OutputError(path + ": cannot build the run file's image");
    image.resize(static_cast<std::size_t>(size));
    if (H5Fget_file_image(file.getId(), image.data(), image.size()) != size)
      throw OutputError(path + ": cannot build the run file's image");
    file.close();
  } catch (const H5::Exception& e) {
    throw OutputError(path + ": cannot build the run file (" + e.getDetailMsg() + ")");
  }
  write_bytes(path, image);
}

namespace {
// What the simulated clock means (every time in the file: /log/t, the frames' and cycles' t).
std::string time_note(const RunMeta& m) {
  std::ostringstream os;
  os << "simulated time in s; the node masses are material.mass_scale = ";
  if (std::isnan(m.mass_scale)) os << "(not recorded)";
  else os << std::setprecision(6) << m.mass_scale;
  os << " times the sheet's, which slows inertial motion by its square root, so elastic waves "
        "and the explicit steps are that much slower than in the real sheet while the "
        "quasistatic path is unchanged (docs/MODEL.md, section 8)";
  return os.str();
}

void write_all(H5::H5File& file, const RunRecord& r) {
  H5::Group root = file.openGroup("/");
  H5::Group meta = h5::group(root, "meta");
  const RunMeta& m = r.meta;
  h5::attr(meta, "program_version", m.program_version);
  h5::attr(meta, "git_revision", m.git_revision);
  h5::attr(meta, "seed", static_cast<std::int64_t>(m.seed));
  h5::attr(meta, "threads", std::int64_t{m.threads});
  h5::attr(meta, "start_time", m.start_time);
  h5::attr(meta, "end_time", m.end_time);
  h5::attr(meta, "status", m.status);
  h5::attr(meta, "length_unit_m", m.length_unit_m);
  h5::attr(meta, "ks", m.ks);
  h5::attr(meta, "kb", m.kb);
  h5::attr(meta, "mass", m.mass);
  h5::attr(meta, "h_eff", m.h_eff);
  h5::attr(meta, "mass_scale", m.mass_scale);
  h5::attr(meta, "crease_threshold", m.crease_threshold);
  h5::attr(meta, "time_note", time_note(m));
  h5::write_string(root, "config", r.config);
  h5::units(root, "config", "none");
  const Units u(m.length_unit_m);
  write_mesh(root, r.mesh, u);

  H5::Group frames = h5::group(root, "frames");
  for (std::size_t k = 0; k < r.frames.size(); ++k) {
    H5::Group g = h5::group(frames, numbered(static_cast<long>(k), 6));
    write_state(g, r.frames[k].state, u);
    h5::write(g, "crease", crease_mask(r.frames[k].state.p, m.crease_threshold));
    h5::units(g, "crease", kDimensionless);
    h5::attr(g, "stage", r.frames[k].stage);
    h5::attr(g, "cycle", std::int64_t{r.frames[k].cycle});
    h5::attr(g, "step", std::int64_t{r.frames[k].step});
  }
  H5::Group cycles = h5::group(root, "cycles");
  for (const auto& c : r.cycles) {
    H5::Group g = h5::group(cycles, numbered(c.cycle, 4));
    h5::write(g, "x", to_vec(c.x), nx3(c.x));
    h5::units(g, "x", u.length);
    h5::write(g, "p", to_vec(c.p));
    h5::units(g, "p", kDimensionless);
    h5::write(g, "crease", crease_mask(c.p, m.crease_threshold));
    h5::units(g, "crease", kDimensionless);
    h5::attr(g, "t", c.t);
    h5::attr(g, "cycle", std::int64_t{c.cycle});
    h5::attr(g, "compaction", c.compaction);
  }
  H5::Group stage_ends = h5::group(root, "stage_ends");
  for (std::size_t k = 0; k < r.stage_ends.size(); ++k) {
    const StageEndRecord& e = r.stage_ends[k];
    H5::Group g = h5::group(stage_ends, numbered(static_cast<long>(k), 6));
    h5::write(g, "p", to_vec(e.p));
    h5::units(g, "p", kDimensionless);
    h5::attr(g, "t", e.t);
    h5::attr(g, "cycle", std::int64_t{e.cycle});
    h5::attr(g, "stage", e.stage);
    h5::attr(g, "stage_index", std::int64_t{e.stage_index});
    h5::attr(g, "wall", e.wall);
    if (e.compaction) h5::attr(g, "compaction", *e.compaction);
    if (e.roll_axis_deg) h5::attr(g, "roll_axis_deg", *e.roll_axis_deg);
  }
  H5::Group log = h5::group(root, "log");
  h5::write(log, "t", log_column(r.log, [](const LogRow& x) { return x.t; }));
  h5::write(log, "h", log_column(r.log, [](const LogRow& x) { return x.h; }));
  h5::write(log, "a_ratio", log_column(r.log, [](const LogRow& x) { return x.a_ratio; }));
  h5::write(log, "a_ratio_avg", log_column(r.log, [](const LogRow& x) { return x.a_ratio_avg; }));
  std::vector<std::int8_t> mode;
  std::vector<std::int32_t> newton, cg, rej, order;
  for (const auto& x : r.log) {
    mode.push_back(static_cast<std::int8_t>(x.mode));
    newton.push_back(x.newton_iters);
    cg.push_back(x.cg_iters);
    rej.push_back(x.rejections);
    order.push_back(x.order);
  }
  h5::write(log, "mode", mode);
  h5::write(log, "order", order);
  h5::write(log, "newton_iters", newton);
  h5::write(log, "cg_iters", cg);
  h5::write(log, "rejections", rej);
  h5::write(log, "e_stretch", log_column(r.log, [](const LogRow& x) { return x.e_stretch; }));
  h5::write(log, "e_bend", log_column(r.log, [](const LogRow& x) { return x.e_bend; }));
  h5::write(log, "e_contact", log_column(r.log, [](const LogRow& x) { return x.e_contact; }));
  h5::write(log, "e_external", log_column(r.log, [](const LogRow& x) { return x.e_external; }));
  h5::write(log, "e_kinetic", log_column(r.log, [](const LogRow& x) { return x.e_kinetic; }));
  for (const char* name : {"t", "h"}) h5::units(log, name, "s");
  for (const char* name : {"e_stretch", "e_bend", "e_contact", "e_external", "e_kinetic"})
    h5::units(log, name, u.energy);
  for (const char* name : {"a_ratio", "a_ratio_avg", "mode", "order", "newton_iters", "cg_iters",
                           "rejections"})
    h5::units(log, name, kDimensionless);
  H5::DataSet log_t = log.openDataSet("t");
  h5::attr(log_t, "time_note", time_note(m));
  if (r.summary) write_summary(log, *r.summary);
  if (r.costs) write_costs(log, *r.costs);
  if (r.checkpoint) write_restart(root, "checkpoint", *r.checkpoint, u);
  H5::Group resumes = h5::group(root, "resumes");
  for (std::size_t k = 0; k < r.resumes.size(); ++k) {
    const ResumeRecord& e = r.resumes[k];
    H5::Group g = h5::group(resumes, numbered(static_cast<long>(k), 4));
    h5::attr(g, "t", e.t);
    h5::attr(g, "time", e.time);
    h5::attr(g, "threads", std::int64_t{e.threads});
    std::string changes;
    for (const auto& c : e.changes) changes += c + "\n";
    h5::attr(g, "changes", changes);
    if (!e.program_before.empty()) h5::attr(g, "program_before", e.program_before);
  }
}
}  // namespace

RunRecord read_run_file(const std::string& path) {
  H5::Exception::dontPrint();
  if (!std::filesystem::exists(path)) throw InputError(path + ": no such file");
  try {
    H5::H5File file(path, H5F_ACC_RDONLY);
    H5::Group root = file.openGroup("/");
    RunRecord r;
    H5::Group meta = root.openGroup("meta");
    r.meta.program_version = h5::attr_string(meta, "program_version");
    r.meta.git_revision = h5::attr_string(meta, "git_revision");
    r.meta.seed = static_cast<std::uint64_t>(h5::attr_int(meta, "seed"));
    r.meta.threads = static_cast<int>(h5::attr_int(meta, "threads"));
    r.meta.start_time = h5::attr_string(meta, "start_time");
    r.meta.end_time = h5::attr_string(meta, "end_time");
    r.meta.status = h5::attr_string(meta, "status");
    r.meta.length_unit_m = h5::attr_double(meta, "length_unit_m");
    r.meta.ks = h5::attr_double(meta, "ks");
    r.meta.kb = h5::attr_double(meta, "kb");
    r.meta.mass = h5::attr_double(meta, "mass");
    r.meta.h_eff = h5::attr_double(meta, "h_eff");
    if (meta.attrExists("mass_scale")) r.meta.mass_scale = h5::attr_double(meta, "mass_scale");
    if (meta.attrExists("crease_threshold"))
      r.meta.crease_threshold = h5::attr_double(meta, "crease_threshold");
    r.config = h5::read_string(root, "config");
    const Checker check{path};
    r.mesh = read_mesh(root, check);
    const Index n = r.mesh.num_nodes(), m = r.mesh.num_hinges();
    H5::Group frames = root.openGroup("frames");
    for (const auto& name : h5::members(frames)) {
      H5::Group g = frames.openGroup(name);
      FrameRecord f;
      f.state = read_state(g, "/frames/" + name, check, n, m);
      f.stage = h5::attr_string(g, "stage");
      f.cycle = static_cast<int>(h5::attr_int(g, "cycle"));
      f.step = static_cast<long>(h5::attr_int(g, "step"));
      r.frames.push_back(std::move(f));
    }
    H5::Group cycles = root.openGroup("cycles");
    for (const auto& name : h5::members(cycles)) {
      H5::Group g = cycles.openGroup(name);
      CycleRecord c;
      c.x = to_eigen(h5::read_doubles(g, "x"));
      c.p = to_eigen(h5::read_doubles(g, "p"));
      c.t = h5::attr_double(g, "t");
      c.cycle = static_cast<int>(h5::attr_int(g, "cycle"));
      if (g.attrExists("compaction")) c.compaction = h5::attr_double(g, "compaction");  // else NaN
      const std::string at = "/cycles/" + name;
      check.length(at + "/x", c.x, 3 * n, "3 per mesh node");
      check.length(at + "/p", c.p, m, "one per hinge");
      r.cycles.push_back(std::move(c));
    }
    if (h5::exists(root, "stage_ends")) {  // files written before per-stage records lack it
      H5::Group stage_ends = root.openGroup("stage_ends");
      for (const auto& name : h5::members(stage_ends)) {
        H5::Group g = stage_ends.openGroup(name);
        StageEndRecord e;
        e.p = to_eigen(h5::read_doubles(g, "p"));
        e.t = h5::attr_double(g, "t");
        e.cycle = static_cast<int>(h5::attr_int(g, "cycle"));
        e.stage = h5::attr_string(g, "stage");
        e.stage_index = static_cast<int>(h5::attr_int(g, "stage_index"));
        if (g.attrExists("wall")) e.wall = h5::attr_double(g, "wall");  // else NaN (older file)
        if (g.attrExists("compaction")) e.compaction = h5::attr_double(g, "compaction");
        if (g.attrExists("roll_axis_deg")) e.roll_axis_deg = h5::attr_double(g, "roll_axis_deg");
        check.length("/stage_ends/" + name + "/p", e.p, m, "one per hinge");
        r.stage_ends.push_back(std::move(e));
      }
    }
    H5::Group log = root.openGroup("log");
    const auto t = h5::read_doubles(log, "t"), hh = h5::read_doubles(log, "h"),
               a = h5::read_doubles(log, "a_ratio"), es = h5::read_doubles(log, "e_stretch"),
               eb = h5::read_doubles(log, "e_bend"), ec = h5::read_doubles(log, "e_contact"),
               ee = h5::read_doubles(log, "e_external"), ek = h5::read_doubles(log, "e_kinetic");
    // Files written before the average was logged have no column: NaN rows.
    const auto avg = h5::exists(log, "a_ratio_avg")
                         ? h5::read_doubles(log, "a_ratio_avg")
                         : std::vector<double>(t.size(), std::numeric_limits<double>::quiet_NaN());
    const auto mode = h5::read_int8(log, "mode");
    const auto order = h5::read_ints(log, "order"), newton = h5::read_ints(log, "newton_iters"),
               cg = h5::read_ints(log, "cg_iters"), rej = h5::read_ints(log, "rejections");
    for (const std::size_t n : {hh.size(), a.size(), es.size(), eb.size(), ec.size(), ee.size(),
                                ek.size(), avg.size(), mode.size(), order.size(), newton.size(),
                                cg.size(), rej.size()})
      if (n != t.size())
        throw InputError(path + ": /log columns of unequal length (" + std::to_string(n) +
                         " rows against " + std::to_string(t.size()) + " times)");
    for (std::size_t k = 0; k < t.size(); ++k) {
      LogRow row;
      row.t = t[k], row.h = hh[k], row.a_ratio = a[k], row.a_ratio_avg = avg[k];
      row.mode = mode[k], row.order = order[k];
      row.newton_iters = newton[k], row.cg_iters = cg[k], row.rejections = rej[k];
      row.e_stretch = es[k], row.e_bend = eb[k], row.e_contact = ec[k], row.e_external = ee[k];
      row.e_kinetic = ek[k];
      r.log.push_back(row);
    }
    r.summary = read_summary(log);
    r.costs = read_costs(log);
    if (h5::exists(root, "checkpoint")) r.checkpoint = read_restart(root, "checkpoint", check, n, m);
    if (h5::exists(root, "resumes")) {  // files written before resumes were recorded lack it
      H5::Group resumes = root.openGroup("resumes");
      for (const auto& name : h5::members(resumes)) {
        H5::Group g = resumes.openGroup(name);
        ResumeRecord e;
        e.t = h5::attr_double(g, "t");
        e.time = h5::attr_string(g, "time");
        e.threads = static_cast<int>(h5::attr_int(g, "threads"));
        std::istringstream lines(h5::attr_string(g, "changes"));
        for (std::string line; std::getline(lines, line);)
          if (!line.empty()) e.changes.push_back(line);
        if (g.attrExists("program_before")) e.program_before = h5::attr_string(g, "program_before");
        r.resumes.push_back(std::move(e));
      }
    }
    return r;
  } catch (const H5::Exception& e) {
    throw InputError(path + ": not a readable run file (" + e.getDetailMsg() + ")");
  }
}

void write_run_file_atomic(const std::string& path, const RunRecord& r) {
  const std::string tmp = path + ".new";
  try {
    write_run_file(tmp, r);
  } catch (const OutputError&) {
    std::error_code ec;
    std::filesystem::remove(tmp, ec);  // a half-written file is no checkpoint; PATH stays as it was
    throw;
  }
  rename_or_throw(tmp, path);
}

void rename_or_throw(const std::string& from, const std::string& to) {
  std::error_code ec;
  std::filesystem::rename(from, to, ec);
  if (ec) {
    std::filesystem::remove(from, ec);
    throw OutputError(to + ": cannot rename " + from + " to it (" + ec.message() + ")");
  }
}

}  // namespace crumple
