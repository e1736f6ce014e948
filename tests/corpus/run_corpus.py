#!/usr/bin/env python3
"""The bad-input corpus (tests/corpus/cases.yaml): every case must fail the way it says.

Each case runs crumple-sim (or crumple-analyze) in a fresh directory holding the files the
case names, and asserts
  - the exit code,
  - that the message (stderr) contains each expected text: the file, line, column and key, or
    the --set argument, or the path and dataset,
  - that nothing was written: the directory holds exactly the same files with the same bytes
    afterwards (a pending checkpoint that was there stays, untouched).
Run files and checkpoints come from one small interrupted run made at the start ("pending":
RUN.h5.tmp of a run stopped by SIGTERM) and one complete run ("complete"), then damaged as the
case says (see EDITS).

usage: run_corpus.py --sim CRUMPLE_SIM --analyze CRUMPLE_ANALYZE [--keep DIR] [-k SUBSTRING]
Prints one line per case and a tally by category; exits 1 if any case fails.
"""
import argparse
import hashlib
import os
import resource
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import time

import h5py
import numpy as np
import yaml

HERE = os.path.dirname(os.path.abspath(__file__))


# ---- damaging a run file -------------------------------------------------------------------

def edit_nan(f, path, _):
    d = f[path]
    a = d[()].astype(float)
    a.flat[0] = np.nan
    d[...] = a


def edit_drop_row(f, path, _):
    a = f[path][()]
    del f[path]
    f[path] = a[:-1]


def edit_set(f, path, value):
    """Sets element 0 of a dataset, or an attribute 'GROUP@NAME', to value."""
    if "@" in path:
        group, name = path.split("@")
        f[group].attrs[name] = value
        return
    d = f[path]
    a = d[()]
    a.flat[0] = value
    d[...] = a


def edit_fill(f, path, value):
    """Sets every element of a dataset to value."""
    d = f[path]
    a = d[()]
    if isinstance(value, str):  # "nan", "inf"
        a = a.astype(float)
        value = float(value)
    a[...] = value
    d[...] = a


def edit_delete(f, path, _):
    """Deletes a dataset or group, or an attribute 'GROUP@NAME'."""
    if "@" in path:
        group, name = path.split("@")
        del f[group].attrs[name]
        return
    del f[path]


def edit_rename_group(f, path, new_name):
    f.move(path, new_name)


def edit_string(f, path, value):
    del f[path]
    f[path] = value


EDITS = {"nan": edit_nan, "drop_row": edit_drop_row, "set": edit_set, "fill": edit_fill,
         "delete": edit_delete,
         "move": edit_rename_group, "string": edit_string}


def make_file(spec, target, bases):
    """Writes one file of a case: text, or a base run file copied and damaged."""
    if isinstance(spec, str):
        with open(target, "w") as fh:
            fh.write(spec)
        return
    if "bytes" in spec:  # a file of this many pseudo-random bytes, or zeros
        rng = np.random.default_rng(7)
        data = rng.integers(0, 256, spec["bytes"], dtype=np.uint8).tobytes()
        with open(target, "wb") as fh:
            fh.write(data)
        return
    if "repeat" in spec:  # a long text file
        with open(target, "w") as fh:
            fh.write(spec["repeat"] * spec["times"])
        return
    shutil.copyfile(bases[spec["run"]], target)
    if "truncate" in spec:
        size = os.path.getsize(target)
        with open(target, "r+b") as fh:
            fh.truncate(int(size * spec["truncate"]))
    if "edit" in spec:
        with h5py.File(target, "r+") as f:
            for e in spec["edit"]:
                EDITS[e["op"]](f, e["path"], e.get("value"))


# ---- running a case -----------------------------------------------------------------------

def snapshot(folder):
    out = {}
    for root, dirs, files in os.walk(folder):
        for name in dirs + files:
            p = os.path.join(root, name)
            rel = os.path.relpath(p, folder)
            if os.path.isdir(p):
                out[rel + "/"] = "dir"
            else:
                with open(p, "rb") as fh:
                    out[rel] = hashlib.sha1(fh.read()).hexdigest()
    return out


