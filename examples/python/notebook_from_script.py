#!/usr/bin/env python3
"""A Jupyter notebook (nbformat 4, no outputs) from a Python script written in cells: the script's
docstring becomes the first Markdown cell, each "# %%" line starts a code cell and each
"# %% [markdown]" line a Markdown cell whose lines are comments ("# " stripped). The examples are
kept as scripts (run by the tests without Jupyter) and their notebooks made from them.

Usage: notebook_from_script.py SCRIPT.py NOTEBOOK.ipynb
       notebook_from_script.py --check SCRIPT.py NOTEBOOK.ipynb   (exit 1 if the notebook differs)
       notebook_from_script.py --run NOTEBOOK.ipynb [ARG ...]     (execute its code cells in order,
                                                                   as a kernel would, without Jupyter)
"""
import ast
import json
import sys


def cells_of(script):
    """The notebook cells of a script's text."""
    docstring = ast.get_docstring(ast.parse(script), clean=True)
    cells, kind, lines = [], None, []

    def close():
        while lines and not lines[-1].strip():
            lines.pop()
        if kind is not None and lines:
            source = [line + "\n" for line in lines[:-1]] + [lines[-1]]
            cells.append({"cell_type": kind, "metadata": {}, "source": source,
                          **({"execution_count": None, "outputs": []} if kind == "code" else {})})

    for line in script.splitlines():
        if line.startswith("# %%"):
            close()
            kind, lines = ("markdown" if "[markdown]" in line else "code"), []
        elif kind == "markdown":
            lines.append(line[2:] if line.startswith("# ") else line.lstrip("#"))
        elif kind == "code" and (lines or line.strip()):
            lines.append(line)
    close()
    intro = {"cell_type": "markdown", "metadata": {}, "source": [docstring]}
    return [intro] + cells


def notebook_text(script):
    notebook = {"cells": cells_of(script),
                "metadata": {"kernelspec": {"display_name": "Python 3", "language": "python", "name": "python3"},
                             "language_info": {"name": "python"}},
                "nbformat": 4, "nbformat_minor": 5}
    for number, cell in enumerate(notebook["cells"]):
        cell["id"] = f"cell-{number}"
    return json.dumps(notebook, indent=1, ensure_ascii=False) + "\n"


def run(notebook_path, arguments):
    with open(notebook_path, encoding="utf-8") as f:
        notebook = json.load(f)
    sys.argv = [notebook_path] + arguments
    namespace = {"__name__": "__main__"}
    for cell in notebook["cells"]:
        if cell["cell_type"] == "code":
            exec(compile("".join(cell["source"]), notebook_path, "exec"), namespace)


def main(argv):
    if argv[:1] == ["--run"]:
        run(argv[1], argv[2:])
        return 0
    check = argv[:1] == ["--check"]
    script_path, notebook_path = argv[1:] if check else argv
    with open(script_path, encoding="utf-8") as f:
        text = notebook_text(f.read())
    if check:
        with open(notebook_path, encoding="utf-8") as f:
            if f.read() != text:
                print(f"{notebook_path} is not the notebook of {script_path}: run notebook_from_script.py")
                return 1
        return 0
    with open(notebook_path, "w", encoding="utf-8") as f:
        f.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
