"""Shared by the bench scripts of pipeline/bench/: the repository's root, and running one child
process (crumple-sim, crumple-analyze) with its wall time and its own peak memory.

The peak memory comes from os.wait4 on the child: the rusage of that one process, where
resource.getrusage(RUSAGE_CHILDREN) would give the largest of all children waited for so far.
"""
import os
import subprocess
import sys
import time

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


def die(msg, code=2):
    print(f"{os.path.basename(sys.argv[0])}: {msg}", file=sys.stderr)
    sys.exit(code)


def from_root(path):
    """A default path of the repository (relative to its root), as a path from here."""
    return os.path.relpath(os.path.join(ROOT, path))


def check_binary(path, what):
    if not (os.path.isfile(path) and os.access(path, os.X_OK)):
        die(f"{what} {path}: no such executable (make build?)")


def run_child(cmd, log_path):
    """Runs cmd with stdout and stderr into log_path. Returns (exit code, wall s, peak RSS MiB)."""
    with open(log_path, "w") as log:
        t0 = time.monotonic()
        p = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(p.pid, 0)
        wall = time.monotonic() - t0
    p.returncode = os.waitstatus_to_exitcode(status)  # reaped here, not by Popen.wait
    return p.returncode, wall, usage.ru_maxrss / 1024.0  # ru_maxrss is in KiB on Linux


def tail(path, lines=15):
    try:
        with open(path) as f:
            return "".join(f.readlines()[-lines:])
    except OSError:
        return ""
