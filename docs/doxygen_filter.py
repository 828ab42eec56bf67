#!/usr/bin/env python3
"""Doxygen INPUT_FILTER for fluidbed: lets Doxygen read the headers' plain `//` comments and
the Markdown catalogue as they are, so that no source file has to carry Doxygen markup.

Usage (Doxygen calls it): doxygen_filter.py FILE     writes the filtered FILE to stdout.
                          doxygen_filter.py --self-test   checks the header rules on a sample.

Headers (*.hpp):
  * the file's leading `//` block becomes its `\\file` documentation;
  * a `//` block immediately followed by a declaration, at namespace or class scope, becomes
    that declaration's `///` documentation; a block followed by a blank line, a `}`, an access
    specifier or a preprocessor line (other than #define) stays an ordinary comment, and
    comments inside function bodies are never touched (Doxygen would append them to the
    function's documentation);
  * a trailing `// text` after a member or enumerator at class scope becomes `///< text`;
  * inside documentation, lines indented by two or more spaces beyond the text (the headers'
    equations and tables) are kept as they are (<pre>), and the characters Doxygen or Markdown
    would interpret (\\ @ # < > & * and word-boundary _) are escaped in the rest, outside `code`.
Markdown (*.md):
  * each heading gets an explicit label, the page label for the first and the page label plus
    GitHub's anchor for the others, so that links written for GitHub
    (`closures/drag.md#ergun-1952`) also work in the generated pages;
  * links to a Markdown file or a header that Doxygen reads become `@ref` links; any other
    relative link is rewritten to point from build/api/html back into the repository;
  * a display formula written `$$ ... $$` on one line becomes Doxygen's `\\f[ ... \\f]`.
The line count of every file is preserved, so Doxygen's line numbers stay right. Python 3
standard library only; the GitHub anchor rule is shared with tests/check_docs_catalogue.py.
"""

import os
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.dont_write_bytecode = True  # leave no __pycache__ in tests/
sys.path.insert(0, str(ROOT / "tests"))
from check_docs_catalogue import github_heading_slugs  # noqa: E402

# The generated HTML lives in build/api/html: from there, the repository root is ../../../
HTML_TO_ROOT = "../../../"

# ------------------------------------------------------------------------------ headers

SCOPE_OPENER = re.compile(r"^\s*(?:template\s*<.*>\s*)?(?:namespace|struct|class|union|enum)\b|^\s*extern\s+\"C\"")
NOT_A_DECLARATION = re.compile(r"^\s*(?:$|}|#(?!\s*define\b)|(?:public|private|protected)\s*:|static_assert\b|using\s+namespace\b)")
TRAILING_MEMBER_COMMENT = re.compile(r"^(?P<code>\s*[^/\s].*?[;,])(?P<space>\s*)//\s?(?P<text>.*)$")
CODE_SPAN = re.compile(r"(`[^`]*`)")


class BraceTracker:
    """Follows {, } and the statement before each {, outside comments and literals, to tell
    whether a line is at namespace/class scope (documentable) or inside a function body."""

    def __init__(self):
        self.stack = []        # "scope" or "body" for every open brace
        self.statement = ""    # code since the last ; { or }
        self.in_block_comment = False

    def at_scope(self):
        return all(kind == "scope" for kind in self.stack)

    def feed(self, line):
        if not self.in_block_comment and line.lstrip().startswith("#"):
            return  # a preprocessor line is not part of any statement
        i, n = 0, len(line)
        while i < n:
            if self.in_block_comment:
                end = line.find("*/", i)
                if end < 0:
                    return
                self.in_block_comment, i = False, end + 2
                continue
            c = line[i]
            if line.startswith("//", i):
                return
            if line.startswith("/*", i):
                self.in_block_comment, i = True, i + 2
                continue
            if c in "\"'":
                j = i + 1
                while j < n and line[j] != c:
                    j += 2 if line[j] == "\\" else 1
                self.statement += c + c
                i = j + 1
                continue
            if c == "{":
                self.stack.append("scope" if SCOPE_OPENER.match(self.statement) else "body")
                self.statement = ""
            elif c == "}":
                if self.stack:
                    self.stack.pop()
                self.statement = ""
            elif c == ";":
                self.statement = ""
            else:
                self.statement += c
            i += 1
        self.statement += " "


