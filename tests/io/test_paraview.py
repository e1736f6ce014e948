#!/usr/bin/python3
"""A run's XDMF sidecars opened with ParaView's own reader (issue 37): a tiny two-cycle run, then
pvpython under xvfb-run (paraview_check.py) loads RUN.xdmf and RUN.cycles.xdmf. ParaView must
see every stored frame at its simulated time with the run's final state as the last step, the
end of each cycle at times 1, 2, ..., the sheet's surface (velocity on the nodes) and its hinge
network (one polyline cell per hinge with p and the crease mask, equal to the run file's), and
cycle, stage code and t as field data; it renders the creases to a PNG that must not be blank.

Skipped (exit 77, with a message) when ParaView or xvfb-run is missing: `make deps-paraview`
installs Debian's paraview, python3-paraview and xvfb.

usage: test_paraview.py CRUMPLE_SIM   (from the repository root)
"""
import json
import os
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SKIP = 77


def check(cond, what):
    if not cond:
        print(f"test_paraview: FAILED: {what}")
        sys.exit(1)


def pvpython(args, attempts=3):
    """pvpython ARGS under xvfb-run on a 24-bit screen. On a loaded machine ParaView's first
    OpenGL window now and then fails to reach the virtual X server ("bad X server connection")
    though the server is up; that is the X setup, not the file under test, so it is retried."""
    for k in range(attempts):
        r = subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 1024x768x24", "pvpython"] + args,
                           capture_output=True, text=True, timeout=300)
        if r.returncode == 0 or "bad X server connection" not in r.stderr:
            return r
        print(f"test_paraview: attempt {k + 1}: ParaView could not reach the virtual X server; "
              "trying again")
    return r


def main():
    sim = os.path.abspath(sys.argv[1])
    missing = [p for p in ("pvpython", "xvfb-run") if not shutil.which(p)]
    if missing:
        print(f"test_paraview: SKIPPED: {' and '.join(missing)} not found; "
              "`make deps-paraview` installs ParaView and a virtual X server")
        return SKIP
    with tempfile.TemporaryDirectory() as tmp:
        run = os.path.join(tmp, "run.h5")
        r = subprocess.run([sim, "protocols/axial_crumpling.yaml", "--seed", "3", "--threads", "1",
                            "--set", "mesh.nodes=200", "--set", "protocol.cycles=2",
                            # A 200-node hinge must fold about 100 degrees to reach the
                            # protocol's 3.55 mm yield radius; a yield angle creases it in two
                            # cycles, which is what this test needs to see.
                            "--set", "material.yield_radius=0", "--set", "material.yield_angle=37.1",
                            "-o", run,
                            "--quiet"], capture_output=True, text=True)
        check(r.returncode == 0, f"crumple-sim failed: {r.stderr}")
        png = os.path.join(tmp, "creases.png")
        r = pvpython([os.path.join(HERE, "paraview_check.py"), os.path.join(tmp, "run.xdmf"),
                      os.path.join(tmp, "run.cycles.xdmf"), png])
        lines = [l for l in r.stdout.splitlines() if l.startswith("PARAVIEW ")]
        check(r.returncode == 0 and lines, f"pvpython failed ({r.returncode}): {r.stderr[:3000]}")
        seen = json.loads(lines[-1][len("PARAVIEW "):])
        with h5py.File(run) as f:
            n, hinges = f["mesh/ref_positions"].shape[0], f["mesh/hinges"].shape[0]
            frames = [f["frames"][k] for k in sorted(f["frames"])]
            t_frames = [g.attrs["t"] for g in frames]
            last_cycle = f["cycles"][sorted(f["cycles"])[-1]]
            t_end, p_end = last_cycle.attrs["t"], last_cycle["p"][:]
            mask_end = last_cycle["crease"][:]
            threshold = f["meta"].attrs["crease_threshold"]
            last_frame_stage = frames[-1].attrs["stage"]

        fr = seen["frames"]
        check(np.allclose(fr["times"], t_frames), "the frames' times are the stored frames' t")
        check(abs(fr["times"][-1] - t_end) < 1e-9, "the last time step is the run's end "
              f"({fr['times'][-1]} against {t_end})")
        surface, net = fr["last"]
        check(surface["points"] == n and "velocity" in surface["point_arrays"],
              f"the surface has the {n} nodes and their velocity: {surface}")
        check(net["cells"] == hinges and net["cell_arrays"] == ["crease", "p"],
              f"the hinge network has one cell per hinge ({hinges}) with p and crease: {net}")
        for block in (surface, net):
            check(block["field"]["cycle"] == 2 and abs(block["field"]["t"] - t_end) < 1e-9
                  and "stage_code" in block["field"], f"field data cycle, t, stage_code: {block}")
        check(last_frame_stage == "unfold", "the final frame belongs to the last stage")

        cy = seen["cycles"]
        check(cy["times"] == [1.0, 2.0], f"one time step per cycle, at its number: {cy['times']}")
        net = cy["last"][1]
        check(np.isclose(net["p_range"][0], p_end.min()) and np.isclose(net["p_range"][1], p_end.max()),
              "ParaView's p is the run file's at the last cycle's end")
        check(net["creased"] == int(mask_end.sum()) == int((np.abs(p_end) > threshold).sum()) > 0,
              f"the crease mask is |p| > {threshold:.3g}: {net['creased']} hinges in ParaView, "
              f"{int(mask_end.sum())} in the file")

        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        check(os.path.isfile(png), "ParaView rendered the crease PNG")
        img = plt.imread(png)
        colours = len(np.unique((img[..., :3] * 255).astype(np.uint8).reshape(-1, 3), axis=0))
        check(colours > 50, f"the rendering shows something ({colours} colours)")
    print(f"test_paraview: ParaView reads both collections ({len(t_frames)} frames to "
          f"t = {t_end:g} s, 2 cycle ends) and draws the creases")
    return 0


if __name__ == "__main__":
    sys.exit(main())
