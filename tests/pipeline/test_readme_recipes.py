#!/usr/bin/python3
"""Every recipe of README.md works as written (issue 37, item 7).

A recipe is a fenced block marked `<!-- recipe: NAME -->` on the line(s) just before it (a run of
HTML comment lines); it is run as written, ```sh / ```bash with `bash -eu -o pipefail`, ```python
with /usr/bin/python3, from the root of a copy of the checkout, in README order (later recipes may
use what earlier ones made, as a reader's would). Every other fenced block must be marked
`<!-- not-a-recipe: REASON -->`, the reason naming what covers it instead; an unmarked block fails
the test, so a new block cannot escape it.

What differs from a reader's machine, and why:
  - the copy: the checkout's files without build/, runs/, results/ and .git, so that nothing the
    recipes write lands in the checkout (runs/sweeps, docs/studies, protocols/);
  - build/ in the copy holds only the two binaries given, and `make` is called with `-o build`
    (a wrapper first on PATH): the test runs after the build and must not rebuild;
  - PRESET=tiny in the environment (README, "The recipes in this file"), the one size setting;
  - the compaction sweep is a stand-in of one tiny grid point and two seeds, written into the
    copy's pipeline/sweeps/compaction_flat_unfold.yaml (the real one takes hours);
  - the resume recipe needs a stopped run: the test starts that recipe's own command and stops
    it with SIGINT, as Ctrl-C would, once its first checkpoint is written;
  - the Python reader's recipe reads make reproduce's first seed: the analysis of the run the
    first recipe made stands in for it.
Bad input to the recipe targets (pipeline/recipes.mk) is checked too: exit 2, a message naming
the problem, nothing written.

usage: test_readme_recipes.py CRUMPLE_SIM CRUMPLE_ANALYZE [--keep]   (from the repository root;
--keep leaves the copy and the recipes' logs in place and prints where)
"""
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import unittest

REPO = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SIM = ANALYZE = None
KEEP = False
BLOCK_TIMEOUT_S = 600

FENCE = re.compile(r"^\s*```\s*([\w+-]*)\s*$")
COMMENT = re.compile(r"^\s*<!--\s*(.*?)\s*-->\s*$")
RUNNERS = {"sh": ["bash", "-eu", "-o", "pipefail", "-c"], "bash": ["bash", "-eu", "-o", "pipefail", "-c"],
           "python": ["/usr/bin/python3", "-c"]}

# One tiny point of the compaction sweep, for the sweep recipe (pipeline/sweeps/README.md).
SWEEP_STANDIN = """# Stand-in written by tests/pipeline/test_readme_recipes.py: one tiny point, two seeds.
description: stand-in for the README's sweep recipe (tiny preset, one grid point)
preset: tiny
protocol: protocols/axial_crumpling.yaml
grid:
  protocol.stages.compress.compaction: [0.27]
seeds: [1, 2]
collapse: false
"""


def parse_blocks(text):
    """The fenced blocks of a Markdown text: dicts of line (1-based, of the opening fence), lang,
    code and markers (the comments on the lines just above it)."""
    lines = text.splitlines()
    blocks, i = [], 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        start, lang = i, m.group(1)
        j = i + 1
        while j < len(lines) and not FENCE.match(lines[j]):
            j += 1
        markers, k = [], start - 1
        while k >= 0 and COMMENT.match(lines[k]):
            markers.insert(0, COMMENT.match(lines[k]).group(1))
            k -= 1
        blocks.append({"line": start + 1, "lang": lang, "code": "\n".join(lines[start + 1:j]) + "\n",
                       "markers": markers})
        i = j + 1
    return blocks


def classify(blocks):
    """(recipes, problems): the recipe blocks with their names, and what is wrong with the
    marking of any block."""
    recipes, problems, names = [], [], set()
    for b in blocks:
        where = f"README.md:{b['line']}"
        rec = [m.split(":", 1)[1].strip() for m in b["markers"] if m.startswith("recipe:")]
        skip = [m.split(":", 1)[1].strip() for m in b["markers"] if m.startswith("not-a-recipe:")]
        if len(rec) + len(skip) != 1:
            problems.append(f"{where}: a fenced block needs exactly one marker on the line before it, "
                            "<!-- recipe: NAME --> or <!-- not-a-recipe: what covers it -->"
                            f" (has {b['markers'] or 'none'})")
        elif skip and not skip[0]:
            problems.append(f"{where}: <!-- not-a-recipe: ... --> must say what covers the block")
        elif rec:
            name = rec[0]
            if not re.fullmatch(r"[\w-]+", name) or name in names:
                problems.append(f"{where}: recipe name '{name}' empty, malformed or used twice")
            elif b["lang"] not in RUNNERS:
                problems.append(f"{where}: recipe '{name}' must be a ```sh, ```bash or ```python block")
            names.add(name)
            recipes.append(dict(b, name=name))
    return recipes, problems


