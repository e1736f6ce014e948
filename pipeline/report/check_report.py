#!/usr/bin/python3
"""Checks that a report is complete: it exists, every file it links (images, tables) exists
beside it, it has a "## Verdict" section with content, it shows the per-stage figure (an image
link to stages*.png: where the creases were made), and it has the crease-threshold sensitivity
table (a Markdown table under the "## Crease-threshold sensitivity" heading).

Usage: check_report.py results/REPORT.md   (exit 0 when complete, 2 naming what is missing)
"""
import os
import pathlib
import re
import sys

SENSITIVITY_HEADING = "## Crease-threshold sensitivity"


def section(text, heading):
    """The lines under `heading` (a line of its own) up to the next heading of level <= 2, or
    None when the heading is absent."""
    lines = text.splitlines()
    for i, line in enumerate(lines):
        if line.strip() == heading:
            body = []
            for l in lines[i + 1:]:
                if re.match(r"^#{1,2} ", l):
                    break
                body.append(l)
            return body
    return None


def main() -> int:
    if len(sys.argv) != 2:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    report = pathlib.Path(sys.argv[1])
    if not report.is_file():
        print(f"check_report: {report}: missing", file=sys.stderr)
        return 2
    text = report.read_text()
    problems = []
    links = re.findall(r"\]\(([^)#\s]+)\)", text)
    if not links:
        problems.append("links no figure")
    missing = [l for l in links if not (report.parent / l).exists()]
    if missing:
        problems.append(f"linked files missing: {', '.join(missing)}")

    verdict = section(text, "## Verdict")
    if verdict is None:
        problems.append('no "## Verdict" section')
    elif not any(l.strip() for l in verdict):
        problems.append('the "## Verdict" section is empty')

    images = re.findall(r"!\[[^\]]*\]\(([^)#\s]+)\)", text)
    stages = [i for i in images if re.match(r"stages.*\.png$", os.path.basename(i))]
    if not stages:
        problems.append("no per-stage figure (an image link to stages.png: where the creases "
                        "were made)")

    sens = section(text, SENSITIVITY_HEADING)
    if sens is None:
        problems.append(f'no threshold-sensitivity section ("{SENSITIVITY_HEADING}")')
    else:
        rows = [l for l in sens if l.strip().startswith("|")]
        has_rule = any(re.match(r"^\|\s*:?-{3,}", l.strip()) for l in rows)
        if not has_rule or len(rows) < 3:
            problems.append(f'no threshold-sensitivity table under "{SENSITIVITY_HEADING}" '
                            "(the stats.json files may lack threshold_sensitivity: rerun "
                            "crumple-analyze)")
    if problems:
        for p in problems:
            print(f"check_report: {report}: {p}", file=sys.stderr)
        return 2
    print(f"check_report: {report}: complete ({len(links)} linked files present, verdict, "
          "per-stage figure and threshold-sensitivity table)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
