// crumple-sim: runs a protocol on a sheet and writes the run file (README.md, "Running the
// simulator"; keys in docs/CONFIG.md, file layout in docs/FILE_FORMAT.md).
//   crumple-sim CONFIG.yaml -o RUN.h5 [--seed S] [--threads N] [--set key=value]...
//               [--resume | --extend | --force] [--quiet] [--list-stages]
// Exit codes: 0 done, 2 bad input (nothing written), 3 numerical failure (checkpoint kept in
// RUN.h5.tmp; rerun with --resume), 128 + N stopped by signal N after a checkpoint, 1 anything
// else (a write failure among them: the last checkpoint is kept).
#include "crumple/version.hpp"
#include "protocols/registry.hpp"
#include "sim/apps/output_paths.hpp"
#include "sim/apps/resume.hpp"
#include "sim/apps/run_sink.hpp"
#include "sim/assemble/simulation.hpp"
#include "sim/core/stop_signal.hpp"
#include "sim/io/config.hpp"
#include "sim/io/config_doc.hpp"
#include "sim/io/xdmf.hpp"
#include "sim/mesh/generate.hpp"
#include "sim/mesh/quality.hpp"
#include "sim/model/crease_rule.hpp"

#include <CLI/CLI.hpp>
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <unistd.h>

using namespace crumple;

namespace {

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}

struct Options {
  std::string config, output;
  std::optional<std::int64_t> seed;
  int threads = 0;
  std::vector<std::string> sets;
  bool resume = false, extend = false, force = false, quiet = false, list = false;
  bool print_config = false;
  bool list_keys = false, markdown = false;
};

/// A protocol that stores more frames than this is a typo of output.dt (every frame is kept in
/// memory and rewritten at every checkpoint).
constexpr double kMaxFrames = 1e6;

/// The stage list: every stage built once (parameters, relations, order) before any output;
/// the frames the run can store at most (when every stage is bounded by its max_duration).
void validate_protocol(const Params& p, const StageRegistry& registry) {
  const YAML::Node& stages = p.protocol.stages;
  registry.validate_protocol(stages, p.protocol.stages_source, &p.protocol.stage_sets);
  double cycle_max = 0;
  for (std::size_t k = 0; k < stages.size(); ++k)
    cycle_max += registry.make(stages[k], p.protocol.stages_source, "")->max_duration;
  const double t_upper = std::min(p.protocol.t_max, p.protocol.cycles * cycle_max);
  // A stage without a real cap (max_duration 1e30, the default of stages with a duration) and
  // no t_max leave the length unknown: then only output.dt's own floor applies.
  if (t_upper < 1e20 && t_upper / p.output.dt > kMaxFrames) {
    std::ostringstream os;
    os << p.where("output.dt") << ": the run may store up to " << t_upper / p.output.dt
       << " frames (" << t_upper << " s of simulated time); at most " << kMaxFrames
       << ", so output.dt >= " << t_upper / kMaxFrames << " s";
    throw InputError(os.str());
  }
}

