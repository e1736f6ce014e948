#!/usr/bin/python3
"""pipeline/sweeps/expand_sweep.py: the points of a sweep (grid x seeds, the preset's settings,
then the sweep's, then the point's own), the make rules and the per-run argument files (rewritten
only when they change), and bad sweep files refused with the file, line and key, exit 2 and
nothing written; a mistyped grid key is caught by crumple-sim --print-config before any run, and
every sweep shipped in pipeline/sweeps/ resolves with this build.

usage: test_sweep_expand.py CRUMPLE_SIM   (from the repository root)
"""
import csv
import json
import os
import subprocess
import sys
import tempfile
import unittest

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
EXPAND = os.path.join(REPO, "pipeline", "sweeps", "expand_sweep.py")
SIM = None

GOOD = """\
description: test
preset: tiny
protocol: protocols/axial_crumpling.yaml
set:
  protocol.cycles: 3
grid:
  protocol.stages.compress.compaction: [0.5, 0.27]
  mesh.nodes: [200, 300]
seeds: [4, 7]
"""


def read(path):
    with open(path) as f:
        return f.read()


def expand(text, tmp, sim=False, extra=()):
    path = os.path.join(tmp, "s.yaml")
    with open(path, "w") as f:
        f.write(text)
    out = os.path.join(tmp, "runs")
    cmd = [sys.executable, EXPAND, path, "--out-dir", out, "--results", os.path.join(tmp, "res")]
    if sim:
        cmd += ["--sim", SIM]
    cmd += list(extra)
    r = subprocess.run(cmd, cwd=REPO, capture_output=True, text=True)
    return r, path, out


def fake_sim(tmp, body):
    """A stand-in simulator for the run rules: it notes in its log (stderr) which way it was
    started (--resume, --force or --extend) as $how, with the run file as $out, then runs `body`."""
    fake = os.path.join(tmp, "fake-sim")
    with open(fake, "w") as f:
        f.write('#!/bin/sh\nout=""; how=""\n'
                'while [ $# -gt 0 ]; do case "$1" in -o) out="$2"; shift;; '
                '--resume|--force|--extend) how="$1";; esac; shift; done\n'
                'echo "piece started with $how" >&2\n' + body)
    os.chmod(fake, 0o755)
    return fake


