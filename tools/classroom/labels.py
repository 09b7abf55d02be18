"""The book's reading order and every label the pages define, numbered as Sphinx numbers them.

Sphinx numbers figures, exercises (sphinx-exercise) and proof statements (sphinx-proof) with
numfig. The book's toctree is not ``:numbered:``, so each kind has ONE counter over the whole
book, in the reading order of the toctree: the exercises of the third chapter may be 5 and 6.
The notebooks use exactly these numbers, so "Exercise 5" is the same exercise in the HTML book,
the PDF and both notebook editions. A figure or statement is numbered only when it has a label
(Sphinx skips nodes without ids) and, for figures, a caption; equations show their ``\\tag``.
"""

from __future__ import annotations

import ast
import re
from dataclasses import dataclass, field
from pathlib import Path

import jupytext

from .markdown import DIRECTIVE_OPEN, HEADING, OPTION, TARGET, Target

# Pages of the book that are not lessons and cannot run away from it: the registry of checks
# reads the checks the build found in the pages (tools/checks) and displays MyST tables.
# They keep their place in the book's numbering, but get no notebook; a link to them
# becomes plain text.
BOOK_ONLY_PAGES = {"checks"}
TAG = re.compile(r"\\tag\*?\{(?P<tag>[^}]*)\}")
TOCTREE = re.compile(r"^(`{3,}|:{3,})\{toctree\}[^\n]*\n(?P<body>.*?)^\1\s*$", re.S | re.M)


def is_notebook_page(path: Path) -> bool:
    """A MyST page with a jupytext header, which myst-nb executes."""
    head = path.read_text(encoding="utf-8")[:400]
    return head.startswith("---") and "jupytext:" in head


def reading_order(book_dir: Path, root: str = "index") -> list[str]:
    """The notebook pages in the order of the root toctree, the root page first."""
    text = (book_dir / f"{root}.md").read_text(encoding="utf-8")
    order = [root]
    for m in TOCTREE.finditer(text):
        for line in m["body"].splitlines():
            entry = line.strip()
            if not entry or OPTION.match(entry):
                continue
            entry = re.sub(r"^.*<(.+)>$", r"\1", entry).strip().lstrip("/")
            entry = re.sub(r"\.(md|ipynb)$", "", entry)
            path = book_dir / f"{entry}.md"
            if entry not in order and path.exists() and is_notebook_page(path):
                order.append(entry)
    return [p for p in order if is_notebook_page(book_dir / f"{p}.md")]


def prf_counters(conf: Path) -> dict[str, str]:
    """conf.py's prf_realtyp_to_countertyp (which statements share a counter)."""
    if not conf.exists():
        return {}
    for node in ast.walk(ast.parse(conf.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Assign) and any(
            isinstance(t, ast.Name) and t.id == "prf_realtyp_to_countertyp" for t in node.targets
        ):
            value = ast.literal_eval(node.value)
            return dict(value) if isinstance(value, dict) else {}
    return {}


@dataclass
class Book:
    """The pages in reading order, their titles and notebook names, every label."""

    pages: list[str]  # every notebook page, in reading order (numbering counts them all)
    exported: list[str] = field(default_factory=list)  # those with a classroom notebook
    files: dict[str, str] = field(default_factory=dict)
    titles: dict[str, str] = field(default_factory=dict)
    targets: dict[str, Target] = field(default_factory=dict)
    exercise_numbers: dict[str, str] = field(default_factory=dict)


def _options(lines: list[str], start: int) -> dict[str, str]:
    options = {}
    for line in lines[start:]:
        m = OPTION.match(line)
        if not m:
            break
        options[m["key"]] = m["value"].strip()
    return options


def scan(book_dir: Path) -> Book:
    """Read every notebook page once and number what Sphinx numbers."""
    pages = reading_order(book_dir)
    book = Book(pages)
    counters: dict[str, int] = {}
    shared = prf_counters(book_dir / "conf.py")

    def next_number(kind: str) -> str:
        counters[kind] = counters.get(kind, 0) + 1
        return str(counters[kind])

    book.exported = [p for p in pages if p not in BOOK_ONLY_PAGES]
    book.files = {page: f"{n:02d}-{page}.ipynb" for n, page in enumerate(book.exported)}
    for page in pages:
        nb = jupytext.read(book_dir / f"{page}.md", fmt="md:myst")
        equations = 0
        for cell in nb.cells:
            if cell.cell_type == "code":
                figure = cell.metadata.get("mystnb", {}).get("figure", {})
                name = figure.get("name")
                if name:
                    number = next_number("figure") if figure.get("caption") else ""
                    title = f"Fig. {number}" if number else name
                    book.targets[name] = Target(page, "figure", title, number)
                continue
            lines = cell.source.splitlines()
            for i, line in enumerate(lines):
                heading = HEADING.match(line)
                if heading and page not in book.titles and line.startswith("# "):
                    book.titles[page] = heading["title"]
                target = TARGET.match(line)
                if target:
                    label = target["label"]
                    rest = [x for x in lines[i + 1 :] if x.strip()]
                    following = rest[0] if rest else ""
                    if HEADING.match(following):
                        title = HEADING.match(following)["title"]  # type: ignore[index]
                        book.targets[label] = Target(page, "section", title)
                    elif following.lstrip().startswith(("$$", "\\begin")):
                        block = "\n".join(rest[:40])
                        end = block.find("$$", block.find("$$") + 2)
                        tag = TAG.search(block[: end if end > 0 else None])
                        if tag:
                            number = tag["tag"]
                        else:
                            equations += 1
                            number = str(equations)
                        book.targets[label] = Target(page, "equation", f"({number})", number)
                    else:
                        book.targets[label] = Target(page, "other", label)
                opened = DIRECTIVE_OPEN.match(line.strip())
                if not opened:
                    continue
                name = opened["name"].strip()
                options = _options(lines, i + 1)
                label = options.get("label") or options.get("name")
                if name in {"exercise", "exercise-start"}:
                    number = "" if "nonumber" in options else next_number("exercise")
                    if label:
                        book.exercise_numbers[label] = number
                        book.targets[label] = Target(page, "exercise", f"Exercise {number}", number)
                elif name.startswith("prf:") and name != "prf:proof" and label:
                    kind = name.split(":")[1]
                    number = "" if "nonumber" in options else next_number(shared.get(kind, kind))
                    title = f"{kind.capitalize()} {number}".strip()
                    book.targets[label] = Target(page, "statement", title, number)
                elif name == "figure" and label:
                    number = next_number("figure")
                    book.targets[label] = Target(page, "figure", f"Fig. {number}", number)
                elif name == "math" and label:
                    equations += 1
                    number = str(equations)
                    book.targets[label] = Target(page, "equation", f"({number})", number)
                elif label:
                    book.targets[label] = Target(page, "other", opened["arg"].strip() or label)
        book.titles.setdefault(page, page)
    for page in pages:
        book.targets.setdefault(page, Target(page, "page", book.titles[page]))
    return book