/// The configuration of this process: the command line's, checked against the checkpoint's
/// when resuming or extending (resume.hpp); `rec` receives the record the run goes on from
/// (RUN.h5.tmp's, or for --extend the complete RUN.h5's) and `resume` its checkpoint, if any.
Params load_run(const Options& o, const std::string& tmp, RunRecord& rec,
                std::optional<Checkpoint>& resume) {
  namespace fs = std::filesystem;
  Params given = load_config(o.config, o.sets);
  if (o.seed) {
    given.mesh.seed = static_cast<std::uint64_t>(*o.seed);
    given.origins["mesh.seed"] = "--seed " + std::to_string(*o.seed);
  }
  if (o.extend) {
    // Checked here, before the run file is read: what is pending or missing decides the error.
    if (fs::exists(tmp))
      throw InputError(tmp + ": holds the checkpoint of an unfinished run (an extension "
                             "stopped?); pass --resume to continue it");
    if (!fs::exists(o.output))
      throw InputError("-o " + o.output + ": --extend needs the complete run there; none");
  } else if (!(o.resume && fs::exists(tmp))) {
    if (o.resume && !o.quiet)
      std::fprintf(stderr, "crumple-sim: nothing to resume (%s absent): starting afresh\n",
                   tmp.c_str());
    return given;
  }
  const std::string source = o.extend ? o.output : tmp;
  rec = read_run_file(source);
  const Params stored = load_stored_config(rec.config, source + ":/config");
  const std::vector<std::string> changes = resume_changes(stored, given, source, o.extend);
  // Keys the run started without may change the physics from here on: always said.
  const std::vector<std::string> added = keys_added_since(rec.config, given);
  resume = o.extend ? checkpoint_to_extend(rec, stored, given, source)
                    : checkpoint_to_resume(rec, given, source);
  ResumeRecord r;
  r.t = resume->state.t;
  r.time = utc_now();
  r.threads = o.threads > 0 ? o.threads : omp_get_max_threads();
  r.program_before = rec.meta.program_version + " (" + rec.meta.git_revision + ")";
  r.changes = added;
  r.changes.insert(r.changes.end(), changes.begin(), changes.end());
  rec.resumes.push_back(r);
  if (!r.changes.empty()) {
    rec.config = resolved_yaml(resolved_for_mesh(given, rec.mesh));  // in force from here on
    const char* how = o.extend ? "on extension" : "on resume";
    const auto say = [&](const std::vector<std::string>& lines) {
      for (const auto& c : lines)
        std::fprintf(stderr, "crumple-sim: %s at t = %g s: %s\n", how, r.t, c.c_str());
    };
    say(added);
    if (!o.quiet) say(changes);
  }
  return given;
}

/// --print-config: the configuration checked as a run would check it (keys, stages, relations),
/// printed resolved with every default; nothing is written.
int print_config(const Options& o) {
  RunRecord rec;
  std::optional<Checkpoint> resume;
  const Params p = load_run(o, "", rec, resume);
  validate_protocol(p, StageRegistry::builtin());
  if (p.material.states_yield())
    std::printf("# integrator.plastic_c0 below is not used: a run sets it from material.%s "
                "(the run file stores the value)\n",
                p.material.yield_angle > 0 ? "yield_angle" : "yield_radius");
  std::printf("%s", resolved_yaml(p).c_str());
  return kExitOk;
}

/// The mesh, the model constants and the contact setup, as the run starts.
void print_setup(const Mesh& mesh, const Params& p, const Simulation& run) {
  const MeshQuality q = mesh_quality(mesh);
  const ResolvedMaterial& mat = run.material();
  std::fprintf(stderr,
               "crumple-sim %s (%s): %s, %d nodes, %d triangles, min angle %.1f deg, edge CV "
               "%.3f\n  ks %.4g N/m, kb %.4g J, m %.4g kg, h_eff %.4g m, b_iso %.3g, b_int %.3g\n",
               kVersion, kGitRevision, mesh.shape.c_str(), mesh.num_nodes(), mesh.num_triangles(),
               q.min_angle_deg, q.edge_cv, mat.model.ks, mat.model.kb, mat.model.mass, mat.h_eff,
               mat.model.b_iso, mat.model.b_int);
  if (p.material.yield_angle > 0)
    std::fprintf(stderr, "  yield: c0 %.4g from the yield angle %.4g deg (the same on every mesh)\n",
                 p.integrator.plastic_c0, p.material.yield_angle);
  if (p.material.yield_radius > 0)
    std::fprintf(stderr, "  yield: c0 %.4g from the yield radius %.4g m over a mean hinge width %.4g m\n",
                 p.integrator.plastic_c0, p.material.yield_radius, mean_hinge_width(mesh));
  if (!run.contact()) return;
  if (run.contact_range_raised())
    std::fprintf(stderr, "  contact: mesh too coarse to resolve h_eff; range raised to %.3g edge\n",
                 p.contact.sigma_floor);
  std::fprintf(stderr, "  contact: sigma %.4g m, %d sites (level %d)\n",
               run.contact_settings().sigma, static_cast<int>(run.contact()->pairs->sites().size()),
               run.contact()->pairs->sites().level);
}

