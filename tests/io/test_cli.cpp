// The crumple-sim binary: bad input exits 2 with the message and writes nothing; a run killed
// with SIGKILL, or stopped by SIGTERM or SIGINT, and resumed gives the uninterrupted result,
// step log included; no final file exists before the end. (tests/corpus holds the many bad
// inputs; these are the basic ones.)
#include "crumple/version.hpp"
#include "sim/io/run_file.hpp"
#include "tests/support/command_output.hpp"
#include "tests/support/scratch.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <csignal>
#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace crumple;

namespace {
const crumple::testing::ScratchDir kScratch("cli_test");
const fs::path kDir = kScratch.path;

struct Result {
  int code;
  std::string err;
};
Result sim(const std::string& args) {
  fs::create_directories(kDir);
  const fs::path err = kDir / "stderr.txt";
  const std::string cmd = std::string(CRUMPLE_SIM) + " " + args + " 2> " + err.string() + " > /dev/null";
  const int status = std::system(cmd.c_str());
  std::ifstream in(err);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text};
}
fs::path write(const std::string& name, const std::string& text) {
  fs::create_directories(kDir);
  const fs::path p = kDir / name;
  std::ofstream(p) << text;
  return p;
}
const char* kTiny = R"(mesh: {nodes: 120, seed: 4}
integrator: {plastic_c0: 0.3}
protocol:
  cycles: 2
  stages:
    - {type: roll, duration: 0.2}
    - {type: compress, compaction: 0.5, speed: 0.3}
output: {dt: 0.05, checkpoint_wall_s: 0}
)";
}  // namespace

TEST(Cli, BadInputExitsTwoAndWritesNothing) {
  const fs::path out = kDir / "bad.h5";
  struct Case {
    std::string yaml, args, expect;
  };
  const std::vector<Case> cases = {
      {"mesh: {nodez: 3}\n", "", ":1:8: mesh.nodez: unknown key"},
      {"mesh: {nodes: abc}\n", "", "mesh.nodes: expected a whole number"},
      {"material: {thickness: -1}\n", "", "material.thickness: must be > 0"},
      {"protocol: {stages: [{type: squash}]}\n", "", "unknown stage type 'squash'"},
      {"protocol: {stages: [{type: compress, speed: 1}]}\n", "", "compaction: missing required"},
      {"protocol: {stages: [{type: compress, compaction: 0.3, speed: -1}]}\n", "", "speed: must be > 0"},
      {"mesh: [1, 2\n", "", "YAML syntax error"},
      {"protocol: {stages: [{type: release}]}\n", "--set mesh.nodes=zero", "--set mesh.nodes=zero"},
  };
  for (const auto& c : cases) {
    const fs::path cfg = write("bad.yaml", c.yaml);
    const Result r = sim(cfg.string() + " -o " + out.string() + " " + c.args);
    SCOPED_TRACE(c.yaml);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(cfg.string()) == std::string::npos && c.args.empty(), true) << r.err;
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(out.string() + ".tmp"));
  }
  const Result missing = sim("no/such.yaml -o " + out.string());
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("no/such.yaml: cannot open"), std::string::npos);
  EXPECT_EQ(sim("--list-stages").code, 0);
}

