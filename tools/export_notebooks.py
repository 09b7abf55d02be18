"""Export the book's MyST pages as plain Jupyter notebooks for the classroom.

Jupyter renders neither MyST roles (``{eq}`...```) nor directives (``:::{prf:lemma}``), so
a page converted as it is shows raw markup. This script reads each page that has a jupytext
header, keeps the code cells as they are, and rewrites the Markdown cells to plain Markdown:
proofs, admonitions and exercises (numbered per page) become bold headings over block quotes,
solutions a bold heading over their text and cells, equation labels are dropped,
references become text, and ``{glue:text}`` roles become the glued numbers when the notebook
is executed here (``--execute``), or the glued name in code font otherwise.

Usage::

    python tools/export_notebooks.py book notebooks [--execute] [--timeout SECONDS]
"""

from __future__ import annotations

import argparse
import os
import re
import sys
from collections.abc import Callable, Iterable
from pathlib import Path

import jupytext
import nbformat

GlueFn = Callable[[str, str], str]

DIRECTIVE_OPEN = re.compile(
    r"^(?P<indent>\s*)(?P<fence>`{3,}|:{3,})\{(?P<name>[^}]+)\}\s*(?P<arg>.*)$"
)
OPTION = re.compile(r"^\s*:(?P<key>[\w-]+):\s*(?P<value>.*)$")
ROLE = re.compile(r"\{(?P<role>[\w:+-]+)\}`(?P<content>[^`]*)`")
TARGET = re.compile(r"^\s*\([\w:.-]+\)=\s*$")
DMATH_LABEL = re.compile(r"^(?P<close>.*\$\$)\s*\([\w:.-]+\)\s*$")
TEXT_AND_TARGET = re.compile(r"^(?P<text>.*?)\s*<(?P<target>[^<>]+)>$", re.DOTALL)

# Directive names shown as a bold heading over a block quote, and the heading they get.
BOXED = {
    "prf:theorem": "Theorem",
    "prf:proposition": "Proposition",
    "prf:lemma": "Lemma",
    "prf:corollary": "Corollary",
    "prf:definition": "Definition",
    "prf:remark": "Remark",
    "prf:example": "Example",
    "prf:property": "Property",
    "prf:observation": "Observation",
    "prf:conjecture": "Conjecture",
    "prf:assumption": "Assumption",
    "prf:axiom": "Axiom",
    "prf:criterion": "Criterion",
    "prf:algorithm": "Algorithm",
    "prf:proof": "Proof",
    "exercise": "Exercise",
    "solution": "Solution",
    "note": "Note",
    "warning": "Warning",
    "tip": "Tip",
    "important": "Important",
    "hint": "Hint",
    "caution": "Caution",
    "attention": "Attention",
    "danger": "Danger",
    "error": "Error",
    "seealso": "See also",
    "admonition": "",
    "dropdown": "",
    "epigraph": "",
}
# Directives with nothing to show in a notebook (navigation, bibliography, glued figures
# whose picture the code cell above already draws).
DROPPED = {
    "toctree",
    "bibliography",
    "contents",
    "tableofcontents",
    "glue:figure",
    "glue",
    "glue:any",
    "solution-end",
    "exercise-end",
}
CODE = {"code-block", "code", "sourcecode", "literalinclude"}


def default_glue(name: str, fmt: str) -> str:
    """Show a glued value that is not known yet as its name in code font."""
    return f"`{name}`"


def convert_roles(text: str, glue: GlueFn) -> str:
    """Rewrite the MyST roles of one Markdown text to plain Markdown."""

    def replace(match: re.Match[str]) -> str:
        role, content = match["role"], match["content"]
        if role == "math":
            return f"${content}$"
        if role.startswith("glue"):
            name, _, fmt = content.partition(":")
            return glue(name.strip(), fmt.strip())
        if role == "eq":
            label = content.strip()
            return "(" + re.sub(r"^eq[-:]?", "", label) + ")"
        if role.startswith("cite"):
            return "[" + ", ".join(k.strip() for k in content.split(",")) + "]"
        m = TEXT_AND_TARGET.match(content)
        if m:  # {ref}`the text <label>` keeps the text
            return m["text"].strip()
        if role in {"ref", "numref", "prf:ref", "doc", "term", "any"}:
            return "*" + content.strip().replace("-", " ") + "*"
        return content

    return ROLE.sub(replace, text)


