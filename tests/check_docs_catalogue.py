#!/usr/bin/env python3
"""Keeps the closure catalogue in docs/ consistent with the headers in include/fluidbed/.

Usage: check_docs_catalogue.py [PROJECT_ROOT]     (default: the parent of this file's folder)
       check_docs_catalogue.py --list [PROJECT_ROOT]   prints what the headers declare

Fails (exit 1, listing every problem) when
  1. a public closure of the headers is not catalogued: its qualified name
     `fluidbed::<namespace>::<Name>` does not appear inside a backtick span of the docs
     (`fluidbed::ns::Name::member` counts for Name too);
  2. a run-time name does not appear in the docs written as `"Name"`. Run-time names are the
     string literals of the family headers that are one CamelCase word: what the laws' name()
     return ("Ergun", "DiFeliceDallavalle") and the presets pass ("Lewis", "WenYu1966");
  3. the docs name a C++ identifier `fluidbed::...` (in backticks) that the headers do not
     declare in that namespace; for `fluidbed::ns::Type::member` the member must also be a
     word of Type's body (a static member function, an enumerator, ...);
  4. the docs cite a header or source path (in backticks, e.g. `drag/ergun.hpp`, or as a
     Markdown link target) that does not exist;
  5. a Markdown link `file.md#anchor` (or `#anchor`) names a heading that file does not have
     (the heading ids GitHub forms).

What counts as a public closure. The headers of the closure families (the folders of FAMILIES
under include/fluidbed/) are read
with comments, string literals and preprocessor lines removed, and scanned brace by brace
(the file is cut into "chunks" at ';', '{' and '}', and each '{' is classified by the chunk
before it: namespace, struct/class, enum, concept, function, or other). A public closure is
  * a struct or class declared at namespace scope, outside any `detail` namespace, whose
    body declares a member `std::string_view name` -- either the static data member of the
    single-particle drag coefficients (`static constexpr std::string_view name = ...`) or the
    `name()` member function every drag law and kinetic-theory law has; and
  * a free function defined at namespace scope, outside any `detail` namespace (every
    overload set counts once): the settling, elastic and moment-inversion closures are free
    functions, and the drag and kinetic-theory families' free helpers (evaluate(),
    gas_damping(), ...) are part of the same public surface.
Class templates, partial specialisations and CRTP bases without a name member (DragLaw,
KineticPlusCollisional), result/option structs and enums are not closures; the catalogue may
still name them (check 3 then verifies they exist). Python 3 standard library only.
"""

import re
import sys
from pathlib import Path

FAMILIES = ("single_particle", "settling", "drag", "fluidization", "elastic", "interaction", "kinetic_theory", "moments",
            "polydisperse")

# ----------------------------------------------------------------------------- C++ scanning


def strip_code(text):
    """Removes comments, string/char literals and preprocessor lines; keeps newlines.
    Returns (code, literals): the literals are the contents of the string literals."""
    out, literals = [], []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("\n" * text.count("\n", i, j))
            i = j
        elif c == '"' or (c == "'" and not (i > 0 and text[i - 1].isalnum())):  # 1'000 is no literal
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            if c == '"':
                literals.append(text[i + 1 : j])
            out.append(" " + c + c + " ")
            i = j + 1
        else:
            out.append(c)
            i += 1
    lines = "".join(out).split("\n")
    code, continued = [], False
    for line in lines:  # drop #include, #pragma, #define (with continuations)
        directive = continued or line.lstrip().startswith("#")
        continued = directive and line.rstrip().endswith("\\")
        # and a line that is only a macro invocation (FLUIDBED_EIGEN_CODE_BEGIN): no declaration
        code.append("" if directive or ALONE_MACRO.match(line) else line)
    return "\n".join(code), literals


ALONE_MACRO = re.compile(r"^\s*[A-Z][A-Z0-9_]*\s*$")


def drop_template_prefix(chunk):
    """`template <...>` prefixes removed (balanced angle brackets)."""
    chunk = chunk.strip()
    while chunk.startswith("template"):
        i = chunk.find("<")
        depth = 0
        for j in range(i, len(chunk)):
            depth += {"<": 1, ">": -1}.get(chunk[j], 0)
            if depth == 0:
                chunk = chunk[j + 1 :].strip()
                break
        else:
            return chunk
    return chunk