def escape_commands(text):
    """Escapes Doxygen's command characters and HTML's in a piece of text."""
    text = text.replace("\\", "\\\\").replace("@", "\\@").replace("#", "\\#")
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def escape_prose(text):
    """Escapes what Doxygen or Markdown would interpret in a line of prose, outside `code`."""
    pieces = CODE_SPAN.split(text)
    for k in range(0, len(pieces), 2):
        s = escape_commands(pieces[k])
        list_marker = re.match(r"^(\s*)\* ", s) if k == 0 else None
        head, s = (s[: list_marker.end()], s[list_marker.end():]) if list_marker else ("", s)
        s = head + s.replace("*", "\\*")
        # '_' opens or closes Markdown emphasis unless it sits between two ASCII word characters
        pieces[k] = re.sub(r"(?<![A-Za-z0-9])_|_(?![A-Za-z0-9])", r"\\_", s)
    return "".join(pieces)


def documentation(texts, indent, file_comment):
    """The /// lines (as many as the // lines) for a block of comment texts. Lines indented by
    two or more spaces are preformatted (the headers' equations and tables): each run of them
    becomes one <pre> block (Doxygen 1.9 keeps the /// of a \\verbatim block's lines)."""
    texts = list(texts)
    if file_comment:
        texts[0] = re.sub(r"^fluidbed\s+—\s+", "", texts[0])
    preformatted = [text.startswith("  ") and bool(text.strip()) for text in texts]
    out = []
    for k, text in enumerate(texts):
        if preformatted[k]:
            opens = k == 0 or not preformatted[k - 1]
            closes = k + 1 == len(texts) or not preformatted[k + 1]
            line = ("<pre>" if opens else "") + escape_commands(text) + ("</pre>" if closes else "")
        else:
            line = escape_prose(text)
        if file_comment and k == 0:
            line += " \\file"  # \file ends the line: it documents this file, whatever its name
        out.append(f"{indent}/// {line}".rstrip())
    return out


def filter_header(lines):
    tracker = BraceTracker()
    out = []
    block, block_indent, block_at_scope = [], "", True
    leading = True  # still in the file's leading comment block

    def flush(next_line):
        nonlocal block, leading
        if not block:
            return
        is_file_comment = leading
        documentable = block_at_scope and not NOT_A_DECLARATION.match(next_line)
        if is_file_comment or documentable:
            out.extend(documentation([t for _, t in block], block_indent, is_file_comment))
        else:
            out.extend(original for original, _ in block)
        block = []

    trailing_column = None  # column of the member comment just converted to ///<
    for line in lines:
        comment = re.match(r"^(\s*)//(?!/)\s?(.*)$", line) if not tracker.in_block_comment else None
        if comment and not block and len(comment.group(1)) == trailing_column:
            # a continuation line aligned under a member's trailing comment
            out.append(f"{comment.group(1)}///< {escape_prose(comment.group(2))}".rstrip())
            continue
        trailing_column = None
        if comment:
            if not block:
                block_indent, block_at_scope = comment.group(1), tracker.at_scope()
            block.append((line, comment.group(2)))
            continue
        flush(line)
        leading = False
        trailing = TRAILING_MEMBER_COMMENT.match(line)
        at_scope = tracker.at_scope()
        tracker.feed(line)
        if trailing and at_scope and tracker.at_scope() and '"' not in trailing.group("code"):
            code_and_space = trailing.group("code") + trailing.group("space")
            line = f"{code_and_space}///< {escape_prose(trailing.group('text'))}"
            trailing_column = len(code_and_space)
        out.append(line)
    flush("")
    return out


# ----------------------------------------------------------------------------- Markdown

def page_label(relative):
    """Doxygen label of a Markdown page: its path with / and . as _ (README.md is the main page)."""
    return "index" if relative == "README.md" else re.sub(r"[^A-Za-z0-9]", "_", relative[: -len(".md")])