def _quote(lines: list[str]) -> list[str]:
    return [("> " + line).rstrip() for line in lines]


def convert_markdown(
    text: str,
    glue: GlueFn = default_glue,
    source_dir: Path | None = None,
    out_dir: Path | None = None,
) -> str:
    """Rewrite a MyST Markdown cell to Markdown that plain Jupyter renders."""
    lines = text.splitlines()
    out: list[str] = []
    i = 0
    while i < len(lines):
        line = lines[i]
        opened = DIRECTIVE_OPEN.match(line)
        if opened:
            fence = opened["fence"]
            name = opened["name"].strip()
            arg = opened["arg"].strip()
            body: list[str] = []
            i += 1
            depth_fence = re.compile(
                r"^\s*" + re.escape(fence[0]) + "{" + str(len(fence)) + r",}\s*$"
            )
            while i < len(lines) and not depth_fence.match(lines[i]):
                body.append(lines[i])
                i += 1
            i += 1  # the closing fence
            out.extend(_convert_directive(name, arg, body, glue, source_dir, out_dir))
            continue
        if TARGET.match(line) or line.lstrip().startswith("% "):
            i += 1
            continue
        labelled = DMATH_LABEL.match(line)
        if labelled:
            line = labelled["close"]
        out.append(line)
        i += 1
    text = convert_roles("\n".join(out), glue)
    return re.sub(r"\n{3,}", "\n\n", text).strip("\n")


def _convert_directive(
    name: str,
    arg: str,
    body: list[str],
    glue: GlueFn,
    source_dir: Path | None,
    out_dir: Path | None,
) -> list[str]:
    options: dict[str, str] = {}
    while body and OPTION.match(body[0]):
        m = OPTION.match(body[0])
        assert m is not None
        options[m["key"]] = m["value"]
        body = body[1:]
    inner = convert_markdown("\n".join(body), glue, source_dir, out_dir).splitlines()
    if name in DROPPED:
        return []
    if name in CODE:
        return ["```" + (arg or "python"), *body, "```", ""]
    if name == "math":
        return ["$$", *body, "$$", ""]
    if name in {"figure", "image"}:
        path = arg
        if source_dir is not None and out_dir is not None and not re.match(r"^\w+://", path):
            path = os.path.relpath(source_dir / path, out_dir).replace(os.sep, "/")
        alt = options.get("alt", "figure")
        block = ["", f"![{alt}]({path})", ""]
        if inner:
            block += [f"*{' '.join(inner).strip()}*", ""]
        return block
    if name == "solution-start":  # gated: the solution's text and cells follow, unquoted
        return ["", "**Solution.**", ""]
    if name in BOXED or name.startswith("prf:"):
        kind = BOXED.get(name, name.split(":")[-1].capitalize())
        # A solution's argument is the label of its exercise, not a title.
        title = "" if name == "solution" else convert_roles(arg, glue)
        heading = f"{kind} ({title})" if kind and title else (kind or title)
        if name == "prf:proof":
            heading = "Proof"
        head = [f"> **{heading}.**", ">"] if heading else []
        return ["", *head, *_quote(inner), ""]
    return ["", *inner, ""]


def _is_myst_notebook(path: Path) -> bool:
    head = path.read_text(encoding="utf-8")[:400]
    return head.startswith("---") and "jupytext:" in head


def book_pages(book_dir: Path) -> list[Path]:
    """Return the book pages that are notebooks (MyST Markdown with a jupytext header)."""
    return sorted(p for p in book_dir.glob("*.md") if _is_myst_notebook(p))