class Expand(unittest.TestCase):
    def test_points_args_and_rules(self):
        with tempfile.TemporaryDirectory() as tmp:
            r, _, out = expand(GOOD, tmp, sim=True)
            self.assertEqual(r.returncode, 0, r.stderr)
            doc = json.loads(read(os.path.join(out, "points.json")))
            pts = doc["points"]
            self.assertEqual(len(pts), 8)  # 2 x 2 grid values, 2 seeds
            self.assertEqual(len({p["group"] for p in pts}), 4)
            self.assertTrue(doc["collapse"])  # the grid varies the compaction
            self.assertFalse(doc["convergence"])  # ... so it is no resolution ladder
            p = pts[0]
            self.assertEqual(p["group"], "compaction-0.5_nodes-200")
            self.assertEqual(p["seed"], 4)
            a = p["args"]
            # The preset's settings first, then the sweep's, then the point's: the last wins.
            self.assertLess(a.index("protocol.cycles=2"), a.index("protocol.cycles=3"))
            self.assertLess(a.index("protocol.cycles=3"),
                            a.index("protocol.stages.compress.compaction=0.5"))
            self.assertEqual(a[a.index("--seed") + 1], "4")
            mk = read(os.path.join(out, "points.mk"))
            self.assertIn(p["run"] + ": " + p["run"] + ".args", mk)
            self.assertEqual(mk.count("$(ANALYZE) ensemble"), 4)
            # Argument files are rewritten only when they change.
            args = p["run"] + ".args"
            os.utime(args, (1, 1))
            r, _, _ = expand(GOOD, tmp)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(os.stat(args).st_mtime, 1)
            r, _, _ = expand(GOOD.replace("protocol.cycles: 3", "protocol.cycles: 4"), tmp)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertNotEqual(os.stat(args).st_mtime, 1)

    def test_a_resumed_run_appends_to_its_log(self):
        # A stand-in simulator that stops with a checkpoint the first time and completes the
        # second, saying which way it was started: both pieces stay in the run's log.
        with tempfile.TemporaryDirectory() as tmp:
            r, _, out = expand(GOOD, tmp)
            self.assertEqual(r.returncode, 0, r.stderr)
            run = json.loads(read(os.path.join(out, "points.json")))["points"][0]["run"]
            fake = fake_sim(tmp, 'if [ -e "$out.tmp" ]; then : > "$out"; rm "$out.tmp"; exit 0; fi\n'
                                 ': > "$out.tmp"; exit 143\n')
            make = ["make", "--no-print-directory", "-f", os.path.join(out, "points.mk"),
                    "SIM=" + fake, "ANALYZE=" + fake, run]
            first = subprocess.run(make, cwd=REPO, capture_output=True, text=True)
            self.assertNotEqual(first.returncode, 0)
            self.assertTrue(os.path.exists(run + ".tmp"))
            second = subprocess.run(make, cwd=REPO, capture_output=True, text=True)
            self.assertEqual(second.returncode, 0, second.stdout + second.stderr)
            self.assertEqual(read(run + ".log"),
                             "piece started with --force\npiece started with --resume\n")

    def test_a_finished_run_made_again_is_extended_when_it_can_be(self):
        # The rule of a finished run whose arguments changed offers it to --extend first (the
        # stand-in takes it, exit 0, or refuses it as crumple-sim does what is not more cycles,
        # exit 2, or fails in it numerically, exit 3): extended, the log goes on; refused, the
        # run is made afresh; failed, it is neither made afresh nor called done.
        with tempfile.TemporaryDirectory() as tmp:
            r, _, out = expand(GOOD, tmp)
            self.assertEqual(r.returncode, 0, r.stderr)
            run = json.loads(read(os.path.join(out, "points.json")))["points"][0]["run"]
            fake = fake_sim(tmp, 'if [ "$how" = --extend ]; then exit "$EXTEND_EXIT"; fi\n'
                                 ': > "$out"; exit 0\n')

            def make(extend_exit):
                os.utime(run + ".args")  # the arguments changed after the run
                os.utime(run, (1, 1))
                return subprocess.run(
                    ["make", "--no-print-directory", "-f", os.path.join(out, "points.mk"),
                     "SIM=" + fake, "ANALYZE=" + fake, run], cwd=REPO, capture_output=True,
                    text=True, env=dict(os.environ, EXTEND_EXIT=str(extend_exit)))

            with open(run, "w"), open(run + ".log", "w") as log:
                log.write("the first run\n")
            done = make(0)
            self.assertEqual(done.returncode, 0, done.stdout + done.stderr)
            self.assertEqual(read(run + ".log"), "the first run\npiece started with --extend\n")
            done = make(2)
            self.assertEqual(done.returncode, 0, done.stdout + done.stderr)
            self.assertEqual(read(run + ".log"), "piece started with --force\n")
            failed = make(3)
            self.assertNotEqual(failed.returncode, 0)
            self.assertIn("run failed", failed.stdout)
            self.assertEqual(read(run + ".log"), "piece started with --force\n"
                                                 "piece started with --extend\n")

    def test_runs_depend_on_their_resolved_configuration_not_the_protocol_file(self):
        import h5py
        with tempfile.TemporaryDirectory() as tmp:
            # Two finished runs from before the configuration files: one stored the configuration
            # the sweep resolves now (with the hinge yield it derived, which --print-config leaves
            # out), the other a different one.
            pts = json.loads(read(os.path.join(expand(GOOD, tmp)[2], "points.json")))["points"]
            good, stale = pts[0]["run"], pts[1]["run"]
            r = subprocess.run([SIM, "--print-config"] + pts[0]["args"], cwd=REPO,
                               capture_output=True, text=True, check=True)
            stored = r.stdout.replace("  plasticity: true\n", "  plasticity: true\n  plastic_c0: 0.5\n")
            for run, text in ((good, stored), (stale, stored.replace("nodes: 200", "nodes: 250"))):
                with h5py.File(run, "w") as f:
                    f["config"] = text
                os.utime(run, ns=(1000123456789, 1000123456789))  # make compares to the ns
            r, _, out = expand(GOOD, tmp, sim=True)
            self.assertEqual(r.returncode, 0, r.stderr)
            mk = read(os.path.join(out, "points.mk"))
            for p in pts:
                self.assertIn(f"{p['run']}: {p['run']}.args {p['run']}.config | $(SIM)", mk)
                printed = subprocess.run([SIM, "--print-config"] + p["args"], cwd=REPO,
                                         capture_output=True, text=True).stdout
                self.assertEqual(read(p["run"] + ".config"), printed)
            self.assertNotIn("protocols/axial_crumpling.yaml |", mk)
            self.assertEqual(os.stat(good + ".config").st_mtime_ns, 1000123456789)  # the run stands
            self.assertGreater(os.stat(stale + ".config").st_mtime, 1001)  # the run is redone
            # Rewritten only when the configuration changes.
            cfg = pts[2]["run"] + ".config"
            os.utime(cfg, (5, 5))
            self.assertEqual(expand(GOOD, tmp, sim=True)[0].returncode, 0)
            self.assertEqual(os.stat(cfg).st_mtime, 5)
            self.assertEqual(os.stat(good + ".config").st_mtime_ns, 1000123456789)
            self.assertEqual(expand(GOOD.replace("protocol.cycles: 3", "protocol.cycles: 4"), tmp,
                                    sim=True)[0].returncode, 0)
            self.assertGreater(os.stat(cfg).st_mtime, 5)
            # Without the simulator the rules fall back on the protocol file.
            with tempfile.TemporaryDirectory() as bare:
                r, _, out = expand(GOOD, bare)
                self.assertIn(f"{pts[0]['run'].replace(tmp, bare)}: {pts[0]['run'].replace(tmp, bare)}"
                              ".args protocols/axial_crumpling.yaml | $(SIM)",
                              read(os.path.join(out, "points.mk")))

    def test_a_run_from_before_the_area_barrier_stands_where_it_would_not_have_acted(self):
        import h5py
        import numpy as np
        with tempfile.TemporaryDirectory() as tmp:
            pts = json.loads(read(os.path.join(expand(GOOD, tmp)[2], "points.json")))["points"]
            printed = [subprocess.run([SIM, "--print-config"] + p["args"], cwd=REPO,
                                      capture_output=True, text=True, check=True).stdout
                       for p in pts[:3]]
            self.assertIn("  area_barrier: true\n", printed[0])
            before = [t.replace("  area_barrier: true\n", "") for t in printed]
            # Two runs with the same configuration from before the key: in one every stored
            # triangle kept most of its area, in the other one triangle fell to 0.55 of it, near
            # enough to the barrier's onset (0.5) that the run might have differed with it; a
            # third differs elsewhere too.
            ref = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], float)
            tri = np.array([[0, 1, 2], [1, 3, 2]])
            squashed = ref.copy()
            squashed[2] = [0, 0.55, 0]
            runs = ((pts[0]["run"], before[0], ref * 1.02), (pts[1]["run"], before[1], squashed),
                    (pts[2]["run"], before[2].replace("compaction: 0.5", "compaction: 0.4"), ref))
            for run, text, x in runs:
                with h5py.File(run, "w") as f:
                    f["config"] = text
                    f["mesh/triangles"] = tri
                    f["mesh/ref_positions"] = ref
                    f["frames/000000/x"] = ref
                    f["frames/000001/x"] = x
                os.utime(run, ns=(1000123456789, 1000123456789))
            r, _, out = expand(GOOD, tmp, sim=True)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(os.stat(pts[0]["run"] + ".config").st_mtime_ns, 1000123456789)
            self.assertGreater(os.stat(pts[1]["run"] + ".config").st_mtime, 1001)
            self.assertGreater(os.stat(pts[2]["run"] + ".config").st_mtime, 1001)
            # A configuration file written before the key, then rewritten with it: the same.
            cfg = pts[0]["run"] + ".config"
            with open(cfg, "w") as f:
                f.write(before[0])
            os.utime(cfg, (7, 7))
            self.assertEqual(expand(GOOD, tmp, sim=True)[0].returncode, 0)
            self.assertEqual(read(cfg), printed[0])
            self.assertEqual(os.stat(cfg).st_mtime_ns, 1000123456789)

    def test_a_subset_of_the_seeds_runs_first_and_the_rest_reuses_it(self):
        with tempfile.TemporaryDirectory() as tmp:
            r, _, out = expand(GOOD, tmp, extra=["--seeds", "7"])
            self.assertEqual(r.returncode, 0, r.stderr)
            doc = json.loads(read(os.path.join(out, "points.json")))
            self.assertEqual(doc["seeds"], ["7"])
            self.assertEqual(doc["sweep_seeds"], ["4", "7"])
            self.assertEqual({p["seed"] for p in doc["points"]}, {7})
            self.assertEqual(len(doc["points"]), 4)
            part = {p["run"] for p in doc["points"]}
            # Each group's ensemble depends on the list of its members, which names seed 7 only.
            group = doc["points"][0]["group"]
            ens = os.path.join(tmp, "res", "groups", group, "ensemble.json")
            members = ens[:-len(".json")] + ".members"
            self.assertEqual(read(members).split(),
                             [p["analysis"] for p in doc["points"] if p["group"] == group])
            self.assertIn(f"{members} | $(ANALYZE)", read(os.path.join(out, "points.mk")))
            os.utime(members, (5, 5))
            self.assertEqual(expand(GOOD, tmp, extra=["--seeds", "7"])[0].returncode, 0)
            self.assertEqual(os.stat(members).st_mtime, 5)  # the same members: not rewritten
            # The whole sweep later names the same run files for seed 7, so they are reused; the
            # ensembles, made of seed 7 alone so far, are made again with both seeds.
            r, _, out = expand(GOOD, tmp)
            self.assertEqual(r.returncode, 0, r.stderr)
            doc = json.loads(read(os.path.join(out, "points.json")))
            self.assertEqual(len(doc["points"]), 8)
            self.assertTrue(part <= {p["run"] for p in doc["points"]})
            self.assertEqual(len(read(members).split()), 2)
            self.assertGreater(os.stat(members).st_mtime, 5)
            # A seed the sweep does not have is refused, nothing written.
            fresh = os.path.join(tmp, "other")
            os.makedirs(fresh)
            r, _, out = expand(GOOD, fresh, extra=["--seeds", "7", "9"])
            self.assertEqual(r.returncode, 2)
            self.assertIn("--seeds 9: not among the sweep's seeds (4, 7)", r.stderr)
            self.assertFalse(os.path.exists(out))

    def test_a_subset_of_the_groups_likewise(self):
        with tempfile.TemporaryDirectory() as tmp:
            r, _, out = expand(GOOD, tmp, extra=["--groups", "compaction-0.27_nodes-300"])
            self.assertEqual(r.returncode, 0, r.stderr)
            doc = json.loads(read(os.path.join(out, "points.json")))
            self.assertEqual({p["group"] for p in doc["points"]}, {"compaction-0.27_nodes-300"})
            self.assertEqual(len(doc["points"]), 2)  # both seeds
            self.assertEqual(len(doc["sweep_groups"]), 4)
            rules = read(os.path.join(out, "points.mk"))
            self.assertNotIn("compaction-0.5_", rules)
            fresh = os.path.join(tmp, "other")
            os.makedirs(fresh)
            r, _, out = expand(GOOD, fresh, extra=["--groups", "compaction-0.9"])
            self.assertEqual(r.returncode, 2)
            self.assertIn("--groups compaction-0.9: not among the sweep's groups", r.stderr)
            self.assertFalse(os.path.exists(out))

    def test_keep_study_keeps_the_report_and_tables_not_the_runs(self):
        keep = os.path.join(REPO, "pipeline", "sweeps", "keep_study.py")
        with tempfile.TemporaryDirectory() as tmp:
            r, _, out = expand(GOOD, tmp)
            self.assertEqual(r.returncode, 0, r.stderr)
            res, kept = os.path.join(tmp, "res"), os.path.join(tmp, "kept")
            run = [sys.executable, keep, "--points", os.path.join(out, "points.json"),
                   "--results", res, "--out", kept]
            r = subprocess.run(run, capture_output=True, text=True)  # no report yet
            self.assertEqual(r.returncode, 2)
            self.assertIn("no report", r.stderr)
            doc = json.loads(read(os.path.join(out, "points.json")))
            for g in {p["group"] for p in doc["points"]}:
                os.makedirs(os.path.join(res, "groups", g), exist_ok=True)
                with open(os.path.join(res, "groups", g, "ensemble.json"), "w") as f:
                    json.dump({"seeds": [4, 7], "fits": {}, "stages": [], "threshold_sensitivity": {},
                               "runs": [], "cycles": [
                        {"cycle": n, "n_runs": 2, "perimeter_P_mean": 10.0 * n,
                         "perimeter_P_sem": 1.0} for n in (1, 2, 3)]}, f)
            with open(os.path.join(res, "REPORT.md"), "w") as f:
                f.write("# Sweep `s`\n\nbody\n")
            with open(os.path.join(res, "collapse.json"), "w") as f:
                f.write("{}")
            # compare_groups.py's outputs, the default name and a named one; not other files.
            for name in ("COMPARISON.md", "COMPARISON.json", "COMPARISON_unfold.md",
                         "COMPARISON_unfold.json", "COMPARISON_notes.txt"):
                with open(os.path.join(res, name), "w") as f:
                    f.write("x")
            # Two runs analysed, the first with its roll axes recorded (30, 170, 100 degrees:
            # 40 and 70 from the axes before), the second from a file that has none.
            import h5py
            for k, p in enumerate(doc["points"][:2]):
                os.makedirs(p["analysis"])
                with open(os.path.join(p["analysis"], "stats.json"), "w") as f:
                    json.dump({"cycles": [{"cycle": n, "compaction": 0.5, "perimeter_P": 5.0 * n}
                                          for n in (1, 2, 3)]}, f)
                with h5py.File(p["run"], "w") as f:
                    for n, axis in enumerate((30.0, 170.0, 100.0), start=1):
                        for j, stage in enumerate(("roll", "compress")):
                            e = f.create_group(f"stage_ends/{2 * n + j:06d}").attrs
                            e["cycle"], e["stage"] = n, stage
                            if k == 0 and stage == "roll":
                                e["roll_axis_deg"] = axis
                    if k == 0:
                        f.create_group("log").attrs["wall_total"] = 1234.56
            r = subprocess.run(run, capture_output=True, text=True)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(sorted(os.listdir(kept)),
                             ["COMPARISON.json", "COMPARISON.md", "COMPARISON_unfold.json",
                              "COMPARISON_unfold.md", "REPORT.md", "collapse.json", "groups.csv",
                              "runs.csv"])
            with open(os.path.join(kept, "runs.csv")) as f:
                runs = list(csv.DictReader(l for l in f if not l.startswith("#")))
            self.assertEqual(len(runs), 6)  # two runs x three cycles
            first = [r for r in runs if r["seed"] == str(doc["points"][0]["seed"]) and
                     r["group"] == doc["points"][0]["group"]]
            self.assertEqual([r["novelty_deg"] for r in first], ["", "40.0", "70.0"])
            self.assertEqual([r["perimeter_P"] for r in first], ["5.0", "10.0", "15.0"])
            self.assertTrue(all(r["roll_axis_deg"] == "" for r in runs if r not in first))
            self.assertEqual([r["run_wall_s"] for r in first], ["1234.6"] * 3)
            self.assertTrue(all(r["run_wall_s"] == "" for r in runs if r not in first))
            report = read(os.path.join(kept, "REPORT.md"))
            self.assertTrue(report.startswith("# Sweep `s`\n\n> Kept in the repository"), report)
            # Kept outside docs/studies/NAME: the note gives the script's command, not make keep-study.
            self.assertIn("keep_study.py --points", report)
            self.assertNotIn("make keep-study", report)
            self.assertIn("body", report)
            rows = [l for l in read(os.path.join(kept, "groups.csv")).splitlines()
                    if not l.startswith("#")]
            self.assertEqual(len(rows), 1 + 4 * 3)  # header, 4 groups x 3 cycles
            self.assertIn(",3,2,4 7,30.0,,1.0,", rows[-1])
            # A fit over a subset kept beside the study's own: only the fit files, renamed.
            before = sorted(os.listdir(kept))
            with open(os.path.join(res, "collapse.json"), "w") as f:
                f.write('{"subset": true, "compactions": [0.27, 0.63]}')
            with open(os.path.join(res, "PREDICTIONS.md"), "w") as f:
                f.write("subset table")
            r = subprocess.run(run + ["--fit-as", "0.27-0.63"], capture_output=True, text=True)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertEqual(sorted(os.listdir(kept)),
                             sorted(before + ["PREDICTIONS_0.27-0.63.md", "collapse_0.27-0.63.json"]))
            self.assertEqual(read(os.path.join(kept, "collapse.json")), "{}")
            self.assertEqual(read(os.path.join(kept, "collapse_0.27-0.63.json")),
                             '{"subset": true, "compactions": [0.27, 0.63]}')
            self.assertIn("compactions 0.27 0.63", r.stdout)
            for bad in ("../x", "a b", ""):
                r = subprocess.run(run + ["--fit-as", bad], capture_output=True, text=True)
                self.assertEqual(r.returncode, 2, bad)
                self.assertIn("--fit-as", r.stderr)
            for f in ("collapse.json", "PREDICTIONS.md"):
                os.remove(os.path.join(res, f))
            r = subprocess.run(run + ["--fit-as", "none"], capture_output=True, text=True)
            self.assertEqual(r.returncode, 2)
            self.assertIn("no fit to keep", r.stderr)
            self.assertEqual(sorted(os.listdir(kept)),
                             sorted(before + ["PREDICTIONS_0.27-0.63.md", "collapse_0.27-0.63.json"]))

    def test_a_sweep_made_in_parts_takes_kept_runs_in_place_of_runs(self):
        # Machine A runs one point and keeps it (make keep-runs); machine B, with no runs/ of its
        # own, analyses that point from its summary and runs only the rest.
        keep = os.path.join(REPO, "pipeline", "sweeps", "kept_runs.py")
        sys.path.insert(0, os.path.join(REPO, "pipeline", "sweeps"))
        import h5py
        import kept_runs
        with tempfile.TemporaryDirectory() as tmp:
            a, b, kdir = (os.path.join(tmp, d) for d in ("a", "b", "kept"))
            os.makedirs(a)
            os.makedirs(b)
            r, _, out = expand(GOOD, a, sim=True, extra=["--kept", kdir])
            self.assertEqual(r.returncode, 0, r.stderr)
            points = os.path.join(out, "points.json")
            keep_runs = [sys.executable, keep, "--points", points, "--out", kdir]
            r = subprocess.run(keep_runs, capture_output=True, text=True)
            self.assertEqual(r.returncode, 2)  # nothing run yet: nothing kept
            self.assertIn("no finished, analysed run to keep", r.stderr)
            p0 = json.loads(read(points))["points"][0]
            stats = {"input": {"meta": {"program_version": "9.9.9", "git_revision": "abc",
                                        "seed": p0["seed"], "status": "complete"}},
                     "cycles": [{"cycle": n, "perimeter_P": 4.0 * n} for n in (1, 2, 3)]}
            with h5py.File(p0["run"], "w") as f:
                f["config"] = read(p0["run"] + ".config")
                for n, axis in enumerate((30.0, 170.0, 100.0), start=1):
                    e = f.create_group(f"stage_ends/{n:06d}").attrs
                    e["cycle"], e["stage"], e["roll_axis_deg"] = n, "roll", axis
                f.create_group("log").attrs["wall_total"] = 99.5
            os.makedirs(p0["analysis"])
            summary = os.path.join(kdir, p0["group"], f"seed{p0['seed']}.json")

            def analysed(when):
                with open(os.path.join(p0["analysis"], "stats.json"), "w") as f:
                    json.dump(stats, f)
                os.utime(os.path.join(p0["analysis"], "stats.json"), (when, when))
            # Not kept while it is not a finished, current run and analysis.
            run_time = os.stat(p0["run"]).st_mtime
            for stale, why in ((lambda: analysed(run_time - 10), "analysis is older than the run"),
                               (lambda: open(p0["run"] + ".tmp", "w").close(), "a checkpoint"),
                               (lambda: os.utime(p0["run"] + ".args", (run_time + 5, run_time + 5)),
                                "arguments or configuration changed after it ran")):
                analysed(run_time + 10)
                stale()
                r = subprocess.run(keep_runs, capture_output=True, text=True)
                self.assertEqual(r.returncode, 2, why)
                self.assertIn(why, r.stdout)
                self.assertFalse(os.path.exists(summary))
                if os.path.exists(p0["run"] + ".tmp"):
                    os.remove(p0["run"] + ".tmp")
                os.utime(p0["run"] + ".args", (run_time - 5, run_time - 5))
            analysed(run_time + 10)
            r = subprocess.run(keep_runs, capture_output=True, text=True)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertIn("1 runs kept", r.stdout)
            self.assertIn("not kept, not run or not analysed yet: ", r.stdout)
            s = json.loads(read(summary))
            self.assertEqual((s["args"], s["stats"], s["run_wall_s"]), (p0["args"], stats, 99.5))
            self.assertEqual(s["config"], read(p0["run"] + ".config"))
            self.assertEqual(s["roll_axis_deg"], {"1": 30.0, "2": 170.0, "3": 100.0})
            # Machine B, where an analysis from before was left: the kept point is analysed from
            # its summary (the configuration resolved again and compared) and has no run rule.
            target = os.path.join(b, "runs", p0["group"], f"seed{p0['seed']}.analysis", "stats.json")
            os.makedirs(os.path.dirname(target))
            with open(target, "w") as f:
                f.write('{"cycles": []}\n')
            r, _, out_b = expand(GOOD, b, sim=True, extra=["--kept", kdir])
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertIn("1 runs analysed from their summaries", r.stdout)
            pts_b = json.loads(read(os.path.join(out_b, "points.json")))["points"]
            q0 = pts_b[0]
            self.assertEqual(q0["analysis"] + "/stats.json", target)
            self.assertEqual(q0["kept"], summary)
            self.assertFalse(any(q.get("kept") for q in pts_b[1:]))
            self.assertEqual(json.loads(read(target)), stats)
            rules = read(os.path.join(out_b, "points.mk"))
            self.assertNotIn(f"{q0['run']}:", rules)
            self.assertNotIn(q0["run"], rules.split("SWEEP_RUNS := ")[1].split("\n")[0])
            self.assertIn(pts_b[1]["run"] + ":", rules)
            os.remove(target)  # the make rule restores it
            r = subprocess.run(["make", "--no-print-directory", "-f", os.path.join(out_b, "points.mk"),
                                "PYTHON=" + sys.executable, "SIM=/bin/false", "ANALYZE=/bin/false",
                                target], cwd=REPO, capture_output=True, text=True)
            self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
            self.assertEqual(json.loads(read(target)), stats)
            # keep_study.py's runs.csv reads the rolls and wall from the summary.
            self.assertEqual(kept_runs.rolls_and_wall(q0), ({1: 30.0, 2: 170.0, 3: 100.0}, 99.5))
            # Keeping B's runs leaves the summary it took as it was.
            os.utime(summary, (5, 5))
            r = subprocess.run([sys.executable, keep, "--points", os.path.join(out_b, "points.json"),
                                "--out", kdir], capture_output=True, text=True)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertIn("1 runs were taken from their summaries", r.stdout)
            self.assertEqual(os.stat(summary).st_mtime, 5)
            # A changed sweep or analysis option, or a run file here, and the point runs.
            for k, (sweep, why) in enumerate((
                    (GOOD.replace("cycles: 3", "cycles: 4"), "made with other crumple-sim arguments"),
                    (GOOD + "analyze: --px-per-edge 12\n", "analysed with other crumple-analyze options"))):
                c = os.path.join(tmp, f"c{k}")
                os.makedirs(c)
                r, _, out_c = expand(sweep, c, extra=["--kept", kdir])
                self.assertEqual(r.returncode, 0, r.stderr)
                self.assertIn(f"not taken for {p0['name']}, which runs: {why}", r.stdout)
                self.assertFalse(any(q.get("kept") for q in
                                     json.loads(read(os.path.join(out_c, "points.json")))["points"]))
            with open(q0["run"], "w"):
                pass
            r, _, out_b = expand(GOOD, b, extra=["--kept", kdir])
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertFalse(json.loads(read(os.path.join(out_b, "points.json")))["points"][0].get("kept"))
            # A configuration that resolves otherwise does not stand either.
            self.assertIsNone(kept_runs.mismatch(s, p0, s["config"]))
            self.assertIn("resolves otherwise",
                          kept_runs.mismatch(s, p0, s["config"].replace("200", "250")))
            # A summary that is not one stops the sweep, naming the file and key, nothing written.
            s.pop("config")
            with open(summary, "w") as f:
                json.dump(s, f)
            fresh = os.path.join(tmp, "d")
            os.makedirs(fresh)
            r, _, out_d = expand(GOOD, fresh, extra=["--kept", kdir])
            self.assertEqual(r.returncode, 2)
            self.assertIn(f"{summary}: config: missing", r.stderr)
            self.assertFalse(os.path.exists(out_d))

    def test_a_ladder_in_node_count_gets_the_convergence_table(self):
        ladder = GOOD.replace("  protocol.stages.compress.compaction: [0.5, 0.27]\n", "")
        with tempfile.TemporaryDirectory() as tmp:
            r, _, out = expand(ladder, tmp)
            self.assertEqual(r.returncode, 0, r.stderr)
            doc = json.loads(read(os.path.join(out, "points.json")))
            self.assertTrue(doc["convergence"])
            self.assertFalse(doc["collapse"])
            self.assertIn("SWEEP_CONVERGENCE := yes", read(os.path.join(out, "points.mk")))
        with tempfile.TemporaryDirectory() as tmp:
            r, _, _ = expand(ladder + "convergence: false\n", tmp)
            self.assertEqual(r.returncode, 0, r.stderr)
        with tempfile.TemporaryDirectory() as tmp:
            r, _, out = expand(GOOD + "convergence: true\n", tmp)
            self.assertEqual(r.returncode, 2)
            self.assertIn("s.yaml:10: convergence: a convergence ladder varies mesh.nodes alone",
                          r.stderr)
            self.assertFalse(os.path.exists(out))

    def test_analysis_options_reach_every_analysis(self):
        with tempfile.TemporaryDirectory() as tmp:
            r, _, out = expand(GOOD + "analyze: --px-per-edge 24\n", tmp)
            self.assertEqual(r.returncode, 0, r.stderr)
            pts = json.loads(read(os.path.join(out, "points.json")))["points"]
            mk = read(os.path.join(out, "points.mk"))
            for p in pts:
                self.assertIn(f"$(ANALYZE) $< -o {p['analysis']} --px-per-edge 24 >", mk)
                self.assertIn(f"{p['analysis']}/stats.json: {p['run']} {p['analysis']}.args", mk)
                self.assertEqual(read(p["analysis"] + ".args"), "--px-per-edge 24\n")
        for bad in ("analyze: -o elsewhere\n", "analyze: runs/x.h5\n"):
            with self.subTest(bad=bad), tempfile.TemporaryDirectory() as tmp:
                r, _, out = expand(GOOD + bad, tmp)
                self.assertEqual(r.returncode, 2)
                self.assertIn("s.yaml:10: analyze: ", r.stderr)
                self.assertFalse(os.path.exists(out))

    def test_a_sweep_of_another_sweeps_runs_analyses_them_again(self):
        with tempfile.TemporaryDirectory() as tmp:
            with open(os.path.join(tmp, "base.yaml"), "w") as f:
                f.write(GOOD + "analyze: --px-per-edge 24\n")
            again = ("description: again\nruns_of: base\n"
                     "analyze: --px-per-edge 24 --close-mm 1.3\n")
            r, _, out = expand(again, tmp, sim=True)
            self.assertEqual(r.returncode, 0, r.stderr)
            doc = json.loads(read(os.path.join(out, "points.json")))
            self.assertEqual(doc["runs_of"], "base")
            self.assertEqual(doc["description"], "again")
            self.assertEqual(doc["name"], "s")
            self.assertEqual(len(doc["points"]), 8)  # the base's grid and seeds
            base_runs = os.path.join(tmp, "base")  # the base's folder beside OUT_DIR
            mk = read(os.path.join(out, "points.mk"))
            for p in doc["points"]:
                # The base's run file and arguments, this sweep's analysis and options.
                self.assertEqual(p["run"], os.path.join(base_runs, p["group"], f"seed{p['seed']}.h5"))
                self.assertEqual(p["analysis"], os.path.join(out, p["group"],
                                                             f"seed{p['seed']}.analysis"))
                self.assertIn("protocol.cycles=3", p["args"])
                self.assertIn(f"$(ANALYZE) $< -o {p['analysis']} --px-per-edge 24 --close-mm 1.3 >",
                              mk)
                self.assertEqual(read(p["analysis"] + ".args"), "--px-per-edge 24 --close-mm 1.3\n")
            # The base expanded into its own folder names the same run files with the same
            # arguments, so a run made by either is the other's.
            r2 = subprocess.run([sys.executable, EXPAND, os.path.join(tmp, "base.yaml"), "--out-dir",
                                 base_runs, "--results", os.path.join(tmp, "res_base")],
                                cwd=REPO, capture_output=True, text=True)
            self.assertEqual(r2.returncode, 0, r2.stderr)
            base = json.loads(read(os.path.join(base_runs, "points.json")))["points"]
            self.assertEqual([(p["run"], p["args"]) for p in base],
                             [(p["run"], p["args"]) for p in doc["points"]])
            self.assertNotIn(out, " ".join(p["analysis"] for p in base))
        # What the other sweep states cannot be stated again, and the other must exist and make
        # its own runs; nothing is written.
        cases = [("runs_of: base\ngrid:\n  mesh.nodes: [300]\n", "s.yaml:2: grid: comes from "
                  "the sweep named by runs_of"),
                 ("runs_of: nothere\n", "s.yaml:1: runs_of: no sweep 'nothere'"),
                 ("runs_of: middle\n", "s.yaml:1: runs_of: middle is itself a sweep of base's runs"),
                 ("runs_of: s\n", "s.yaml:1: runs_of: names this sweep itself")]
        for text, expect in cases:
            with self.subTest(expect=expect), tempfile.TemporaryDirectory() as tmp:
                with open(os.path.join(tmp, "base.yaml"), "w") as f:
                    f.write(GOOD)
                with open(os.path.join(tmp, "middle.yaml"), "w") as f:
                    f.write("runs_of: base\n")
                r, _, out = expand(text, tmp)
                self.assertEqual(r.returncode, 2, r.stderr)
                self.assertIn(expect, r.stderr)
                self.assertFalse(os.path.exists(out), "nothing is written")

    def test_bad_sweep_files_name_line_and_key(self):
        cases = [
            (GOOD.replace("seeds:", "seedz:"), "s.yaml:9: seedz: unknown key"),
            (GOOD.replace("preset: tiny", "preset: huge"), "s.yaml:2: preset: no preset 'huge'"),
            (GOOD.replace("axial_crumpling", "nope"), "s.yaml:3: protocol: no such file"),
            (GOOD.replace("[4, 7]", "[4, 4]"), "s.yaml:9: seeds: a seed appears twice"),
            (GOOD.replace("[4, 7]", "[4, x]"), "s.yaml:9: seeds: 'x' is not a seed"),
            (GOOD.replace("[200, 300]", "300"),
             "s.yaml:8: grid.mesh.nodes: expected a non-empty list"),
            ("\n".join(l for l in GOOD.splitlines() if "grid" not in l and "  " not in l),
             "grid: missing"),
            ("[1, 2]", "a sweep file is a mapping"),
            ("grid: [", "not valid YAML"),
        ]
        for text, expect in cases:
            with self.subTest(expect=expect), tempfile.TemporaryDirectory() as tmp:
                r, path, out = expand(text, tmp)
                self.assertEqual(r.returncode, 2, r.stderr)
                self.assertIn(expect, r.stderr)
                self.assertFalse(os.path.exists(out), "nothing is written")

    def test_a_mistyped_grid_key_is_caught_before_any_run(self):
        with tempfile.TemporaryDirectory() as tmp:
            r, _, out = expand(GOOD.replace("mesh.nodes:", "mesh.nodez:"), tmp, sim=True)
            self.assertEqual(r.returncode, 2, r.stderr)
            self.assertIn("is not a valid configuration", r.stderr)
            self.assertIn("mesh.nodez", r.stderr)
            self.assertFalse(os.path.exists(out))

    def test_every_shipped_sweep_resolves_with_this_program(self):
        # The shipped sweeps name keys, presets and protocol files that later changes can rename
        # or remove; a sweep that no longer resolves would be found only when someone next runs
        # it. Expanding each with --sim resolves every point's configuration (seconds in all).
        # Expanded where it lies, not through expand(), which copies the text elsewhere: a sweep
        # of another's runs (runs_of) finds that sweep beside its own file.
        folder = os.path.join(REPO, "pipeline", "sweeps")
        names = sorted(f[:-5] for f in os.listdir(folder) if f.endswith(".yaml"))
        self.assertIn("convergence_flat_unfold", names)
        with tempfile.TemporaryDirectory() as tmp:
            for name in names:
                with self.subTest(sweep=name):
                    r = subprocess.run([sys.executable, EXPAND, os.path.join(folder, name + ".yaml"),
                                        "--out-dir", os.path.join(tmp, name),
                                        "--results", os.path.join(tmp, "res", name), "--sim", SIM,
                                        # its kept run summaries, if any, must be readable ones
                                        "--kept", os.path.join(REPO, "docs", "studies", name, "runs")],
                                       cwd=REPO, capture_output=True, text=True)
                    self.assertEqual(r.returncode, 0, r.stderr)
                    points = json.loads(read(os.path.join(tmp, name, "points.json")))
                    self.assertTrue(points["points"], name)


