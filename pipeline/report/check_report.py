#!/usr/bin/python3
"""Checks that a report exists and that every file it links (images, tables) exists beside it.

Usage: check_report.py results/REPORT.md   (exit 0 when complete, 2 with the missing files)
"""
import pathlib
import re
import sys


def main() -> int:
    if len(sys.argv) != 2:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    report = pathlib.Path(sys.argv[1])
    if not report.is_file():
        print(f"check_report: {report}: missing", file=sys.stderr)
        return 2
    text = report.read_text()
    links = re.findall(r"\]\(([^)#\s]+)\)", text)
    missing = [l for l in links if not (report.parent / l).exists()]
    if not links:
        print(f"check_report: {report}: links no figure", file=sys.stderr)
        return 2
    if missing:
        print(f"check_report: {report}: missing {', '.join(missing)}", file=sys.stderr)
        return 2
    print(f"check_report: {report}: complete ({len(links)} linked files present)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
