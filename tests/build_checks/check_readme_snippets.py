#!/usr/bin/env python3
"""Compiles and runs the C++ snippets of README.md the way a user would, and checks their output.

Every ```cpp block of README.md is a snippet: its #include lines go to the top of one translation
unit, the rest becomes the body of a function. The ```text block that must follow each snippet is
what it prints. The translation unit is compiled with the flags users build with, warnings as
errors, and the headers found as a pkg-config user finds them (-I, not -isystem, also for Eigen):

    <compiler> -std=c++20 -Wall -Wextra -Wpedantic -Werror  x  {-O2, -O3, -O3 -march=native}
                                                            x  {with, without -DNDEBUG}

and each snippet's output must equal its ```text block in every configuration.

    check_readme_snippets.py <source dir> <scratch dir> <compiler> [<compiler> ...]

A compiler that is not installed is reported and skipped (exit 77 when none is installed).
Standard library only.
"""
import concurrent.futures
import os
import re
import shutil
import subprocess
import sys

OPTIMISATIONS = [["-O2"], ["-O3"], ["-O3", "-march=native"]]
ASSERTIONS = [[], ["-DNDEBUG"]]
WARNINGS = ["-Wall", "-Wextra", "-Wpedantic", "-Werror"]


def snippets_of(readme_text):
    """[(line number, code, expected output)] for every ```cpp block of the README."""
    lines = readme_text.splitlines()
    found, i = [], 0
    while i < len(lines):
        if lines[i].strip() != "```cpp":
            i += 1
            continue
        start = i + 1
        end = lines.index("```", start)
        code = lines[start:end]
        j = end + 1
        while j < len(lines) and not lines[j].strip():
            j += 1
        if j >= len(lines) or lines[j].strip() != "```text":
            sys.exit(f"README.md:{start}: a ```cpp snippet must be followed by the ```text block of what it prints")
        output_end = lines.index("```", j + 1)
        found.append((start, code, lines[j + 1:output_end]))
        i = output_end + 1
    if not found:
        sys.exit("README.md has no ```cpp snippet")
    return found


def translation_unit(snippets):
    includes, bodies = [], []
    for k, (line, code, _) in enumerate(snippets):
        body = []
        for text in code:
            if text.startswith("#include"):
                if text not in includes:
                    includes.append(text)
            else:
                body.append("  " + text if text else "")
        bodies.append(f"// README.md line {line}\nstatic void snippet_{k}() {{\n" + "\n".join(body) + "\n}\n")
    includes.append("#include <cstdlib>")
    calls = "\n".join(f"    case {k}: snippet_{k}(); break;" for k in range(len(snippets)))
    main = ("int main(int argc, char** argv) {\n  switch (argc > 1 ? std::atoi(argv[1]) : -1) {\n" + calls +
            "\n    default: return 2;\n  }\n  return 0;\n}\n")
    return "\n".join(includes) + "\n\n" + "\n".join(bodies) + "\n" + main


def eigen_flags():
    try:
        return subprocess.run(["pkg-config", "--cflags", "eigen3"], check=True, capture_output=True,
                              text=True).stdout.split()
    except (OSError, subprocess.CalledProcessError):
        return ["-I/usr/include/eigen3"]


def check(compiler, flags, source, work, snippets, source_dir):
    name = "-".join([os.path.basename(compiler)] + [f.lstrip("-").replace("=", "") for f in flags])
    program = os.path.join(work, name)
    command = [compiler, "-std=c++20", *WARNINGS, *flags, f"-I{source_dir}/include", *eigen_flags(), source, "-o",
               program]
    build = subprocess.run(command, capture_output=True, text=True)
    if build.returncode != 0:
        return f"{name}: does not compile:\n  {' '.join(command)}\n" + build.stderr[-4000:]
    problems = []
    for k, (line, _, expected) in enumerate(snippets):
        run = subprocess.run([program, str(k)], capture_output=True, text=True)
        got = [text.rstrip() for text in run.stdout.rstrip("\n").splitlines()]
        want = [text.rstrip() for text in expected]
        if run.returncode != 0 or got != want:
            problems.append(f"{name}: the snippet at README.md:{line} exits {run.returncode} and prints\n    " +
                            "\n    ".join(got) + "\n  instead of\n    " + "\n    ".join(want))
    return "\n".join(problems) or None


def main():
    source_dir, work, compilers = os.path.abspath(sys.argv[1]), sys.argv[2], sys.argv[3:]
    os.makedirs(work, exist_ok=True)
    with open(os.path.join(source_dir, "README.md"), encoding="utf-8") as readme:
        snippets = snippets_of(readme.read())
    source = os.path.join(work, "readme_snippets.cpp")
    with open(source, "w", encoding="utf-8") as out:
        out.write(translation_unit(snippets))

    installed = [c for c in compilers if shutil.which(c)]
    for c in set(compilers) - set(installed):
        print(f"{c}: not installed, not checked")
    if not installed:
        return 77
    configurations = [(c, o + a) for c in installed for o in OPTIMISATIONS for a in ASSERTIONS]
    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
        results = list(pool.map(lambda cf: check(cf[0], cf[1], source, work, snippets, source_dir), configurations))
    failures = [r for r in results if r]
    for r in failures:
        print(r)
    print(f"{len(snippets)} README snippets x {len(configurations)} configurations "
          f"({', '.join(installed)}): {len(failures)} failing")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