/// The run in one line, its last on the console (issue 37): its name, cycles, simulated time,
/// integration wall and steps per mode over the whole run (resumes included), and the crease
/// length after each cycle in units of the sheet's side L0 (hinges with |p| above the run file's
/// crease threshold, the analysis's default rule; crumple-analyze gives the full statistics).
std::string run_line(const std::string& label, const State& s, const RunRecord& rec, double L0) {
  std::ostringstream os;
  os << label << ": " << rec.cycles.size() << " cycles to t = " << s.t << " s";
  if (rec.summary)
    os << ", integration wall " << std::llround(rec.summary->wall_total) << " s, steps "
       << rec.summary->steps_implicit << " implicit + " << rec.summary->steps_explicit
       << " explicit";
  os << "; crease length l/L0 per cycle (|p| > " << std::setprecision(3)
     << rec.meta.crease_threshold << "):";
  for (const CycleRecord& c : rec.cycles) {
    double length = 0;
    for (Index h = 0; h < rec.mesh.num_hinges(); ++h)
      if (std::abs(c.p[h]) > rec.meta.crease_threshold)
        length += rec.mesh.rest_length[rec.mesh.hinges[static_cast<std::size_t>(h)].edge];
    os << " " << std::fixed << std::setprecision(1) << length / L0 << std::defaultfloat;
  }
  return os.str();
}

/// What the run did: time, frames, steps per mode, wall per stage, the cost of contact (this
/// process's share: a resumed run counts from the resume).
void print_summary(const std::string& output, const State& s, const RunRecord& rec, Simulation& run) {
  const IntegratorSummary& sum = run.integrator().summary();
  std::fprintf(stderr, "crumple-sim: wrote %s (t = %g s, %zu frames, %zu cycles)\n%s",
               output.c_str(), s.t, rec.frames.size(), rec.cycles.size(), sum.text().c_str());
  std::string stages_line = "by stage:";
  for (const auto& [type, wall] : run.runner().stage_wall())
    stages_line += " " + type + " " + std::to_string(wall).substr(0, 8) + " s;";
  std::fprintf(stderr, "%s\n", stages_line.c_str());
  const SelfContact* contact = run.contact();
  if (!contact) return;
  const ContactStats& c = contact->pairs->stats();
  const double sites = static_cast<double>(contact->pairs->sites().size());
  std::fprintf(stderr,
               "contact: %zu searches in %.3f s (%.3g us per site and search), force and "
               "Jacobian %.3f s; %.1f%% of the integration wall time\n",
               c.searches, c.search_seconds,
               c.searches ? 1e6 * c.search_seconds / (double(c.searches) * sites) : 0.0,
               c.eval_seconds,
               sum.wall_total > 0 ? 100.0 * (c.search_seconds + c.eval_seconds) / sum.wall_total : 0.0);
}