def export_page(page: Path, out_dir: Path, glue: GlueFn = default_glue) -> nbformat.NotebookNode:
    """Read one MyST page with jupytext and return it as a plain-Markdown notebook."""
    nb = jupytext.read(page, fmt="md:myst")
    for cell in nb.cells:
        if cell.cell_type == "markdown":
            cell.source = convert_markdown(cell.source, glue, page.parent, out_dir)
        elif cell.cell_type == "raw":
            cell.cell_type = "markdown"
            cell.source = convert_markdown(cell.source, glue, page.parent, out_dir)
            cell.pop("outputs", None)
            cell.pop("execution_count", None)
    nb.cells = [c for c in nb.cells if c.source.strip()]
    # Number the exercises of this notebook "Exercise 1", "Exercise 2", ... (the HTML book
    # numbers them through the whole book instead).
    count = 0

    def number(match: re.Match[str]) -> str:
        nonlocal count
        count += 1
        return f"**Exercise {count}"

    for cell in nb.cells:
        if cell.cell_type == "markdown":
            cell.source = re.sub(r"\*\*Exercise(?=[ .])", number, cell.source)
    origin = nbformat.v4.new_markdown_cell(
        f"*Classroom notebook generated from `book/{page.name}` by `tools/export_notebooks.py`; "
        "edit the book page, not this file.*"
    )
    nb.cells.insert(0, origin)
    nb.metadata.pop("jupytext", None)
    nb.metadata["kernelspec"] = {
        "name": "python3",
        "display_name": "Python 3",
        "language": "python",
    }
    return nb


def glued_values(nb: nbformat.NotebookNode) -> dict[str, object]:
    """Collect the values that ``myst_nb.glue`` recorded in the outputs of an executed notebook."""
    values: dict[str, object] = {}
    for cell in nb.cells:
        for output in cell.get("outputs", []):
            scrapbook = output.get("metadata", {}).get("scrapbook", {})
            name = scrapbook.get("name")
            if name is None:
                continue
            # display=False glues under a prefixed mime type that Jupyter does not show.
            text = output.get("data", {}).get(scrapbook.get("mime_prefix", "") + "text/plain")
            if text is None:
                continue
            try:
                values[name] = float(text)
            except ValueError:
                values[name] = text.strip("'\"")
    return values


def execute(nb: nbformat.NotebookNode, cwd: Path, timeout: int = 600) -> nbformat.NotebookNode:
    """Run a notebook top to bottom in a fresh ``python3`` kernel; raise on the first error."""
    from nbclient import NotebookClient

    client = NotebookClient(
        nb, timeout=timeout, kernel_name="python3", resources={"metadata": {"path": str(cwd)}}
    )
    client.execute()
    return nb


def fill_glue(nb: nbformat.NotebookNode, page: Path, out_dir: Path) -> nbformat.NotebookNode:
    """Rewrite the Markdown cells again, now with the glued values of the executed notebook."""
    values = glued_values(nb)

    def glue(name: str, fmt: str) -> str:
        if name not in values:
            return f"`{name}`"
        value = values[name]
        return format(value, fmt) if fmt and isinstance(value, float) else str(value)

    fresh = export_page(page, out_dir, glue)
    markdown = iter(c for c in fresh.cells if c.cell_type == "markdown")
    for cell in nb.cells:
        if cell.cell_type == "markdown":
            cell.source = next(markdown).source
    return nb


def export(
    book_dir: Path,
    out_dir: Path,
    run: bool = False,
    timeout: int = 600,
    pages: Iterable[Path] | None = None,
) -> list[Path]:
    """Export (and optionally execute) every notebook page of the book; return the files."""
    out_dir.mkdir(parents=True, exist_ok=True)
    written = []
    for page in pages if pages is not None else book_pages(book_dir):
        nb = export_page(page, out_dir)
        if run:
            execute(nb, out_dir, timeout)
            fill_glue(nb, page, out_dir)
        target = out_dir / (page.stem + ".ipynb")
        nbformat.write(nb, target)
        written.append(target)
    return written


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("book", type=Path, help="folder of the MyST pages (book/)")
    parser.add_argument("out", type=Path, help="folder for the .ipynb files (notebooks/)")
    parser.add_argument(
        "--execute", action="store_true", help="run each notebook in a fresh kernel"
    )
    parser.add_argument("--timeout", type=int, default=600, help="seconds per cell")
    args = parser.parse_args(argv)
    for path in export(args.book, args.out, run=args.execute, timeout=args.timeout):
        print(f"wrote {path}" + (" (executed)" if args.execute else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
