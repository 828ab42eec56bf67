#!/usr/bin/env python3
"""Renders docs/catalogue.md from the output of the catalogue generator
(docs/catalogue/generate_catalogue.cpp, the CMake target fluidbed_catalogue), or checks it.

Usage: render_catalogue.py GENERATOR                 rewrites docs/catalogue.md
       render_catalogue.py GENERATOR --check OUTPUT   writes OUTPUT and fails, with a diff, where
                                                      docs/catalogue.md differs from it

The generator prints each closure's metadata with a placeholder {{section "Name"}}; this script
replaces it with a link to the closure's section of docs/closures/*.md: the first "### " section
(pages in alphabetical order) that gives the run-time name written "Name", the section that
tests/test_registries.cpp checks the reference's year and DOIs against. It fails (exit 1) where
a closure has no such section, or where that section has no display equation ($$...$$ or a
```math block): the equation's one hand-written place besides the header's doc comment.
Anchors are GitHub's heading ids (tests/check_docs_catalogue.py). Python 3 standard library only.
"""

import difflib
import re
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tests"))
from check_docs_catalogue import github_heading_slugs  # noqa: E402

CATALOGUE = ROOT / "docs" / "catalogue.md"
PLACEHOLDER = re.compile(r'\{\{section "([^"]+)"\}\}')
DISPLAY_EQUATION = re.compile(r"\$\$.+?\$\$|^```math$", re.S | re.M)


def sections():
    """(page, heading text, anchor, body) of every "### " section of docs/closures/*.md."""
    found = []
    for page in sorted((ROOT / "docs" / "closures").glob("*.md")):
        lines = page.read_text(encoding="utf-8").split("\n")
        headings = github_heading_slugs(lines)
        for k, (index, anchor) in enumerate(headings):
            if lines[index].startswith("### "):
                end = headings[k + 1][0] if k + 1 < len(headings) else len(lines)
                found.append((page, lines[index][4:].strip(), anchor, "\n".join(lines[index:end])))
    return found


def render(generated):
    """The catalogue's text, and the problems found while linking the sections."""
    catalogued = sections()
    problems = []

    def link(match):
        name = match.group(1)
        for page, title, anchor, body in catalogued:
            if f'"{name}"' in body:
                if not DISPLAY_EQUATION.search(body):
                    problems.append(f'"{name}": its section {page.name}#{anchor} has no display equation')
                return f"[{title}](closures/{page.name}#{anchor})"
        problems.append(f'"{name}": no "### " section of docs/closures/*.md gives the name written "{name}"')
        return "—"

    return PLACEHOLDER.sub(link, generated), problems


def main(argv):
    if len(argv) not in (2, 4) or (len(argv) == 4 and argv[2] != "--check"):
        print(__doc__)
        return 2
    generated = subprocess.run([argv[1]], check=True, capture_output=True, text=True, encoding="utf-8").stdout
    text, problems = render(generated)
    if len(argv) == 2:
        CATALOGUE.write_text(text, encoding="utf-8")
        print(f"wrote {CATALOGUE}")
    else:
        output = Path(argv[3])
        output.parent.mkdir(parents=True, exist_ok=True)
        output.write_text(text, encoding="utf-8")
        committed = CATALOGUE.read_text(encoding="utf-8") if CATALOGUE.exists() else ""
        if committed != text:
            diff = difflib.unified_diff(committed.splitlines(True), text.splitlines(True),
                                        "docs/catalogue.md (committed)", f"{output} (generated)")
            problems.append("docs/catalogue.md is out of date; regenerate it (the command is at its top):\n"
                            + "".join(diff))
    for problem in problems:
        print("catalogue: " + problem)
    if problems:
        return 1
    rows = text.count("\n| `")
    print(f"catalogue OK: {rows} closures, each linked to a section with a display equation")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
