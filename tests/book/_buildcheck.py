"""Checks shared by the book and docs build tests."""

from __future__ import annotations

import re
from dataclasses import dataclass
from html.parser import HTMLParser
from pathlib import Path


class _External(HTMLParser):
    def __init__(self) -> None:
        super().__init__()
        self.found: list[str] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        wanted = {"script": "src", "link": "href"}.get(tag)
        for key, value in attrs:
            if key == wanted and value and re.match(r"^(https?:)?//", value.strip()):
                self.found.append(f"<{tag} {key}={value}>")


def external_resources(html_dir: Path) -> dict[str, list[str]]:
    """Map each built page to the scripts and stylesheets it would load from the network."""
    result = {}
    for page in sorted(html_dir.rglob("*.html")):
        if "_static" in page.parts:
            continue
        parser = _External()
        parser.feed(page.read_text(encoding="utf-8"))
        if parser.found:
            result[str(page.relative_to(html_dir))] = parser.found
    return result


def toctree_entries(source: Path) -> list[str]:
    """The documents named in the {toctree} directives of the source pages."""
    entries = []
    for page in sorted(source.glob("*.md")):
        text = page.read_text(encoding="utf-8")
        for block in re.findall(
            r"^(`{3,}|:{3,})\{toctree\}[^\n]*\n(.*?)^\1\s*$", text, re.M | re.S
        ):
            for line in block[1].splitlines():
                line = line.strip()
                if not line or line.startswith(":"):
                    continue
                match = re.search(r"<([^>]+)>$", line)
                entries.append((match.group(1) if match else line).removesuffix(".md"))
    return entries


def pages_with_math(html_dir: Path) -> list[Path]:
    """The built pages that contain math (Sphinx adds the MathJax script only to those)."""
    return [
        p
        for p in sorted(html_dir.rglob("*.html"))
        if "_static" not in p.parts and 'class="math' in p.read_text(encoding="utf-8")
    ]


class _Links(HTMLParser):
    def __init__(self) -> None:
        super().__init__()
        self.found: list[str] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.found += [v for k, v in attrs if k in ("href", "src") and v is not None]


def links(html_dir: Path) -> dict[str, list[str]]:
    """Map each built page to the href and src values it contains (entities decoded)."""
    result = {}
    for page in sorted(html_dir.rglob("*.html")):
        if "_static" in page.parts:
            continue
        parser = _Links()
        parser.feed(page.read_text(encoding="utf-8"))
        result[str(page.relative_to(html_dir))] = parser.found
    return result


def links_with_spaces(html_dir: Path) -> dict[str, list[str]]:
    """The links that contain white space: a URL with a space is a broken URL (a `~` in
    a .bib url field becomes a space unless escaped)."""
    result = {}
    for page, found in links(html_dir).items():
        bad = [link for link in found if re.search(r"\s", link.strip())]
        if bad:
            result[page] = bad
    return result


@dataclass(frozen=True)
class BookIndex:
    """The book as Sphinx resolved it in a build: reading order, titles, numbers.

    Read from the build's environment (``<doctrees>/environment.pickle``), not from the
    pages: the numbers are the ones the HTML shows. ``files`` is the notebook of each page
    that has one (tools/classroom/export.py names them).
    """

    pages: list[str]  # the executed pages in reading order, the index first
    exported: list[str]
    files: dict[str, str]
    titles: dict[str, str]
    exercise_numbers: dict[str, str]  # label -> number, in reading order
    exercise_pages: dict[str, str]  # label -> page
    figure_numbers: dict[str, str]  # figure id -> number


def book_index(doctrees: Path) -> BookIndex:
    import pickle

    from tools.classroom import export

    with (doctrees / "environment.pickle").open("rb") as f:
        env = pickle.load(f)
    pages = export.reading_order(env)
    files = export.notebook_files(env)

    def numbered(kind: str) -> dict[str, tuple[str, str]]:
        return {i: (".".join(map(str, n)), page) for page in pages
                for i, n in env.toc_fignumbers.get(page, {}).get(kind, {}).items()}

    exercises = numbered("exercise")
    return BookIndex(
        pages=pages, exported=list(files), files=files,
        titles={page: env.titles[page].astext() for page in pages},
        exercise_numbers={k: v[0] for k, v in exercises.items()},
        exercise_pages={k: v[1] for k, v in exercises.items()},
        figure_numbers={k: v[0] for k, v in numbered("figure").items()},
    )