int run(const Options& o) {
  if (o.print_config) return print_config(o);
  const std::string tmp = o.output + ".tmp";
  RunRecord rec;
  std::optional<Checkpoint> resume_from;
  const Params given = load_run(o, tmp, rec, resume_from);
  const auto& registry = StageRegistry::builtin();
  validate_protocol(given, registry);
  const OutputPaths paths =
      check_output_paths(o.output, given.output.xdmf, o.resume, o.force, o.extend);

  if (o.threads > 0) omp_set_num_threads(o.threads);
  if (!resume_from) {
    rec = RunRecord{};
    rec.mesh = generate_mesh(given.mesh);
    rec.meta.start_time = utc_now();
  }
  const Mesh& mesh = rec.mesh;
  // What depends on the mesh (the yield curvature of a yield radius) resolved, as stored.
  const Params p = resolved_for_mesh(given, mesh);
  if (!resume_from) rec.config = resolved_yaml(p);
  // Progress lines carry the run's name (its folder and file stem: runs side by side on one
  // console), and overwrite each other on a terminal.
  const std::filesystem::path out(o.output);
  const std::string label = (out.parent_path().filename() / out.stem()).string();
  Simulation run(p, mesh, registry, {o.quiet, label, isatty(fileno(stderr)) == 1}, stop_requested);
  const ResolvedMaterial& mat = run.material();
  rec.meta.program_version = kVersion;
  rec.meta.git_revision = kGitRevision;
  rec.meta.seed = p.mesh.seed;
  rec.meta.threads = omp_get_max_threads();
  rec.meta.status = "running";
  rec.meta.ks = mat.model.ks, rec.meta.kb = mat.model.kb, rec.meta.mass = mat.model.mass;
  rec.meta.h_eff = mat.h_eff;
  rec.meta.mass_scale = p.material.mass_scale;
  rec.meta.crease_threshold = crease_threshold(p.integrator.plastic_c0, p.output.crease_angle);
  if (!o.quiet) print_setup(mesh, p, run);

  Integrator& integ = run.integrator();
  const SelfContact* contact = run.contact();
  // The sink also records the contact term's costs (/log@contact_*) for benchmarks.
  FileSink sink(rec, tmp, integ, contact ? contact->pairs.get() : nullptr);
  State s = run.model().rest_state();
  const bool complete = run.run(s, sink, resume_from ? &*resume_from : nullptr);

  rec.meta.end_time = utc_now();
  rec.meta.status = complete ? "complete" : "complete: stopped at protocol.t_max";
  sink.write_final();
  // All three files are complete under temporary names before any takes its final name.
  const std::string h5_name = std::filesystem::path(paths.run).filename().string();
  if (!paths.xdmf.empty()) {
    write_xdmf(paths.xdmf + ".new", h5_name, rec, XdmfCollection::Frames);
    write_xdmf(paths.xdmf_cycles + ".new", h5_name, rec, XdmfCollection::Cycles);
  }
  rename_or_throw(paths.tmp, paths.run);
  if (!paths.xdmf.empty()) {
    rename_or_throw(paths.xdmf + ".new", paths.xdmf);
    rename_or_throw(paths.xdmf_cycles + ".new", paths.xdmf_cycles);
  }
  // A checkpoint kept from an earlier failure of this run is stale once the run is complete.
  std::error_code ec;
  std::filesystem::remove(before_failure_path(paths.tmp), ec);
  if (!o.quiet) {
    print_summary(o.output, s, rec, run);
    std::fprintf(stderr, "%s\n", run_line(label, s, rec, p.mesh.size).c_str());
  }
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"crumple-sim: simulate a protocol of crumpling stages on an elastoplastic sheet"};
  app.set_version_flag("--version", std::string("crumple-sim ") + kVersion + " (git " + kGitRevision + ")");
  app.footer(
      "Files written:\n"
      "  RUN.h5        the run (docs/FILE_FORMAT.md): mesh, frames, the plastic field at every stage\n"
      "                end, the compaction per cycle, step log, resolved config, seed, version\n"
      "  RUN.xdmf      its frames for ParaView (output.xdmf)\n"
      "  RUN.cycles.xdmf  the state at each cycle's end for ParaView (output.xdmf)\n"
      "  RUN.h5.tmp    while running: the run so far with a checkpoint (--resume continues it);\n"
      "                renamed to RUN.h5 when complete\n"
      "  RUN.h5.tmp.before-failure  after a numerical failure: the checkpoint before it (RUN.h5.tmp\n"
      "                holds the failing state); removed when the run completes\n"
      "Exit codes: 0 done; 2 bad input (nothing written); 3 numerical failure (checkpoint kept in\n"
      "RUN.h5.tmp, continue with --resume); 128+N stopped by signal N (SIGTERM 143, SIGINT 130)\n"
      "after a checkpoint; 1 anything else (e.g. a write failure; the last checkpoint is kept).");
  app.add_option("config", o.config, "protocol/config YAML file");
  app.add_option("-o,--output", o.output, "run file to write (HDF5), e.g. runs/a.h5");
  // 2^53: seeds are stored as YAML numbers, exact up to there.
  app.add_option("--seed", o.seed, "seed of the run (mesh and protocol randomness), 0 to 2^53")
      ->check(CLI::Range(std::int64_t{0}, std::int64_t{9007199254740992}));
  app.add_option("--threads", o.threads, "OpenMP threads (default: all)")->check(CLI::Range(1, 1024));
  app.add_option("--set", o.sets, "override a config key: dotted.key=value (repeatable)");
  app.add_flag("--resume", o.resume,
               "continue a stopped run from RUN.h5.tmp; the configuration must be the run's, "
               "except integrator tolerances, step limits and output intervals");
  app.add_flag("--extend", o.extend,
               "continue the complete run RUN.h5 to the larger protocol.cycles given, from the "
               "state after its last cycle; the configuration must otherwise be the run's (as "
               "for --resume). RUN.h5 stays as it was until the longer run completes");
  app.add_flag("--force", o.force,
               "replace an existing RUN.h5 (and its .xdmf sidecars) and discard a pending RUN.h5.tmp");
  app.add_flag("--quiet", o.quiet, "no progress output");
  app.add_flag("--list-stages", o.list, "print every stage type with its parameters");
  app.add_flag("--list-keys", o.list_keys,
               "print every configuration key (type, default, range, unit, meaning) and every "
               "stage type with its parameters");
  app.add_flag("--markdown", o.markdown,
               "with --list-keys: as the markdown tables of docs/CONFIG.md");
  app.add_flag("--print-config", o.print_config,
               "check CONFIG (with --set and --seed) as a run would and print it resolved, every "
               "default filled in; runs nothing, writes nothing, needs no -o");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? kExitOk : kExitBadInput;
  }
  if (o.list_keys) {
    const auto& stages = StageRegistry::builtin();
    if (o.markdown)
      std::printf("%s%s", config_keys_markdown().c_str(), stages.describe_markdown().c_str());
    else
      std::printf("%s\nstage types (protocol.stages[k].type) and their parameters:\n%s",
                  config_keys_text().c_str(), stages.describe().c_str());
    return kExitOk;
  }
  if (o.list) {
    std::printf("%s", StageRegistry::builtin().describe().c_str());
    return kExitOk;
  }
  if (o.config.empty() || (o.output.empty() && !o.print_config)) {
    std::fprintf(stderr, "crumple-sim: usage: crumple-sim CONFIG.yaml -o RUN.h5 [options]\n");
    return kExitBadInput;
  }
  if (int(o.resume) + int(o.extend) + int(o.force) > 1) {
    std::fprintf(stderr, "crumple-sim: --resume, --extend and --force contradict each other\n");
    return kExitBadInput;
  }
  namespace fs = std::filesystem;
  const std::string tmp = o.output + ".tmp";
  std::error_code ec;
  const bool tmp_before = fs::exists(tmp, ec);
  const auto kept = [&] {
    return fs::exists(tmp, ec) ? "crumple-sim: checkpoint kept in " + tmp + "; continue with --resume\n"
                               : std::string();
  };
  install_stop_handlers();
  try {
    return run(o);
  } catch (const InputError& e) {
    std::fprintf(stderr, "crumple-sim: %s\n", e.what());
    // Nothing half written: a checkpoint this process began is removed; one that was there
    // before (another run's, or this run's before a resume) is never touched.
    if (!tmp_before && !o.output.empty()) fs::remove(tmp, ec);
    return kExitBadInput;
  } catch (const NumericalFailure& e) {
    std::fprintf(stderr, "crumple-sim: numerical failure: %s\n%s", e.what(), kept().c_str());
    const std::string before = before_failure_path(tmp);
    if (fs::exists(before, ec))
      std::fprintf(stderr, "crumple-sim: the checkpoint before the failure is kept in %s; move it "
                           "to %s to resume from there (with other settings: the failing state "
                           "fails again)\n", before.c_str(), tmp.c_str());
    return kExitNumerical;
  } catch (const Interrupted& e) {
    std::fprintf(stderr, "crumple-sim: %s\n%s", e.what(), kept().c_str());
    return 128 + e.signal;
  } catch (const OutputError& e) {
    std::fprintf(stderr, "crumple-sim: cannot write: %s\n%s", e.what(), kept().c_str());
    return kExitFailure;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "crumple-sim: error: %s\n%s", e.what(), kept().c_str());
    return kExitFailure;
  }
}
