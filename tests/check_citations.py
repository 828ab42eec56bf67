#!/usr/bin/env python3
"""Fails when the project cites documents its users do not have.

Usage: check_citations.py [PROJECT_ROOT]     (default: the parent of this file's folder)

The library was written from five source documents ("seed 000" ... "seed 004", cited in full in
docs/bibliography.md) and from working extractions of them that never left the developers'
machines. A user has the seeds' primary papers, not those extractions, and not the developers'
file system. So every tracked text file under include/, docs/, examples/, tests/, bench/,
fuzz/ and scripts/, and README.md, must cite a paper, a seed (equation, table, figure,
section) or state the fact itself, never

  * an extraction: "note §2.6", "seed 002 note D8", "seed-004 note Part 3", "the note's
    reading", "anchors §2.9", "the anchors note", "anchors-moments.md", "note seed000 §3", ...;
  * a path outside the repository: "/work/...", "shared/notes", "notes/".

Prints FILE:LINE: the offending text, for each, and exits 1; exits 0 when there is none.
The patterns are written for what such citations look like, so that ordinary English ("note
that", "noted", "a footnote", an HTML "anchor", a C++ name such as note_once) passes.
Python 3 standard library only.
"""

import re
import subprocess
import sys
from pathlib import Path

SCANNED = ("include", "docs", "examples", "tests", "bench", "fuzz", "scripts", "README.md")

# This file spells the patterns out, so it is the one file not scanned.
SELF = Path("tests") / "check_citations.py"

# One alternative per kind of citation; matched case-insensitively. "note" and "notes" only
# count as citations when followed by a section mark, a section or item number, or a seed, or
# when they are possessive or "the note(s)" other than in "the note that".
CITATION = re.compile(
    r"""
      /work/                                                # the developers' machine
    | (?<![\w-])shared/                                     # /work/shared/...
    | (?<![\w-])notes/                                      # the extractions' folder
    | \b(?:seed00[0-4](?:-003)?-(?:closures|moments|niemi|multiscale|ktgf)
          |anchors-(?:closures|moments)|code-review\.md)     # the extractions' file names
    | \bnotes?\s*\(?(?:§|sec\b|sec\.|section\s+\d|part\s+\d+|item\s+[a-z]?\d|d\d+\b|\d+\.\d)
    | \bnotes?\s+seed                                       # "note seed000-003 §7"
    | \bnotes?\s+of\s+(?:the\s+)?seeds?\b                   # "the notes of seeds 001 and 004"
    | \bseeds?(?:'|’)?[\s_-]*(?:\d{3}[\s_-]*)?notes?\b      # "seed 002 note", "seed note", "seeds' note"
    | \bnotes?(?:'s|’s|s'|s’)                               # "the note's reading", "the notes' tables"
    | \bthe\s+notes?\b(?!\s+that\b)                         # "the note rounds", "with the notes"
    | \banchors?(?:'|’)?\s*\(?(?:§|note|survey|appendix|sec\b|\d)  # "anchors §2.9", "anchors note"
    | \bthe\s+anchors(?:'|’)                                # "the anchors' re-evaluation"
    | \banchor,\s+not\s+a\s+seed                            # an extraction's own label
    """,
    re.IGNORECASE | re.VERBOSE,
)


# The checker's own test, run first on every call: what must be caught, and ordinary text that
# must pass.
MUST_CITE = (
    "(seed 002 note §2.6, table checked)", "(note item D1)", "seed 002 note D8", "note §7.5(b)",
    "seed-004 note Part 3", "the seed note's reading", "(anchors §2.9 \"MFX\")", "anchors note §2.16",
    "the anchors survey (§2.8)", "(anchors appendix)", "the anchors' re-evaluation", "(note 3.12)",
    "note seed000-003 §2.3", "seed note 000 marks", "the seeds' note §7", "Note sec. 8.5",
    "values of the note (50 digits)", "the notes' tables", "anchors-moments.md", "seed004-ktgf §1.9",
    "extractions in `/work/shared/notes/`", "see shared/notes", "notes/seed000-closures.md",
)
MUST_PASS = (
    "Note that the drag is per unit volume.", "with the seed's misprint noted where there is one",
    "a footnote of the paper", "fuzz note: %s", "note_once(message)", "note_material.density",
    "a Markdown link file.md#anchor names a heading (anchors as GitHub forms them)",
    "Technical Note DOE/METC-94/1004", "seed 000 eq. 3.24 and seed 002 §II.D",
    "leaves the .dat and .gp files and a note, never a failure", "the note that follows",
)


def self_test():
    """Empty when the pattern catches every MUST_CITE and passes every MUST_PASS sample."""
    return ([f"not caught: {s!r}" for s in MUST_CITE if not CITATION.search(s)] +
            [f"false positive: {s!r}" for s in MUST_PASS if CITATION.search(s)])


def tracked_files(root):
    """The tracked files under SCANNED (git ls-files), or every file there outside git."""
    try:
        listed = subprocess.run(["git", "-C", str(root), "ls-files", "-z", "--", *SCANNED],
                                check=True, capture_output=True).stdout.decode().split("\0")
        return sorted(root / p for p in listed if p)
    except (OSError, subprocess.CalledProcessError):
        found = []
        for name in SCANNED:
            path = root / name
            found += [path] if path.is_file() else [p for p in path.rglob("*") if p.is_file()]
        return sorted(found)


def citations(root):
    """(relative path, line number, matched texts, line) for every line that cites."""
    hits = []
    for path in tracked_files(root):
        relative = path.relative_to(root)
        if relative == SELF or not path.is_file():
            continue
        try:
            text = path.read_text(encoding="utf-8")
        except UnicodeDecodeError:  # a binary file cites nothing
            continue
        for lineno, line in enumerate(text.splitlines(), 1):
            matched = [m.group(0).strip() for m in CITATION.finditer(line)]
            if matched:
                hits.append((relative, lineno, " | ".join(matched), line.strip()))
    return hits


def main(argv):
    root = Path(argv[1]).resolve() if len(argv) > 1 else Path(__file__).resolve().parent.parent
    broken = self_test()
    if broken:
        print("citation check: the pattern itself is wrong:\n  " + "\n  ".join(broken))
        return 2
    hits = citations(root)
    if hits:
        print(f"citation check FAILED: {len(hits)} lines cite internal notes or paths outside the "
              "repository (cite the paper, the seed's equation/table/section, or state the fact):")
        for relative, lineno, matched, line in hits:
            print(f"  {relative}:{lineno}: [{matched}] {line[:160]}")
        return 1
    print(f"citation check OK: {len(tracked_files(root))} files scanned, no internal-note citation "
          "and no path outside the repository")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
