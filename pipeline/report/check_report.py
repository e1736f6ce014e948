#!/usr/bin/python3
"""Checks that a report is complete: it exists, every file it links (images, tables) exists
beside it by a relative link (so the folder can be copied), it has a "## Verdict" section with
content, it shows the per-stage figure (an image link to stages*.png or stages*.svg: where the
creases were made), it has the crease-threshold sensitivity table (a Markdown table under the
"## Crease-threshold sensitivity" heading), and it ends with an "## Images" section whose table
links every image file (.png, .svg) in the images/ folder beside it and every figure it shows.

Usage: check_report.py results/REPORT.md   (exit 0 when complete, 2 naming what is missing)
"""
import os
import pathlib
import re
import sys

SENSITIVITY_HEADING = "## Crease-threshold sensitivity"
IMAGES_HEADING = "## Images"
FIGURE_EXT = (".png", ".svg")


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


def absolute(link):
    """A link that breaks when the report's folder is copied: a file path from the root, a
    file: URL or a Windows drive."""
    return link.startswith(("/", "file:", "\\")) or re.match(r"^[A-Za-z]:[\\/]", link) is not None


def images_problems(report, text):
    """What is wrong with the images index: missing, not the last section, no table, an image
    file in images/ or a figure shown in the report that it does not link."""
    body = section(text, IMAGES_HEADING)
    if body is None:
        return [f'no images index ("{IMAGES_HEADING}" section)']
    problems = []
    headings = [l.strip() for l in text.splitlines() if re.match(r"^#{1,2} ", l)]
    if headings[-1] != IMAGES_HEADING:
        problems.append(f'"{IMAGES_HEADING}" is not the last section (it comes before '
                        f'"{headings[-1]}")')
    rows = [l for l in body if l.strip().startswith("|")]
    if not any(re.match(r"^\|\s*:?-{3,}", l.strip()) for l in rows):
        problems.append(f'no table under "{IMAGES_HEADING}"')
    listed = {os.path.normpath(l) for r in rows for l in re.findall(r"\]\(([^)#\s]+)\)", r)}
    folder = report.parent / "images"
    present = sorted(f.name for f in folder.iterdir()
                     if f.suffix.lower() in FIGURE_EXT) if folder.is_dir() else []
    unlisted = [f for f in present if os.path.normpath(f"images/{f}") not in listed]
    if unlisted:
        problems.append(f"images index lacks files in {folder}: {', '.join(unlisted)}")
    shown = re.findall(r"!\[[^\]]*\]\(([^)#\s]+)\)", text)
    unshown = [i for i in shown if os.path.normpath(i) not in listed]
    if unshown:
        problems.append(f"images index lacks figures the report shows: {', '.join(unshown)}")
    return problems


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
    fixed = [l for l in links if absolute(l)]
    if fixed:
        problems.append(f"links not relative to the report (they break when the folder is "
                        f"copied): {', '.join(fixed)}")
    missing = [l for l in links if l not in fixed and not (report.parent / l).exists()]
    if missing:
        problems.append(f"linked files missing: {', '.join(missing)}")

    verdict = section(text, "## Verdict")
    if verdict is None:
        problems.append('no "## Verdict" section')
    elif not any(l.strip() for l in verdict):
        problems.append('the "## Verdict" section is empty')

    images = re.findall(r"!\[[^\]]*\]\(([^)#\s]+)\)", text)
    stages = [i for i in images if re.match(r"stages.*\.(png|svg)$", os.path.basename(i))]
    if not stages:
        problems.append("no per-stage figure (an image link to stages.png or stages.svg: where "
                        "the creases were made)")

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
    problems += images_problems(report, text)
    if problems:
        for p in problems:
            print(f"check_report: {report}: {p}", file=sys.stderr)
        return 2
    print(f"check_report: {report}: complete ({len(links)} linked files present, verdict, "
          "per-stage figure, threshold-sensitivity table and images index)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