namespace {
// Starts the tiny run to `out` (with `extra` arguments, up to three), sends `signo` once it has
// written a checkpoint, and returns the wait status.
int interrupt_run(const fs::path& cfg, const fs::path& out, int signo,
                  std::vector<std::string> extra = {}) {
  extra.resize(3);
  const pid_t pid = fork();
  if (pid == 0) {
    std::vector<const char*> argv = {CRUMPLE_SIM, cfg.c_str(), "-o", out.c_str(), "--threads", "1",
                                     "--quiet"};
    for (const auto& a : extra)
      if (!a.empty()) argv.push_back(a.c_str());
    argv.push_back(nullptr);
    execv(CRUMPLE_SIM, const_cast<char* const*>(argv.data()));
    _exit(127);
  }
  const fs::path tmp = out.string() + ".tmp";
  for (int i = 0; i < 2000 && !fs::exists(tmp); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  kill(pid, signo);  // the .tmp appears (atomically) only with a checkpoint in it
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

// The resumed run `b` took exactly the steps of the uninterrupted `a`.
void expect_same_run(const RunRecord& a, const RunRecord& b) {
  ASSERT_TRUE(a.checkpoint && b.checkpoint);
  EXPECT_EQ(a.checkpoint->state("state").t, b.checkpoint->state("state").t);
  EXPECT_EQ(a.checkpoint->state("state").x, b.checkpoint->state("state").x);
  EXPECT_EQ(a.checkpoint->state("state").p, b.checkpoint->state("state").p);
  EXPECT_EQ(a.frames.size(), b.frames.size());
  EXPECT_EQ(b.meta.status, "complete");
  // The step log: one row per accepted step up to the end, the same rows with and without the
  // interruption.
  ASSERT_FALSE(a.log.empty());
  EXPECT_EQ(a.log.back().t, a.checkpoint->state("state").t);
  ASSERT_EQ(a.log.size(), b.log.size());
  // The run summary covers the whole run, across the interruption too (wall times aside).
  ASSERT_TRUE(a.summary && b.summary);
  EXPECT_EQ(a.summary->steps(), static_cast<long>(a.log.size()));
  EXPECT_EQ(b.summary->steps(), a.summary->steps());
  EXPECT_EQ(b.summary->newton_iters, a.summary->newton_iters);
  EXPECT_EQ(b.summary->cg_iters, a.summary->cg_iters);
  EXPECT_EQ(b.summary->rejections(), a.summary->rejections());
  for (std::size_t k = 0; k < a.log.size(); ++k) {
    const LogRow &x = a.log[k], &y = b.log[k];
    ASSERT_TRUE(x.t == y.t && x.h == y.h && x.mode == y.mode && x.order == y.order &&
                x.newton_iters == y.newton_iters && x.cg_iters == y.cg_iters &&
                x.rejections == y.rejections && x.a_ratio == y.a_ratio &&
                x.a_ratio_avg == y.a_ratio_avg && x.e_stretch == y.e_stretch &&
                x.e_bend == y.e_bend && x.e_contact == y.e_contact &&
                x.e_external == y.e_external && x.e_kinetic == y.e_kinetic)
        << "log row " << k << ": t " << x.t << " / " << y.t << ", h " << x.h << " / " << y.h;
    if (k > 0) {
      EXPECT_GT(x.t, a.log[k - 1].t) << "log row " << k;
    }
    EXPECT_TRUE(x.mode == 0 || x.mode == 1) << "log row " << k;
    EXPECT_TRUE(std::isfinite(x.a_ratio_avg) && x.a_ratio_avg >= 0) << "log row " << k;
  }
  // The compaction each cycle's compress stage imposed is recorded alike across the
  // interruption (a cycle's value comes from its stage ends, which a resumed run reads back).
  ASSERT_EQ(a.cycles.size(), b.cycles.size());
  for (std::size_t k = 0; k < a.cycles.size(); ++k)
    EXPECT_EQ(b.cycles[k].compaction, a.cycles[k].compaction) << "cycle " << k + 1;
  ASSERT_EQ(a.stage_ends.size(), b.stage_ends.size());
  for (std::size_t k = 0; k < a.stage_ends.size(); ++k)
    EXPECT_EQ(b.stage_ends[k].compaction, a.stage_ends[k].compaction) << "stage end " << k;
}

}  // namespace

// SIGKILL ends the run at once; SIGTERM (a scheduler's time limit) and SIGINT (Ctrl-C) let it
// write a checkpoint at the end of its chunk of steps and exit 128 + the signal. Either way no
// final file exists, and --resume gives the uninterrupted result.
TEST(Cli, InterruptedRunResumesToTheUninterruptedResult) {
  const fs::path cfg = write("tiny.yaml", kTiny);
  const fs::path whole = kDir / "whole.h5";
  fs::remove(whole);
  fs::remove(whole.string() + ".xdmf");
  fs::remove(kDir / "whole.xdmf");
  ASSERT_EQ(sim(cfg.string() + " -o " + whole.string() + " --threads 1 --quiet").code, 0);
  const RunRecord a = read_run_file(whole.string());
  const double given = YAML::Load(kTiny)["protocol"]["stages"][1]["compaction"].as<double>();
  ASSERT_EQ(a.cycles.size(), 2u);
  for (const auto& c : a.cycles) EXPECT_EQ(c.compaction, given);
  for (const int signo : {SIGKILL, SIGTERM, SIGINT}) {
    SCOPED_TRACE(strsignal(signo));
    const fs::path out = kDir / ("stopped" + std::to_string(signo) + ".h5");
    const fs::path tmp = out.string() + ".tmp";
    for (const auto& p : {out, tmp, fs::path(out).replace_extension(".xdmf")}) fs::remove(p);
    const int status = interrupt_run(cfg, out, signo);
    if (signo == SIGKILL) {
      ASSERT_TRUE(WIFSIGNALED(status)) << "the run finished before it could be killed";
    } else {
      ASSERT_TRUE(WIFEXITED(status));
      ASSERT_EQ(WEXITSTATUS(status), 128 + signo) << "the run finished before the signal?";
    }
    EXPECT_FALSE(fs::exists(out)) << "a final file exists before completion";
    ASSERT_TRUE(fs::exists(tmp));
    const Result r = sim(cfg.string() + " -o " + out.string() + " --threads 1 --quiet --resume");
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_FALSE(fs::exists(tmp));
    const RunRecord b = read_run_file(out.string());
    expect_same_run(a, b);
    ASSERT_EQ(b.resumes.size(), 1u);
    EXPECT_TRUE(b.resumes[0].changes.empty());
    EXPECT_GT(b.resumes[0].t, 0.0);
  }
}

// A complete run extended with --extend to more cycles is, step for step, the run that had been
// given those cycles from the start; its file stays as it was until the longer run completes
// (here stopped by SIGTERM during the extension and resumed). What is not an extension is
// refused with the run file untouched.
TEST(Cli, ExtendedRunIsTheLongerRun) {
  const fs::path cfg = write("tiny.yaml", kTiny);
  const fs::path whole = kDir / "whole_for_extend.h5", out = kDir / "extended.h5";
  const std::string tmp = out.string() + ".tmp";
  for (const auto& p : {whole, out, fs::path(tmp)}) fs::remove(p);
  const std::string opts = " --threads 1 --quiet";
  ASSERT_EQ(sim(cfg.string() + " -o " + whole.string() + opts).code, 0);
  const RunRecord a = read_run_file(whole.string());
  ASSERT_EQ(a.cycles.size(), 2u);

  const std::string base = cfg.string() + " -o " + out.string() + opts;
  const Result absent = sim(base + " --extend");
  EXPECT_EQ(absent.code, 2);
  EXPECT_NE(absent.err.find("--extend needs the complete run there"), std::string::npos) << absent.err;
  ASSERT_EQ(sim(base + " --set protocol.cycles=1").code, 0);
  const auto stamp = fs::last_write_time(out);
  struct Refusal {
    std::string args, expect;
  };
  for (const Refusal& r : std::vector<Refusal>{
           {" --set protocol.cycles=1", "--extend needs more (e.g. --set protocol.cycles=2)"},
           {" --set protocol.cycles=2 --set mesh.nodes=150", "mesh.nodes: 120 in the run, 150 given"},
           {" --set protocol.cycles=2 --force", "contradict"}}) {
    SCOPED_TRACE(r.args);
    const Result refused = sim(base + " --extend" + r.args);
    EXPECT_EQ(refused.code, 2);
    EXPECT_NE(refused.err.find(r.expect), std::string::npos) << refused.err;
    EXPECT_EQ(fs::last_write_time(out), stamp) << "a refused extension touched the run file";
    EXPECT_FALSE(fs::exists(tmp));
  }

  const int status = interrupt_run(cfg, out, SIGTERM, {"--extend", "--set", "protocol.cycles=2"});
  ASSERT_TRUE(WIFEXITED(status));
  ASSERT_EQ(WEXITSTATUS(status), 128 + SIGTERM) << "the extension finished before the signal?";
  ASSERT_TRUE(fs::exists(tmp));
  EXPECT_EQ(read_run_file(out.string()).cycles.size(), 1u) << "the run file changed before the end";
  const Result again = sim(base + " --extend --set protocol.cycles=2");
  EXPECT_EQ(again.code, 2);
  EXPECT_NE(again.err.find("pass --resume"), std::string::npos) << again.err;
  const Result resumed = sim(base + " --resume --set protocol.cycles=2");
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  EXPECT_FALSE(fs::exists(tmp));
  const RunRecord b = read_run_file(out.string());
  expect_same_run(a, b);
  EXPECT_EQ(YAML::Load(b.config)["protocol"]["cycles"].as<int>(), 2);
  ASSERT_EQ(b.resumes.size(), 2u);
  EXPECT_EQ(b.resumes[0].t, a.cycles[0].t) << "extended from the end of cycle 1";
  const auto& c = b.resumes[0].changes;
  EXPECT_NE(std::find(c.begin(), c.end(), "protocol.cycles: 1 -> 2"), c.end())
      << (c.empty() ? "" : c[0]);
  EXPECT_EQ(b.resumes[0].program_before, std::string(kVersion) + " (" + kGitRevision + ")");
  for (std::size_t k = 0; k < a.frames.size(); ++k)
    ASSERT_EQ(a.frames[k].state.t, b.frames[k].state.t) << "frame " << k;
}

// A run that failed numerically (exit 3, here: a step limit the first step cannot meet) goes on
// with corrected integrator settings: --resume applies them, records them in /resumes, and
// refuses a change of the problem itself.
TEST(Cli, FailedRunResumesWithCorrectedStepLimits) {
  const fs::path cfg = write("tiny.yaml", kTiny);
  const fs::path out = kDir / "failed.h5";
  const fs::path tmp = out.string() + ".tmp";
  for (const auto& p : {out, tmp, fs::path(out).replace_extension(".xdmf")}) fs::remove(p);
  const std::string base = cfg.string() + " -o " + out.string() + " --threads 1 --quiet" +
                           " --set integrator.explicit_h_start=1e-9";
  const Result failed = sim(base + " --set integrator.h_min=0.01 --set integrator.h_init=0.01");
  ASSERT_EQ(failed.code, 3) << failed.err;
  EXPECT_NE(failed.err.find("checkpoint kept in " + tmp.string()), std::string::npos) << failed.err;
  ASSERT_TRUE(fs::exists(tmp));
  const Result changed = sim(base + " --resume --set mesh.nodes=150");
  EXPECT_EQ(changed.code, 2);
  EXPECT_NE(changed.err.find("--set mesh.nodes=150: mesh.nodes: 120 in the run, 150 given"),
            std::string::npos) << changed.err;
  ASSERT_TRUE(fs::exists(tmp)) << "a refused resume must keep the checkpoint";
  const Result resumed = sim(base + " --resume");
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  const RunRecord r = read_run_file(out.string());
  EXPECT_EQ(r.meta.status, "complete");
  ASSERT_EQ(r.resumes.size(), 1u);
  const auto& c = r.resumes[0].changes;
  EXPECT_NE(std::find(c.begin(), c.end(), "integrator.h_min: 0.01 -> 9.9999999999999998e-13"), c.end())
      << (c.empty() ? "" : c[0]);
  EXPECT_EQ(r.resumes[0].t, 0.0);
}

// A run failing numerically after checkpoints (here in the second cycle's compression, at a
// step limit it cannot meet there) keeps the failing state in RUN.h5.tmp and the checkpoint
// before it in RUN.h5.tmp.before-failure, says so, and goes on from the latter with other
// settings; the kept file is removed once the run completes.
TEST(Cli, NumericalFailureKeepsTheCheckpointBeforeIt) {
  const fs::path cfg = write("tiny.yaml", kTiny);
  const fs::path out = kDir / "late_failure.h5";
  const std::string tmp = out.string() + ".tmp", before = tmp + ".before-failure";
  for (const auto& p : {out.string(), tmp, before}) fs::remove(p);
  const std::string base = cfg.string() + " -o " + out.string() + " --threads 1 --quiet";
  const Result failed = sim(base + " --set integrator.h_min=1e-4");
  ASSERT_EQ(failed.code, 3) << failed.err;
  EXPECT_NE(failed.err.find("checkpoint before the failure is kept in " + before),
            std::string::npos) << failed.err;
  ASSERT_TRUE(fs::exists(tmp));
  ASSERT_TRUE(fs::exists(before));
  const RunRecord at = read_run_file(tmp), prior = read_run_file(before);
  ASSERT_TRUE(at.checkpoint.has_value());
  ASSERT_TRUE(prior.checkpoint.has_value());
  const double t_at = at.checkpoint->state("state").t;
  const double t_prior = prior.checkpoint->state("state").t;
  EXPECT_GT(t_prior, 0.0);
  EXPECT_LE(t_prior, t_at);
  EXPECT_GE(prior.frames.size(), 2u);
  // Resumed from the checkpoint before the failure with the default step limit: it completes.
  fs::rename(before, tmp);
  const Result resumed = sim(base + " --resume");
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  EXPECT_EQ(read_run_file(out.string()).meta.status, "complete");
  EXPECT_FALSE(fs::exists(before));
  // A failure before any checkpoint keeps only the failing state.
  fs::remove(out);
  const Result early = sim(base + " --force --set integrator.explicit_h_start=1e-9 "
                                  "--set integrator.h_min=0.01 --set integrator.h_init=0.01");
  ASSERT_EQ(early.code, 3) << early.err;
  EXPECT_TRUE(fs::exists(tmp));
  EXPECT_FALSE(fs::exists(before));
  EXPECT_EQ(early.err.find("before the failure"), std::string::npos) << early.err;
}

// A run started by an earlier program stores a configuration without the keys added since
// (here material.area_barrier, removed from the stored text): the resume goes on, says that the
// key now takes its value, records it in /resumes and stores the configuration in force.
TEST(Cli, ResumeNamesKeysTheRunStartedWithout) {
  const fs::path cfg = write("tiny.yaml", kTiny);
  const fs::path out = kDir / "older.h5";
  const std::string tmp = out.string() + ".tmp";
  for (const auto& p : {out, fs::path(tmp), fs::path(out).replace_extension(".xdmf")}) fs::remove(p);
  const std::string base = cfg.string() + " -o " + out.string() + " --threads 1 --quiet" +
                           " --set integrator.explicit_h_start=1e-9";
  ASSERT_EQ(sim(base + " --set integrator.h_min=0.01 --set integrator.h_init=0.01").code, 3);
  RunRecord older = read_run_file(tmp);
  const std::size_t key = older.config.find("  area_barrier:");
  ASSERT_NE(key, std::string::npos) << older.config;
  const std::size_t at = older.config.rfind('\n', key) + 1;  // the whole line, its indent too
  older.config.erase(at, older.config.find('\n', at) + 1 - at);
  write_run_file(tmp, older);

  const Result resumed = sim(base + " --resume");
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  const std::string line =
      "material.area_barrier: (absent: the run was started by a program without this key) -> true";
  EXPECT_NE(resumed.err.find(line), std::string::npos) << resumed.err;
  const RunRecord r = read_run_file(out.string());
  ASSERT_EQ(r.resumes.size(), 1u);
  const auto& c = r.resumes[0].changes;
  EXPECT_NE(std::find(c.begin(), c.end(), line), c.end()) << (c.empty() ? "" : c[0]);
  EXPECT_NE(r.config.find("area_barrier: true"), std::string::npos);
}

TEST(Cli, VersionAndHelpFollowTheConventions) {
  // --version prints the program, its version and git revision on stdout and exits 0; --help
  // lists the files a run writes and the exit codes.
  const auto out = [](const std::string& args, int& code) {
    return crumple::testing::command_output(std::string(CRUMPLE_SIM) + " " + args, code);
  };
  int code = -1;
  const std::string version = out("--version", code);
  EXPECT_EQ(code, 0);
  EXPECT_EQ(version.rfind(std::string("crumple-sim ") + kVersion + " (git ", 0), 0u) << version;
  const std::string help = out("--help", code);
  EXPECT_EQ(code, 0);
  for (const char* part : {"--version", "Files written:", "RUN.h5.tmp", "Exit codes: 0 done; 2 bad input",
                           "3 numerical failure", "128+N stopped by signal N"})
    EXPECT_NE(help.find(part), std::string::npos) << part;
}

TEST(Cli, ProgressLinesNameTheRunAndTheShareDone) {
  // Runs side by side on one console: every progress line starts with the run's folder and
  // stem, then the share of the whole run done (stage ends reach 100 % at the last one).
  const fs::path cfg = write("tiny.yaml", kTiny);
  fs::create_directories(kDir / "seedling");
  const fs::path out = kDir / "seedling" / "run7.h5";
  const Result r = sim(cfg.string() + " -o " + out.string() + " --force --threads 1");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("\nseedling/run7: 0 % | cycle 1/2  stage 1/2 roll"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("\nseedling/run7: 50 % ETA "), std::string::npos) << r.err;  // cycle 1 done
  EXPECT_NE(r.err.find("\nseedling/run7: 100 % | cycle 2/2  stage 2/2 compress"), std::string::npos)
      << r.err;
  // Not a terminal: no carriage returns or escape sequences in a log.
  EXPECT_EQ(r.err.find('\r'), std::string::npos);
  EXPECT_EQ(r.err.find('\033'), std::string::npos);
  // The last line sums the run up: name, cycles, wall, steps per mode, and the crease length
  // after each cycle, which is the run file's crease mask summed over the hinge edges.
  std::string last = r.err.substr(0, r.err.size() - 1);
  last = last.substr(last.rfind('\n') + 1);
  EXPECT_EQ(last.rfind("seedling/run7: 2 cycles to t = ", 0), 0u) << last;
  for (const char* part : {"integration wall ", " implicit + ", " explicit; crease length l/L0 per cycle (|p| > "})
    EXPECT_NE(last.find(part), std::string::npos) << part << " in: " << last;
  const RunRecord rec = read_run_file(out.string());
  std::string expected;
  for (const auto& c : rec.cycles) {
    double length = 0;
    for (Index h = 0; h < rec.mesh.num_hinges(); ++h)
      length += c.p[h] != 0 && std::abs(c.p[h]) > rec.meta.crease_threshold
                    ? rec.mesh.rest_length[rec.mesh.hinges[static_cast<std::size_t>(h)].edge]
                    : 0.0;
    char cell[32];
    std::snprintf(cell, sizeof cell, " %.1f", length / 0.1);  // kTiny: a 10 cm sheet
    expected += cell;
  }
  EXPECT_EQ(last.substr(last.rfind("):") + 2), expected) << last;
}

TEST(Cli, AStatedCreaseAngleSetsTheCreaseMasks) {
  // output.crease_angle: the masks (and the summary line) count folds above that angle, not 0.5 c0.
  const fs::path cfg = write("tiny.yaml", kTiny);
  const fs::path out = kDir / "crease_angle.h5";
  const Result r = sim(cfg.string() + " -o " + out.string() +
                       " --force --threads 1 --quiet --set output.crease_angle=20");
  ASSERT_EQ(r.code, 0) << r.err;
  const RunRecord rec = read_run_file(out.string());
  EXPECT_NEAR(rec.meta.crease_threshold, 2 * std::sin(10 * std::numbers::pi / 180), 1e-12);
}