class RunConfig(unittest.TestCase):
    """pipeline/sweeps/run_config.py as make reproduce calls it for each run."""
    RUN_CONFIG = os.path.join(REPO, "pipeline", "sweeps", "run_config.py")
    ARGS = ["protocols/axial_crumpling.yaml", "--seed", "3", "--set", "mesh.nodes=200"]

    def call(self, run, args):
        return subprocess.run([sys.executable, self.RUN_CONFIG, run, "--", SIM] + args, cwd=REPO,
                              capture_output=True, text=True)

    def test_written_when_changed_and_a_matching_run_stands(self):
        import h5py
        with tempfile.TemporaryDirectory() as tmp:
            run = os.path.join(tmp, "runs", "seed3.h5")
            r = self.call(run, self.ARGS)
            self.assertEqual(r.returncode, 0, r.stderr)
            printed = subprocess.run([SIM, "--print-config"] + self.ARGS, cwd=REPO,
                                     capture_output=True, text=True, check=True).stdout
            self.assertEqual(read(run + ".config"), printed)
            os.utime(run + ".config", (5, 5))
            self.assertEqual(self.call(run, self.ARGS).returncode, 0)
            self.assertEqual(os.stat(run + ".config").st_mtime, 5)  # unchanged: not rewritten
            # A finished run that stored this configuration: the rewritten file takes its date.
            with h5py.File(run, "w") as f:
                f["config"] = printed
            os.utime(run, ns=(1000123456789, 1000123456789))
            self.assertEqual(self.call(run, self.ARGS + ["--set", "mesh.nodes=250"]).returncode, 0)
            self.assertGreater(os.stat(run + ".config").st_mtime, 1001)  # changed: the run is redone
            self.assertEqual(self.call(run, self.ARGS).returncode, 0)
            self.assertEqual(os.stat(run + ".config").st_mtime_ns, 1000123456789)  # back: it stands

    def test_an_invalid_configuration_writes_nothing(self):
        with tempfile.TemporaryDirectory() as tmp:
            run = os.path.join(tmp, "seed3.h5")
            r = self.call(run, self.ARGS + ["--set", "protocol.bogus=1"])
            self.assertEqual(r.returncode, 2)
            self.assertIn("protocol.bogus", r.stderr)
            self.assertIn(run, r.stderr)
            self.assertFalse(os.path.exists(run + ".config"))
            self.assertEqual(subprocess.run([sys.executable, self.RUN_CONFIG, run], cwd=REPO,
                                            capture_output=True, text=True).returncode, 2)


if __name__ == "__main__":
    SIM = os.path.abspath(sys.argv.pop(1))
    unittest.main()
