#!/usr/bin/env python3
"""The configuration file a run depends on: RUN.h5.config, the run's configuration as
`crumple-sim --print-config` resolves it, rewritten only when it changes.

Make rules let a run depend on this file rather than on the protocol, preset or sweep files it
comes from, so an edit that does not change what a run computes (a comment, a key another
setting overrides) redoes nothing, and one that does redoes exactly the runs it changes. When
the file is written and a finished run file stored this very configuration (a run made before
the file existed, or before a key was added to the simulator: ADDED_KEYS), the file takes the
run's date and the run stands. Used by pipeline/sweeps/expand_sweep.py for every sweep point and,
as a command, by pipeline/reproduce.mk for the runs of `make reproduce`:

  run_config.py RUN.h5 -- CRUMPLE-SIM ARGS...   (ARGS as for the run, without -o)

Exit codes: 0 written or unchanged, 2 the configuration is not valid (crumple-sim's message;
nothing written).
"""
import os
import subprocess
import sys

import yaml


def min_area_ratio(f):
    """The least area of any triangle, over its rest area, in the stored frames and cycles of the
    open run file f (None when it holds no positions)."""
    import numpy as np
    tri = f["mesh/triangles"][()]
    ref = f["mesh/ref_positions"][()]

    def areas(x):
        return 0.5 * np.linalg.norm(np.cross(x[tri[:, 1]] - x[tri[:, 0]], x[tri[:, 2]] - x[tri[:, 0]]),
                                    axis=1)
    rest, least = areas(ref), None
    for group in ("frames", "cycles"):
        for k in f.get(group, {}):
            r = float((areas(f[group][k]["x"][()]) / rest).min())
            least = r if least is None else min(least, r)
    return least


# Keys the simulator gained after runs were made: a run whose stored configuration lacks one
# counts as made with it at this value when its own stored states show the key would have
# changed nothing. The area barrier (docs/MODEL.md §3.1) acts below half a triangle's rest area;
# a run none of whose stored frames came below AREA_MARGIN of it is taken as the same run with
# the barrier (checked by rerunning kept runs with it: identical bit for bit).
AREA_MARGIN = 0.6
ADDED_KEYS = {("material", "area_barrier"):
              (True, lambda f: (min_area_ratio(f) or 0.0) >= AREA_MARGIN)}


def stored_config_is(run, text):
    """Whether the finished run file RUN was made with the configuration `text` (as
    --print-config prints it). The run stores the hinge yield it derived from a yield radius
    (integrator.plastic_c0), which --print-config leaves out, so that key is not compared then;
    a key added to the simulator after the run (ADDED_KEYS) is taken at its value there when the
    run's stored states show it would not have acted."""
    try:
        import h5py
        with h5py.File(run, "r") as f:
            stored = f["config"][()]
            stored = yaml.safe_load(stored.decode() if isinstance(stored, bytes) else stored)
            new = yaml.safe_load(text)
            if not isinstance(stored, dict) or not isinstance(new, dict):
                return False
            for (section, key), (value, acts_not) in ADDED_KEYS.items():
                old_sec, new_sec = stored.get(section) or {}, new.get(section) or {}
                if key not in old_sec and new_sec.get(key) == value and acts_not(f):
                    stored.setdefault(section, {})[key] = value
    except Exception:  # no readable run file or no /config: not known to match
        return False
    for c in (stored, new):
        if (c.get("material") or {}).get("yield_radius"):
            (c.get("integrator") or {}).pop("plastic_c0", None)
    return stored == new


def write_if_changed(path, text):
    """Writes text to path unless it holds it already; True if written."""
    if os.path.isfile(path):
        with open(path) as f:
            if f.read() == text:
                return False
    tmp = path + ".new"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)
    return True


def update(run, text):
    """Writes RUN.config with text if it changed; a finished RUN that stored text keeps
    standing (the file takes its date). Returns the configuration file's path."""
    config = run + ".config"
    if write_if_changed(config, text) and os.path.isfile(run) and stored_config_is(run, text):
        t = os.stat(run).st_mtime_ns  # to the nanosecond, as make compares
        os.utime(config, ns=(t, t))
    return config


def main(argv):
    if len(argv) < 4 or argv[2] != "--":
        print(__doc__.split("\n\n")[2], file=sys.stderr)
        return 2
    run, cmd = argv[1], argv[3:]
    r = subprocess.run(cmd[:1] + ["--print-config"] + cmd[1:], capture_output=True, text=True)
    if r.returncode != 0:
        print(f"run_config: {run}: the run's configuration is not valid:\n{r.stderr.strip()}",
              file=sys.stderr)
        return 2
    os.makedirs(os.path.dirname(run) or ".", exist_ok=True)
    update(run, r.stdout)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