def classify(chunk):
    """(kind, name) of the declaration a chunk opens or ends; name may be None."""
    c = drop_template_prefix(chunk)
    if not c:
        return "other", None
    m = re.match(r"(?:inline\s+)?namespace\b\s*([\w:]*)", c)
    if m:
        return "namespace", m.group(1)
    m = re.match(r"enum\s+(?:class\s+|struct\s+)?(\w+)", c)
    if m:
        return "enum", m.group(1)
    m = re.match(r"(?:\[\[[^\]]*\]\]\s*)?(?:struct|class|union)\s+(\w+)", c)
    if m:
        return "type", m.group(1)
    m = re.match(r"concept\s+(\w+)", c)
    if m:
        return "concept", m.group(1)
    m = re.match(r"using\s+(\w+)\s*=", c)
    if m:
        return "alias", m.group(1)
    paren = c.find("(")
    if paren >= 0 and "=" not in c[:paren]:
        m = re.search(r"(~?\w+)\s*$", c[:paren])
        if m and m.group(1) not in ("requires", "decltype", "sizeof", "alignas", "return"):
            return "function", m.group(1)
        return "other", None
    m = re.search(r"(\w+)\s*(?:=.*)?$", c, re.S)  # a variable: `... name = value` or `... name{`
    if m and re.search(r"\w\s+" + m.group(1), c):
        return "variable", m.group(1)
    return "other", None


class Declaration:
    def __init__(self, kind, namespace, name, path, body=""):
        self.kind, self.namespace, self.name, self.path, self.body = kind, namespace, name, path, body

    @property
    def qualified(self):
        return "::".join(self.namespace + [self.name])

    @property
    def in_detail(self):
        return "detail" in self.namespace


def scan_header(path, relative):
    """Every namespace-scope declaration of one header (types with their body text)."""
    code, literals = strip_code(path.read_text(encoding="utf-8"))
    declarations = []
    stack = []  # one entry per open '{': (kind, name, start index)
    chunk_start = 0
    for i, ch in enumerate(code):
        if ch not in "{};":
            continue
        chunk = code[chunk_start:i]
        chunk_start = i + 1
        at_namespace_scope = all(kind == "namespace" for kind, _, _ in stack)
        namespace = [part for kind, name, _ in stack for part in name.split("::") if name]
        if ch == "{":
            kind, name = classify(chunk) if at_namespace_scope else ("other", None)
            stack.append((kind, name or "", i))
            if at_namespace_scope and kind in ("function", "variable", "concept", "enum") and name:
                declarations.append(Declaration(kind, namespace, name, relative))
        elif ch == "}":
            if not stack:
                raise SystemExit(f"{relative}: unbalanced '}}'")
            kind, name, start = stack.pop()
            if kind in ("type", "enum") and all(k == "namespace" for k, _, _ in stack):
                outer = [part for k, nm, _ in stack for part in nm.split("::") if nm]
                body = code[start + 1 : i]
                if kind == "enum":  # the enum itself was recorded at '{'; attach its body
                    for d in declarations:
                        if d.kind == "enum" and d.name == name and d.namespace == outer and not d.body:
                            d.body = body
                else:
                    declarations.append(Declaration("type", outer, name, relative, body))
        elif at_namespace_scope:  # ';' ends a declaration without a body
            kind, name = classify(chunk)
            if kind in ("alias", "variable", "function", "type") and name:
                declarations.append(Declaration(kind, namespace, name, relative))
    if stack:
        raise SystemExit(f"{relative}: unbalanced '{{'")
    return declarations, literals


NAME_MEMBER = re.compile(r"std::string_view\s+name\s*(?:\(\s*\)\s*const\b|=)")
RUNTIME_NAME = re.compile(r"[A-Z][A-Za-z0-9]+")  # a name() string: one CamelCase word


def scan_library(root):
    include = root / "include" / "fluidbed"
    if not include.is_dir():
        raise SystemExit(f"no include/fluidbed under {root}")
    declarations, closures, runtime_names = [], set(), set()
    for path in sorted(include.rglob("*.hpp")):
        relative = path.relative_to(include).as_posix()
        found, literals = scan_header(path, relative)
        declarations += found
        if relative.split("/")[0] not in FAMILIES:
            continue
        for d in found:
            if d.in_detail:
                continue
            if d.kind == "function" or (d.kind == "type" and NAME_MEMBER.search(d.body)):
                closures.add((d.qualified, relative))
        runtime_names |= {s for s in literals if RUNTIME_NAME.fullmatch(s)}
    return declarations, closures, runtime_names


# ----------------------------------------------------------------------------- docs scanning

BACKTICK = re.compile(r"`([^`\n]+)`")
QUALIFIED = re.compile(r"\bfluidbed(?:::\w+)+")
PATH_IN_BACKTICKS = re.compile(r"^[\w./-]+\.(?:hpp|cpp|py|md|txt|csv|sh|cmake)$")
LINK_TARGET = re.compile(r"\]\(([^)\s#]*)(?:#([^)\s]*))?\)")  # (file, anchor); "(#anchor)" links its own file


