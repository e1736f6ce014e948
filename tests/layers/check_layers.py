#!/usr/bin/env python3
"""Layers point down only (docs/ARCHITECTURE.md, "Who may include whom").

Reads every project #include "..." in the source folders and checks it against the table
below: a folder may include its own headers and those of the folders it lists, nothing else.
Exits 1 naming each offending file, line and include. A new folder must be added to the table;
an include the table does not allow is either a layering mistake or a decision to record here
and in docs/ARCHITECTURE.md.
"""
import os
import re
import sys

# Each folder and the folders below it that it may include (the whole chain, not only the next
# step down). The simulator and the analysis are separate programs: the analysis reads run files
# through its own reader and includes nothing of sim/ or protocols/.
SIM_BASE = ["sim/core", "sim/mesh", "sim/model"]
ALLOWED = {
    "sim/core": [],
    "sim/mesh": ["sim/core"],
    "sim/model": ["sim/core", "sim/mesh"],
    "sim/contact": SIM_BASE,
    "sim/integrate": SIM_BASE,
    "protocols/terms": SIM_BASE,
    "protocols": SIM_BASE + ["sim/integrate", "protocols/terms"],
    "protocols/stages": SIM_BASE + ["sim/integrate", "protocols", "protocols/terms"],
    "sim/io": SIM_BASE + ["sim/contact", "sim/integrate"],
    "sim/assemble": SIM_BASE + ["sim/contact", "sim/integrate", "protocols", "protocols/terms",
                                "sim/io"],
    "sim/apps": SIM_BASE + ["sim/contact", "sim/integrate", "protocols", "protocols/terms",
                            "sim/io", "sim/assemble", "crumple"],  # crumple/version.hpp: generated
    "analysis/io": [],
    "analysis/fits": [],
    "analysis/facets": [],
    "analysis/creases": ["analysis/io"],
    "analysis/raster": ["analysis/io"],
    "analysis/ensemble": ["analysis/io", "analysis/fits"],
    "analysis/run": ["analysis/io", "analysis/fits", "analysis/facets", "analysis/creases",
                     "analysis/raster"],
    "analysis/apps": ["analysis/io", "analysis/fits", "analysis/facets", "analysis/creases",
                      "analysis/raster", "analysis/ensemble", "analysis/run",
                      "crumple"],  # crumple/version.hpp: generated
}
SOURCE_ROOTS = ("sim", "protocols", "analysis")
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')


def main(root):
    problems = []
    for top in SOURCE_ROOTS:
        for dirpath, _, files in os.walk(os.path.join(root, top)):
            folder = os.path.relpath(dirpath, root)
            sources = [f for f in files if f.endswith((".cpp", ".hpp"))]
            if not sources:
                continue
            if folder not in ALLOWED:
                problems.append(f"{folder}: a source folder the layer table does not know "
                                f"(add it to tests/layers/check_layers.py and docs/ARCHITECTURE.md)")
                continue
            for name in sorted(sources):
                path = os.path.join(folder, name)
                with open(os.path.join(root, path), encoding="utf-8") as f:
                    for line_no, line in enumerate(f, 1):
                        m = INCLUDE.match(line)
                        if not m:
                            continue
                        target = os.path.dirname(m.group(1))
                        if target in ("", folder) or target in ALLOWED[folder]:
                            continue
                        problems.append(f"{path}:{line_no}: includes \"{m.group(1)}\": "
                                        f"{folder} may include only {ALLOWED[folder] or 'itself'}")
    for p in problems:
        print(p, file=sys.stderr)
    if not problems:
        print(f"layers: every include in {', '.join(SOURCE_ROOTS)} points down")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "."))
