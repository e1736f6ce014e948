// crumple-sim: runs a protocol on a sheet and writes the run file (README.md, "Running the
// simulator"; keys in docs/CONFIG.md, file layout in docs/FILE_FORMAT.md).
//   crumple-sim CONFIG.yaml -o RUN.h5 [--seed S] [--threads N] [--set key=value]... [--resume]
//               [--quiet] [--list-stages]
// Exit codes: 0 done, 2 bad input (nothing written), 3 numerical failure (checkpoint kept in
// RUN.h5.tmp; rerun with --resume), 1 anything else.
#include "crumple/version.hpp"
#include "protocols/integrator_stepper.hpp"
#include "protocols/registry.hpp"
#include "sim/apps/run_sink.hpp"
#include "sim/contact/self_contact.hpp"
#include "sim/io/config.hpp"
#include "sim/io/units.hpp"
#include "sim/mesh/generate.hpp"
#include "sim/mesh/quality.hpp"

#include <CLI/CLI.hpp>
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>

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
  std::optional<std::uint64_t> seed;
  int threads = 0;
  std::vector<std::string> sets;
  bool resume = false, quiet = false, list = false;
};

int run(const Options& o) {
  namespace fs = std::filesystem;
  const std::string tmp = o.output + ".tmp";
  RunRecord rec;
  Params p;
  if (o.resume && fs::exists(tmp)) {
    rec = read_run_file(tmp);
    // The stored resolved configuration is the run's configuration.
    p = load_config_text(rec.config, tmp + ":/config");
  } else {
    if (o.resume && !o.quiet)
      std::fprintf(stderr, "crumple-sim: nothing to resume (%s absent): starting afresh\n",
                   tmp.c_str());
    p = load_config(o.config, o.sets);
    if (o.seed) p.mesh.seed = *o.seed;
  }
  const auto& registry = StageRegistry::builtin();
  const YAML::Node& stages = p.protocol.stages;
  if (stages.size() == 0)
    throw InputError(p.file + ": protocol.stages: the protocol has no stages");
  for (std::size_t k = 0; k < stages.size(); ++k)  // validate every stage before any output
    registry.make(stages[k], p.file, "protocol.stages[" + std::to_string(k) + "]");

  if (o.threads > 0) omp_set_num_threads(o.threads);
  if (!rec.checkpoint) {
    MeshSpec spec;
    spec.shape = p.mesh.shape;
    spec.size = p.mesh.size;
    spec.nodes = p.mesh.nodes;
    spec.seed = p.mesh.seed;
    spec.lloyd_iterations = p.mesh.lloyd_iterations;
    rec = RunRecord{};
    rec.mesh = generate_mesh(spec);
    rec.config = resolved_yaml(p);
    rec.meta.start_time = utc_now();
  }
  const Mesh& mesh = rec.mesh;
  const ResolvedMaterial mat = resolve_material(p.material, mesh.total_area(), mesh.num_nodes());
  rec.meta.program_version = kVersion;
  rec.meta.git_revision = kGitRevision;
  rec.meta.seed = p.mesh.seed;
  rec.meta.threads = omp_get_max_threads();
  rec.meta.status = "running";
  rec.meta.ks = mat.model.ks, rec.meta.kb = mat.model.kb, rec.meta.mass = mat.model.mass;
  rec.meta.h_eff = mat.h_eff;

  if (!o.quiet) {
    const MeshQuality q = mesh_quality(mesh);
    std::fprintf(stderr,
                 "crumple-sim %s (%s): %s, %d nodes, %d triangles, min angle %.1f deg, edge CV "
                 "%.3f\n  ks %.4g N/m, kb %.4g J, m %.4g kg, h_eff %.4g m, b_iso %.3g, b_int %.3g\n",
                 kVersion, kGitRevision, mesh.shape.c_str(), mesh.num_nodes(),
                 mesh.num_triangles(), q.min_angle_deg, q.edge_cv, mat.model.ks, mat.model.kb,
                 mat.model.mass, mat.h_eff, mat.model.b_iso, mat.model.b_int);
  }

  SheetModel model(mesh, mat.model);
  // Self-contact (paper §2.4): range sigma = h_eff unless set, stiffness ks unless set; its
  // candidate list is refreshed before every step; stages may switch it off (unfold).
  std::unique_ptr<SelfContact> contact;
  bool contact_on = false;
  if (p.contact.enabled) {
    ContactSettings cs;
    cs.ks = p.contact.stiffness > 0 ? p.contact.stiffness : mat.model.ks;
    // sigma = h_eff (paper §2.4) unless the mesh is too coarse to resolve it: with site
    // refinement capped at level 3 the sites are a quarter edge apart, and layers slip between
    // sites unless the range covers them (measured: a flat sheet stays force-free up to
    // 0.79 edge at level 3), so the automatic range is at least half an edge.
    const double floor = 0.5 * mesh.mean_edge_length();
    cs.sigma = p.contact.sigma > 0 ? p.contact.sigma : std::max(mat.h_eff, floor);
    if (p.contact.sigma <= 0 && floor > mat.h_eff && !o.quiet)
      std::fprintf(stderr,
                   "  contact: mesh too coarse to resolve h_eff; range raised to half an edge\n");
    cs.level = p.contact.refinement == "auto" ? -1 : std::stoi(p.contact.refinement);
    cs.skin = p.contact.skin;
    contact = std::make_unique<SelfContact>(mesh, cs, p.contact.fold_barrier);
    contact->add_to(model);
    contact_on = true;
    if (!o.quiet)
      std::fprintf(stderr, "  contact: sigma %.4g m, %d sites\n", cs.sigma,
                   static_cast<int>(contact->pairs->sites().size()));
  }
  Integrator integ(model, p.integrator);
  if (contact)
    integ.before_step = [&](const State& st) {
      if (!contact_on) return false;
      // True when a re-search found a pair in range that the old list lacked: the explicit
      // step's reused last stage (FSAL) was evaluated without it.
      return contact->update(st.x);
    };
  IntegratorStepper stepper(integ);
  SheetInfo info;
  info.size = p.mesh.size;
  info.area = mesh.total_area();
  info.h_eff = mat.h_eff;
  info.ks = mat.model.ks, info.kb = mat.model.kb, info.mass = mat.model.mass;
  info.spacing = mesh.mean_edge_length();
  RunnerSettings rs;
  rs.cycles = p.protocol.cycles;
  rs.t_max = p.protocol.t_max;
  rs.frame_dt = p.output.dt;
  rs.checkpoint_wall_s = p.output.checkpoint_wall_s;
  rs.quiet = o.quiet;
  rs.seed = p.mesh.seed;
  const std::string file = p.file;
  ProtocolRunner runner(
      model, stepper,
      [&](int k) {
        return registry.make(stages[k], file, "protocol.stages[" + std::to_string(k) + "]");
      },
      static_cast<int>(stages.size()), info, rs);

  if (contact)
    runner.set_contact_switch(
        [&](bool on) {
          if (on == contact_on) return;
          if (on) {
            contact->add_to(model);
          } else {
            contact->remove_from(model);
          }
          contact_on = on;
        },
        [&] { return contact_on; });
  // The sink also records the contact term's costs (/log@contact_*) for benchmarks.
  FileSink sink(rec, tmp, integ, p.output.crease_threshold,
                contact ? contact->pairs.get() : nullptr);
  State s = model.rest_state();
  const std::optional<Checkpoint> resume_from = rec.checkpoint;
  const bool complete = runner.run(s, sink, resume_from ? &*resume_from : nullptr);

  rec.meta.end_time = utc_now();
  rec.meta.status = complete ? "complete" : "complete: stopped at protocol.t_max";
  sink.write_final();
  fs::rename(tmp, o.output);
  if (p.output.xdmf) {
    const fs::path out(o.output);
    write_xdmf(fs::path(out).replace_extension(".xdmf").string(), out.filename().string(), rec);
  }
  if (!o.quiet) {
    std::fprintf(stderr, "crumple-sim: wrote %s (t = %g s, %zu frames, %zu cycles)\n%s",
                 o.output.c_str(), s.t, rec.frames.size(), rec.cycles.size(),
                 integ.summary().text().c_str());
    std::string stages_line = "by stage:";
    for (const auto& [type, wall] : runner.stage_wall())
      stages_line += " " + type + " " + std::to_string(wall).substr(0, 8) + " s;";
    std::fprintf(stderr, "%s\n", stages_line.c_str());
    if (contact) {
      // This process's share (a resumed run counts from the resume).
      const ContactStats& c = contact->pairs->stats();
      const double wall = integ.summary().wall_total;
      std::fprintf(stderr,
                   "contact: %zu searches in %.3f s (%.3g us per site and search), force and "
                   "Jacobian %.3f s; %.1f%% of the integration wall time\n",
                   c.searches, c.search_seconds,
                   c.searches ? 1e6 * c.search_seconds / (double(c.searches) * contact->pairs->sites().size())
                              : 0.0,
                   c.eval_seconds,
                   wall > 0 ? 100.0 * (c.search_seconds + c.eval_seconds) / wall : 0.0);
    }
  }
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"crumple-sim: simulate a protocol of crumpling stages on an elastoplastic sheet"};
  app.add_option("config", o.config, "protocol/config YAML file");
  app.add_option("-o,--output", o.output, "run file to write (HDF5), e.g. runs/a.h5");
  app.add_option("--seed", o.seed, "seed of the run (mesh and protocol randomness)");
  app.add_option("--threads", o.threads, "OpenMP threads (default: all)")->check(CLI::Range(1, 1024));
  app.add_option("--set", o.sets, "override a config key: dotted.key=value (repeatable)");
  app.add_flag("--resume", o.resume, "continue a killed run from RUN.h5.tmp");
  app.add_flag("--quiet", o.quiet, "no progress output");
  app.add_flag("--list-stages", o.list, "print every stage type with its parameters");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int rc = app.exit(e);
    return rc == 0 ? kExitOk : kExitBadInput;
  }
  if (o.list) {
    std::printf("%s", StageRegistry::builtin().describe().c_str());
    return kExitOk;
  }
  if (o.config.empty() || o.output.empty()) {
    std::fprintf(stderr, "crumple-sim: usage: crumple-sim CONFIG.yaml -o RUN.h5 [options]\n");
    return kExitBadInput;
  }
  const std::string tmp = o.output + ".tmp";
  try {
    return run(o);
  } catch (const InputError& e) {
    std::fprintf(stderr, "crumple-sim: %s\n", e.what());
    // Nothing half written: a fresh run leaves no file behind (a resumed one keeps its file).
    if (!o.resume) std::filesystem::remove(tmp);
    return kExitBadInput;
  } catch (const NumericalFailure& e) {
    std::fprintf(stderr,
                 "crumple-sim: numerical failure: %s\ncrumple-sim: checkpoint kept in %s; "
                 "continue with --resume\n",
                 e.what(), tmp.c_str());
    return kExitNumerical;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "crumple-sim: error: %s\n", e.what());
    return kExitFailure;
  }
}
