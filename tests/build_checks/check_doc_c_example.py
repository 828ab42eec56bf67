#!/usr/bin/env python3
"""The C example of docs/c_interface.md, as written: compiled as C11 with every warning an error
against the C interface just built, run, and its output checked against the MazzeiLettieri values
the C++ library gives (printed by the example as 'beta = ...').

Usage: check_doc_c_example.py SOURCE_DIR WORK_DIR C_COMPILER INCLUDE_DIR LIBRARY
"""
import re
import subprocess
import sys
from pathlib import Path


def main(argv):
    if len(argv) != 6:
        sys.exit(__doc__)
    source, work, compiler, include, library = argv[1], Path(argv[2]), argv[3], argv[4], Path(argv[5])
    text = (Path(source) / "docs" / "c_interface.md").read_text()
    blocks = re.findall(r"```c\n(.*?)```", text, re.S)
    if len(blocks) != 1:
        print(f"docs/c_interface.md has {len(blocks)} C blocks, expected 1")
        return 1
    work.mkdir(parents=True, exist_ok=True)
    (work / "example.c").write_text(blocks[0])
    subprocess.run([compiler, "-std=c11", "-Wall", "-Wextra", "-Wpedantic", "-Werror", f"-I{include}",
                    str(work / "example.c"), str(library), f"-Wl,-rpath,{library.parent}", "-o",
                    str(work / "example")], check=True)
    output = subprocess.run([str(work / "example")], check=True, capture_output=True, text=True).stdout
    print(output, end="")
    if not output.startswith("beta = "):
        print("the example did not print beta")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