def github_heading_slugs(lines):
    """(index, anchor) of every heading among the lines of a Markdown file, with the anchor
    GitHub gives it: lower case, characters other than letters, digits, spaces, '-' and '_'
    dropped, spaces to '-', repeats suffixed -1, -2. (Also used by docs/doxygen_filter.py.)"""
    slugs, seen = [], {}
    in_fence = False
    for index, line in enumerate(lines):
        if line.startswith("```"):
            in_fence = not in_fence
        m = None if in_fence else re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", line)
        if not m:
            continue
        text = re.sub(r"[`*]", "", m.group(1)).lower()
        slug = "".join(ch for ch in text if ch.isalnum() or ch in " -_").replace(" ", "-")
        count = seen.get(slug, 0)
        seen[slug] = count + 1
        slugs.append((index, slug if count == 0 else f"{slug}-{count}"))
    return slugs


def heading_ids(path):
    """The ids GitHub gives the headings of a Markdown file (the #fragment of a link)."""
    return {slug for _, slug in github_heading_slugs(path.read_text(encoding="utf-8").split("\n"))}


def doc_files(root):
    docs = root / "docs"
    return sorted(p for p in docs.rglob("*.md")) if docs.is_dir() else []


def check(root):
    declarations, closures, runtime_names = scan_library(root)
    by_qualified = {}
    for d in declarations:
        by_qualified.setdefault(d.qualified, []).append(d)
    namespaces = {"::".join(d.namespace[: k + 1]) for d in declarations for k in range(len(d.namespace))}

    files = doc_files(root)
    problems = []
    if not files:
        problems.append(f"no Markdown files under {root / 'docs'}")
    named = set()       # qualified names found in backticks
    text_all = ""
    for path in files:
        text = path.read_text(encoding="utf-8")
        text_all += text + "\n"
        shown = path.relative_to(root).as_posix()
        for lineno, line in enumerate(text.split("\n"), 1):
            for span in BACKTICK.findall(line):
                for q in QUALIFIED.findall(span):
                    named.add(q)
                    error = resolve(q, by_qualified, namespaces)
                    if error:
                        problems.append(f"{shown}:{lineno}: `{q}` {error}")
                token = span.strip()
                if PATH_IN_BACKTICKS.match(token) and not path_exists(root, path, token):
                    problems.append(f"{shown}:{lineno}: path `{token}` does not exist")
            for target, anchor in LINK_TARGET.findall(line):
                if "://" in target or target.startswith("mailto:"):
                    continue
                linked = path if not target else path.parent / target
                if not linked.exists():
                    problems.append(f"{shown}:{lineno}: link target {target} does not exist")
                elif anchor and linked.suffix == ".md" and anchor not in heading_ids(linked):
                    problems.append(f"{shown}:{lineno}: no heading #{anchor} in {target or shown}")

    catalogued = {q for q in named} | {q.rsplit("::", 1)[0] for q in named if "::" in q}
    for qualified, header in sorted(closures):
        if qualified not in catalogued:
            problems.append(f"not catalogued: `{qualified}` ({header})")
    for name in sorted(runtime_names):
        if f'"{name}"' not in text_all:
            problems.append(f'run-time name "{name}" does not appear in the docs as `"{name}"`')
    return closures, problems


def resolve(qualified, by_qualified, namespaces):
    """None if `qualified` names something the headers declare, else what is wrong."""
    if qualified in by_qualified or qualified in namespaces:
        return None
    parts = qualified.split("::")
    for k in range(len(parts) - 1, 1, -1):  # fluidbed::ns::Type::member...
        owner = "::".join(parts[:k])
        for d in by_qualified.get(owner, []):
            if d.kind in ("type", "enum") and all(re.search(r"\b" + re.escape(m) + r"\b", d.body) for m in parts[k:]):
                return None
    if qualified.split("::")[-1] in {d.name for ds in by_qualified.values() for d in ds}:
        return "is declared, but not in that namespace"
    return "is not declared in include/fluidbed/"


def path_exists(root, doc, token):
    candidates = [root / token, root / "include" / "fluidbed" / token, root / "include" / token, doc.parent / token]
    return any(p.exists() for p in candidates)


def main(argv):
    listing = "--list" in argv
    args = [a for a in argv[1:] if a != "--list"]
    root = Path(args[0]).resolve() if args else Path(__file__).resolve().parent.parent
    if listing:
        _, closures, runtime_names = scan_library(root)
        for qualified, header in sorted(closures, key=lambda c: (c[1], c[0])):
            print(f"{header:45s} {qualified}")
        print("run-time names:", " ".join(sorted(runtime_names)))
        return 0
    closures, problems = check(root)
    families = {}  # an overload set declared in several headers counts once
    for qualified in {q for q, _ in closures}:
        family = qualified.split("::")[1]
        families[family] = families.get(family, 0) + 1
    summary = ", ".join(f"{f} {families.get(f, 0)}" for f in FAMILIES)
    if problems:
        print(f"docs catalogue check FAILED ({len(problems)} problems):")
        for p in problems:
            print("  " + p)
        return 1
    print(f"docs catalogue OK: {sum(families.values())} public closures catalogued ({summary}); "
          f"{len(doc_files(root))} doc files checked")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