def tree(root):
    """Every path below root (for 'nothing written')."""
    out = set()
    for d, dirs, files in os.walk(root):
        out.update(os.path.relpath(os.path.join(d, n), root) for n in dirs + files)
    return out


class Sandbox:
    """A copy of the checkout to run the recipes in, with the given binaries and make -o build."""

    def __init__(self):
        self.tmp = tempfile.mkdtemp(prefix="readme-recipes-")
        self.root = os.path.join(self.tmp, "checkout")
        self.logs = os.path.join(self.tmp, "logs")
        os.makedirs(self.logs)

        def ignore(d, names):
            drop = {"__pycache__"}
            if os.path.samefile(d, REPO):
                drop |= {n for n in names if n in ("build", "runs", "results", ".git") or n.startswith("build-")}
            return drop & set(names)
        shutil.copytree(REPO, self.root, symlinks=True, ignore=ignore)
        for binary, rel in ((SIM, "sim/apps/crumple-sim"), (ANALYZE, "analysis/apps/crumple-analyze")):
            dst = os.path.join(self.root, "build", rel)
            os.makedirs(os.path.dirname(dst), exist_ok=True)
            os.symlink(os.path.abspath(binary), dst)
        bindir = os.path.join(self.tmp, "bin")
        os.makedirs(bindir)
        with open(os.path.join(bindir, "make"), "w") as f:
            f.write(f'#!/bin/sh\n# the build is done: ctest runs after it\nexec {shutil.which("make")} -o build "$@"\n')
        os.chmod(os.path.join(bindir, "make"), 0o755)
        # A reader's shell: no make variables inherited from a make that started ctest.
        keep = ("HOME", "USER", "LANG", "LC_ALL", "LC_CTYPE", "TMPDIR", "TERM")
        self.env = {k: v for k, v in os.environ.items() if k in keep}
        self.env.update(PATH=bindir + os.pathsep + os.environ.get("PATH", "/usr/bin:/bin"),
                        PRESET="tiny", MPLBACKEND="Agg")

    def path(self, *parts):
        return os.path.join(self.root, *parts)

    def command(self, recipe):
        return RUNNERS[recipe["lang"]] + [recipe["code"]]

    def run(self, args, log_name, timeout=BLOCK_TIMEOUT_S):
        """Runs args in the copy's root; (exit code, output), the output kept in a log."""
        log = os.path.join(self.logs, log_name + ".log")
        with open(log, "w") as f:
            try:
                r = subprocess.run(args, cwd=self.root, env=self.env, stdout=f, stderr=subprocess.STDOUT,
                                   timeout=timeout)
                code = r.returncode
            except subprocess.TimeoutExpired:
                code = f"timeout after {timeout} s"
        with open(log) as f:
            return code, f.read()

    def close(self):
        if KEEP:
            print(f"kept: {self.root} (logs in {self.logs})")
        else:
            shutil.rmtree(self.tmp, ignore_errors=True)


# --- what each recipe needs before it and leaves after it ---------------------------------------

def stop_run_at_checkpoint(sb, recipe):
    """A stopped run for the resume recipe: its own command started afresh and stopped by SIGINT
    to its process group (Ctrl-C) once the first checkpoint RUN.h5.tmp is written."""
    for f in ("runs/a.h5", "runs/a.xdmf", "runs/a.cycles.xdmf"):
        if os.path.exists(sb.path(f)):
            os.remove(sb.path(f))
    with open(os.path.join(sb.logs, "resume-stopped.log"), "w") as log:
        p = subprocess.Popen(sb.command(recipe), cwd=sb.root, env=sb.env, stdout=log,
                             stderr=subprocess.STDOUT, start_new_session=True)
        deadline = time.time() + 300
        while not os.path.exists(sb.path("runs/a.h5.tmp")) and p.poll() is None and time.time() < deadline:
            time.sleep(0.1)
        if p.poll() is None:
            os.killpg(p.pid, signal.SIGINT)
        p.wait(timeout=300)
    assert os.path.exists(sb.path("runs/a.h5.tmp")) and not os.path.exists(sb.path("runs/a.h5")), \
        "could not stop the run at a checkpoint (see resume-stopped.log)"