def anchor_label(relative, slug):
    return f"{page_label(relative)}_{re.sub(r'[^A-Za-z0-9_]', '_', slug)}"


LINK = re.compile(r"\[(?P<text>[^\]]*)\]\((?P<target>[^)\s#]*)(?:#(?P<anchor>[^)\s]*))?\)")
DISPLAY_MATH = re.compile(r"\$\$(.+?)\$\$")


def filter_markdown(lines, relative):
    here = Path(relative).parent
    slugs = {lineno: slug for lineno, slug in github_heading_slugs(lines)}
    first_heading = min(slugs) if slugs else None

    def relink(match):
        text, target, anchor = match.group("text"), match.group("target"), match.group("anchor")
        if "://" in target or target.startswith("mailto:"):
            return match.group(0)
        linked = os.path.normpath(here / target).replace(os.sep, "/") if target else relative
        plain = text.replace("`", "")  # Doxygen shows the backticks of an @ref link's text
        if linked.endswith(".md") and (ROOT / linked).is_file():
            label = anchor_label(linked, anchor) if anchor else page_label(linked)
            return f"[{plain}](@ref {label})"
        if linked.startswith("include/") and linked.endswith(".hpp"):
            return f"[{plain}](@ref {linked[len('include/'):]})"
        return f"[{text}]({HTML_TO_ROOT}{linked}{'#' + anchor if anchor else ''})"

    out = []
    for lineno, line in enumerate(lines):
        line = DISPLAY_MATH.sub(lambda m: f"\\f[{m.group(1)}\\f]", line)
        line = LINK.sub(relink, line)
        if lineno in slugs and not (lineno == first_heading and relative == "README.md"):
            label = page_label(relative) if lineno == first_heading else anchor_label(relative, slugs[lineno])
            line = f"{line.rstrip()} {{#{label}}}"
        out.append(line)
    return out


SELF_TEST_HEADER = """// fluidbed — a sample header.
#pragma once
namespace fluidbed::sample {

// ------------------------------------------------ a section comment, followed by a blank line

// A law, after van der Hoef et al. (2005):
//   β = 18 μ_f ε φ F / d²
// with <d> the Sauter mean.
struct Law {
  double margin = 0.01;  // the distance below φ_max
                         // where the linear continuation starts
  // The value.
  double operator()(double x) const {
    // inside a body: never documentation
    return x;
  }
};

}  // namespace fluidbed::sample"""

SELF_TEST_EXPECTED = {  # line index -> filtered line
    0: "/// a sample header. \\file",
    4: "// ------------------------------------------------ a section comment, followed by a blank line",
    6: "/// A law, after van der Hoef et al. (2005):",
    7: "/// <pre>  β = 18 μ_f ε φ F / d²</pre>",
    8: "/// with &lt;d&gt; the Sauter mean.",
    10: "  double margin = 0.01;  ///< the distance below φ\\_max",
    11: "                         ///< where the linear continuation starts",
    12: "  /// The value.",
    14: "    // inside a body: never documentation",
}


def self_test():
    """Empty when the header rules above hold on a sample, one message per broken rule."""
    lines = SELF_TEST_HEADER.split("\n")
    filtered = filter_header(lines)
    problems = [] if len(filtered) == len(lines) else [f"{len(lines)} lines became {len(filtered)}"]
    for index, expected in SELF_TEST_EXPECTED.items():
        if index < len(filtered) and filtered[index] != expected:
            problems.append(f"line {index + 1}: {filtered[index]!r}, expected {expected!r}")
    return problems


def main(argv):
    if argv[1:] == ["--self-test"]:
        problems = self_test()
        print("\n".join(problems) if problems else "doxygen_filter self-test OK")
        return 1 if problems else 0
    path = Path(argv[1]).resolve()
    lines = path.read_text(encoding="utf-8").split("\n")
    if path.suffix == ".md":
        lines = filter_markdown(lines, path.relative_to(ROOT).as_posix())
    elif path.suffix in (".hpp", ".h"):
        lines = filter_header(lines)
    sys.stdout.write("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
