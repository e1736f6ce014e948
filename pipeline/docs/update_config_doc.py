#!/usr/bin/env python3
"""Regenerate the key tables of docs/CONFIG.md from the simulator's schema, or check them.

The tables are printed by `crumple-sim --list-keys --markdown` as blocks between
`<!-- keys: NAME -->` and `<!-- /keys -->`; this script replaces each block of the same name in
the document and leaves the prose around them alone. With --check it changes nothing and exits 1
(showing the difference) when the document is stale; `make docs` rewrites it.
"""
import argparse
import difflib
import re
import subprocess
import sys

BLOCK = re.compile(r"<!-- keys: (\w+) -->\n.*?<!-- /keys -->\n", re.S)


def blocks(text):
    return {m.group(1): m.group(0) for m in BLOCK.finditer(text)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sim", required=True, help="the crumple-sim binary")
    ap.add_argument("--doc", default="docs/CONFIG.md", help="the document (default: %(default)s)")
    ap.add_argument("--check", action="store_true", help="only check; exit 1 when stale")
    a = ap.parse_args()

    generated = blocks(subprocess.run([a.sim, "--list-keys", "--markdown"], check=True,
                                      capture_output=True, text=True).stdout)
    with open(a.doc) as f:
        old = f.read()
    present = blocks(old)
    missing = sorted(set(generated) - set(present))
    unknown = sorted(set(present) - set(generated))
    if missing or unknown:
        sys.exit(f"{a.doc}: the document's key blocks do not match the schema's sections: "
                 f"missing {missing or 'none'}, not in the schema {unknown or 'none'} "
                 f"(add a '<!-- keys: NAME -->' ... '<!-- /keys -->' block per section)")
    new = BLOCK.sub(lambda m: generated[m.group(1)], old)
    if new == old:
        print(f"{a.doc}: key tables up to date ({len(generated)} blocks)")
        return 0
    if a.check:
        sys.stdout.writelines(difflib.unified_diff(old.splitlines(True), new.splitlines(True),
                                                   a.doc, "generated"))
        print(f"\n{a.doc}: stale; run `make docs` to regenerate its key tables", file=sys.stderr)
        return 1
    with open(a.doc, "w") as f:
        f.write(new)
    print(f"{a.doc}: key tables regenerated ({len(generated)} blocks)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