def run_case(case, folder, tools, bases, defaults):
    os.makedirs(os.path.join(folder, "out"))
    for name, spec in case.get("files", {}).items():
        spec = defaults.get(spec, spec) if isinstance(spec, str) and spec in defaults else spec
        target = os.path.join(folder, name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        make_file(spec, target, bases)
    before = snapshot(folder)
    tool = tools[case.get("tool", "sim")]
    cmd = [tool] + shlex.split(case["args"])
    limit = case.get("file_size_limit")

    def preexec():
        if limit:  # a write that fails as on a full disk: write() returns EFBIG
            signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
            resource.setrlimit(resource.RLIMIT_FSIZE, (limit, resource.RLIM_INFINITY))

    try:
        p = subprocess.run(cmd, cwd=folder, capture_output=True, text=True, errors="replace", timeout=120,
                           preexec_fn=preexec, stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        return ["hung: no exit within 120 s"]
    problems = []
    if p.returncode != case["exit"]:
        problems.append(f"exit {p.returncode}, expected {case['exit']}")
    for text in case.get("expect", []):
        if text not in p.stderr:
            problems.append(f"message lacks {text!r}")
    after = snapshot(folder)
    if after != before:
        added = sorted(set(after) - set(before))
        removed = sorted(set(before) - set(after))
        changed = sorted(k for k in before if k in after and before[k] != after[k])
        problems.append(f"files changed: added {added}, removed {removed}, modified {changed}")
    if problems:
        problems.append("stderr: " + p.stderr.strip().replace("\n", "\n    "))
    return problems


def make_bases(sim, folder, tiny):
    """A pending checkpoint (run stopped by SIGTERM) and a complete run of the tiny config."""
    os.makedirs(folder)
    cfg = os.path.join(folder, "tiny.yaml")
    with open(cfg, "w") as fh:
        fh.write(tiny)
    complete = os.path.join(folder, "complete.h5")
    subprocess.run([sim, cfg, "-o", complete, "--quiet", "--threads", "1"], check=True)
    pending = os.path.join(folder, "pending.h5")
    proc = subprocess.Popen([sim, cfg, "-o", pending, "--quiet", "--threads", "1"],
                            stderr=subprocess.DEVNULL)
    for _ in range(4000):
        if os.path.exists(pending + ".tmp"):
            break
        time.sleep(0.005)
    proc.send_signal(signal.SIGTERM)
    if proc.wait() != 128 + signal.SIGTERM:
        raise RuntimeError("could not make the pending checkpoint (the run ended first?)")
    return {"complete": complete, "pending": pending + ".tmp"}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sim", required=True)
    ap.add_argument("--analyze", required=True)
    ap.add_argument("--cases", default=os.path.join(HERE, "cases.yaml"))
    ap.add_argument("--keep", help="work in this directory and keep it (default: a temporary one)")
    ap.add_argument("-k", help="only the cases whose name contains this")
    a = ap.parse_args()
    with open(a.cases) as fh:
        corpus = yaml.safe_load(fh)
    tools = {"sim": os.path.abspath(a.sim), "analyze": os.path.abspath(a.analyze)}
    work = a.keep or tempfile.mkdtemp(prefix="crumple_corpus_")
    if a.keep and os.path.exists(work):
        shutil.rmtree(work)
    try:
        defaults = corpus["files"]
        bases = make_bases(tools["sim"], os.path.join(work, "bases"), defaults["tiny.yaml"])
        tally, failed = {}, 0
        names = set()
        for k, case in enumerate(corpus["cases"]):
            assert case["name"] not in names, f"case name twice: {case['name']}"
            names.add(case["name"])
            if a.k and a.k not in case["name"]:
                continue
            problems = run_case(case, os.path.join(work, f"case{k:03d}"), tools, bases, defaults)
            cat = case["category"]
            ok, n = tally.get(cat, (0, 0))
            tally[cat] = (ok + (not problems), n + 1)
            print(f"{'ok  ' if not problems else 'FAIL'} [{cat}] {case['name']}")
            for pr in problems:
                print("    " + pr)
            failed += bool(problems)
        total = sum(n for _, n in tally.values())
        print("\n" + ", ".join(f"{cat} {ok}/{n}" for cat, (ok, n) in tally.items()))
        print(f"{total - failed} of {total} cases passed")
        return 1 if failed else 0
    finally:
        if not a.keep:
            shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