def reproduce_seed_for_reader(sb, recipe):
    """make reproduce's first seed, which the reader's example reads: the analysis of runs/a.h5."""
    r = subprocess.run([ANALYZE, "runs/a.h5", "-o", "runs/quick/axial_crumpling/seed1.analysis"],
                       cwd=sb.root, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr


def write_sweep_standin(sb, recipe):
    with open(sb.path("pipeline/sweeps/compaction_flat_unfold.yaml"), "w") as f:
        f.write(SWEEP_STANDIN)


def exists(*paths):
    def check(sb, out):
        for p in paths:
            assert os.path.exists(sb.path(p)), f"{p} missing"
    return check


def check_run(sb, out):
    exists("runs/a.h5")(sb, out)
    assert "--threads 1" in out, "make run did not pass the preset's threads"
    assert "compress:" in out and "protocol.cycles" in out, "--list-stages / --list-keys said nothing"


def check_resume(sb, out):
    exists("runs/a.h5")(sb, out)
    assert "--resume" in out, "make run did not resume from the checkpoint"
    assert not os.path.exists(sb.path("runs/a.h5.tmp")), "the checkpoint is still pending"


def check_compare(sb, out):
    exists("runs/mine/compare/REPORT.md", "runs/mine/compare/ensemble.json", "runs/mine/seed3.analysis/stats.json")(sb, out)
    with open(sb.path("runs/mine/compare/compared_runs.txt")) as f:
        assert f.read().split() == [f"runs/mine/seed{s}.h5" for s in (1, 2, 3)]
    assert not os.path.exists(sb.path("runs/mine/compare.part")), "staging folder left behind"


HOOKS = {  # name: (before, check after)
    "run": (None, check_run),
    "resume": (stop_run_at_checkpoint, check_resume),
    "sweep": (write_sweep_standin, exists("results/compaction_flat_unfold/REPORT.md", "docs/studies/compaction_flat_unfold")),
    "python-reader": (reproduce_seed_for_reader, exists("P.png")),
    "compare": (None, check_compare),
    "protocol": (None, exists("protocols/mine.yaml", "runs/mine.h5")),
}

# Bad input to the recipe targets: (make arguments, a file to create first or None, message).
BAD_INPUT = [
    (["run"], None, "make run: give RUN="),
    (["run", "RUN=runs/x.h5", "PROTOCOL=protocols/nope.yaml"], None, "protocols/nope.yaml: no such protocol file"),
    (["compare"], None, "make compare: give RUN="),
    (["compare", "RUN=runs/nope.h5"], None, "runs/nope.h5: no such run file"),
    (["compare", "RUN=runs/pending.h5"], "runs/pending.h5.tmp", "runs/pending.h5: not finished"),
    (["compare", "RUN=runs/fake.h5", "OUT=docs"], "runs/fake.h5", "OUT=docs holds other files"),
    (["compare", "RUN=runs/fake.h5"], "runs/fake.h5", "not an HDF5 file"),
    (["protocol"], None, "make protocol: give NAME="),
    (["protocol", "NAME=protocols/x.yaml"], None, "make protocol: give NAME="),
    (["protocol", "NAME=x", "FROM=protocols/nope.yaml"], None, "FROM=protocols/nope.yaml: no such protocol file"),
]


class ReadmeRecipes(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        with open(os.path.join(REPO, "README.md")) as f:
            cls.blocks = parse_blocks(f.read())
        cls.recipes, cls.problems = classify(cls.blocks)
        cls.sb = Sandbox()

    @classmethod
    def tearDownClass(cls):
        cls.sb.close()

    def test_every_block_is_marked(self):
        self.assertGreater(len(self.blocks), 5, "README.md: no fenced blocks found")
        self.assertEqual(self.problems, [], "\n".join(self.problems))
        names = {r["name"] for r in self.recipes}
        # The test's own preparations must not outlive the recipes they serve.
        self.assertEqual(set(HOOKS) - names, set(), "recipes this test prepares are gone from README.md")

    def test_recipes_run_as_written(self):
        for r in self.recipes:
            with self.subTest(recipe=r["name"], line=r["line"]):
                before, check = HOOKS.get(r["name"], (None, None))
                if before:
                    before(self.sb, r)
                t0 = time.time()
                code, out = self.sb.run(self.sb.command(r), r["name"])
                print(f"recipe {r['name']} (README.md:{r['line']}): exit {code}, {time.time() - t0:.0f} s",
                      flush=True)
                self.assertEqual(code, 0, f"recipe '{r['name']}' (README.md:{r['line']}) failed; its output ends:\n"
                                 + "\n".join(out.splitlines()[-30:]))
                if check:
                    check(self.sb, out)

    def test_bad_input_is_refused_and_writes_nothing(self):
        for i, (args, make_file, message) in enumerate(BAD_INPUT):
            with self.subTest(args=" ".join(args)):
                if make_file:
                    os.makedirs(os.path.dirname(self.sb.path(make_file)), exist_ok=True)
                    with open(self.sb.path(make_file), "w") as f:
                        f.write("not a run file\n")
                files = tree(self.sb.root)
                code, out = self.sb.run(["make"] + args, f"bad-input-{i}", timeout=120)
                self.assertEqual(code, 2, out)
                self.assertIn(message, out)
                self.assertEqual(tree(self.sb.root) - files, set(), f"make {' '.join(args)} wrote files")
                if make_file:
                    os.remove(self.sb.path(make_file))


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if a != "--keep"]
    KEEP = "--keep" in sys.argv[1:]
    if len(args) != 2:
        sys.exit(__doc__)
    SIM, ANALYZE = args
    unittest.main(argv=sys.argv[:1], verbosity=2)
