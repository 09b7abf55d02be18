"""Export the book's MyST pages as plain Jupyter notebooks, in a student and an instructor edition.

``notebooks/student/NN-page.ipynb`` and ``notebooks/instructor/NN-page.ipynb``, NN the reading
order of the book's toctree (00 is the first page, which lists the chapters). Markdown is plain
(see markdown.py); exercises keep the book's numbers (labels.py). Student:
each exercise is followed by an empty code cell and the solutions are left out. Instructor:
each solution opens with a "Solution to Exercise N" heading, then its worked cells.

The code needs only the package: ``from myst_nb import glue`` becomes a three-line stand-in
that keeps the values in a dict. The glued numbers of the text come from one execution of the
instructor edition (``--execute``; this also proves the cells run), or from the notebooks that
a book build has just executed (``--glue-from book/_build/jupyter_execute``, used by the Sphinx
extension book/_ext/classroom.py, whose HTML shows the same values). Values are formatted as
myst-nb formats ``{glue:text}`name:fmt``` so integers stay integers.

Each edition's folder also gets what a student needs to run it (bundle.py: the package's
wheel, requirements.txt, a README) and is zipped as ``notebooks/<name>-<edition>.zip``.

``--language ja`` makes the Japanese notebooks: each Markdown cell goes through its page's
catalog in book/locale before it is converted (translation.py), the exporter's own words are
Japanese (words.py), and so are the self-checks' answers and the bundle's README. The code
cells are the English ones.

Usage::

    python -m tools.classroom book notebooks [--execute | --glue-from DIR] [--language ja]
"""

from __future__ import annotations

import argparse
import json
import re
import sys
from ast import literal_eval
from pathlib import Path

import jupytext
import nbformat

from elliptic_pendulum import selfcheck

from . import bundle, translation
from .bib import label as bib_label
from .bib import load as load_bib
from .bib import reference_line
from .labels import Book, scan
from .markdown import SENTINEL, Context, Target, convert_markdown
from .words import ENGLISH, WORDS, Words, words

EDITIONS = ("student", "instructor")
GLUE_IMPORT = re.compile(r"^\s*from\s+myst_nb\s+import\s+glue\s*$", re.MULTILINE)
GLUE_STANDIN = """\
import IPython.display

# The book pastes these values into its text (glue); this notebook's text already
# shows them, so here glue only keeps them in the dict `glued` (and shows one if asked).
glued = {}


def glue(name, value, display=True):
    glued[name] = value
    if display:
        IPython.display.display(value)
"""
GLUE_HARVEST = (
    "import json as _json\n"
    "_fmt = get_ipython().display_formatter.format\n"
    "print('GLUED' + _json.dumps({k: _fmt(v)[0].get('text/plain', '') "
    "for k, v in globals().get('glued', {}).items()}))"
)
BOOK_ONLY = re.compile(r"^\s*(import|from)\s+(myst_nb|sphinx\w*|docutils)\b", re.MULTILINE)
# The book's folding tags, as Jupyter's own collapsed metadata.
HIDDEN = {
    "hide-input": ("source_hidden",), "remove-input": ("source_hidden",),
    "hide-output": ("outputs_hidden",), "remove-output": ("outputs_hidden",),
    "hide-cell": ("source_hidden", "outputs_hidden"),
    "remove-cell": ("source_hidden", "outputs_hidden"),
}


def format_glue(text: str, fmt: str) -> str:
    """myst-nb's format_plain_text: the text/plain of the value, formatted by the role's spec."""
    try:
        value: object = literal_eval(text)
    except (SyntaxError, ValueError):
        value = text
    if fmt == "":
        return str(value)
    kind = fmt[-1]
    if kind == "s":
        value = str(value)
    elif kind in "bcdoxX":
        value = int(value)  # type: ignore[call-overload]
    elif kind in "eEfFgGn%":
        value = float(value)  # type: ignore[arg-type]
    return format(value, fmt)


def _code_cell(cell: nbformat.NotebookNode, first_glue: list[bool]) -> None:
    source = cell.source
    if GLUE_IMPORT.search(source):
        source = GLUE_IMPORT.sub("", source)
        if first_glue[0]:  # one stand-in per notebook, or the dict would start again
            # First in the cell: the rest of the cell may glue already.
            source = GLUE_STANDIN + "\n\n" + source
            first_glue[0] = False
        cell.source = re.sub(r"\n{4,}", "\n\n\n", source).strip("\n")
    if BOOK_ONLY.search(cell.source):
        raise ValueError(f"a code cell needs myst_nb or Sphinx: {cell.source[:200]!r}")
    # The figure's caption becomes a Markdown cell under it (_caption_cell); its alt text and
    # options are the book's (MyST roles inside), which Jupyter neither shows nor reads.
    cell.metadata.pop("mystnb", None)
    hidden = {k for tag in cell.metadata.get("tags", []) for k in HIDDEN.get(tag, ())}
    if hidden:
        cell.metadata.setdefault("jupyter", {}).update({k: True for k in sorted(hidden)})
    cell.outputs, cell.execution_count = [], None


def _caption_cell(cell: nbformat.NotebookNode, book: Book, ctx: Context,
                  catalog: translation.Catalog | None = None) -> list[str]:
    figure = cell.metadata.get("mystnb", {}).get("figure", {})
    if not figure.get("caption"):
        return []
    name = figure.get("name", "")
    number = book.targets[name].number if name in book.targets else ""
    caption = str(figure["caption"]).strip()
    if catalog is not None:
        caption = translation.translate(caption, catalog)
    caption = convert_markdown(caption, ctx)
    anchor = f'<a id="{name}"></a>\n\n' if name else ""
    if not number:
        return [anchor + caption]
    return [anchor + ctx.words.figure_caption.format(number=number, caption=caption)]


def first_cell(book: Book, page: str, edition: str, answers: bool = False,
               language: Words = ENGLISH) -> str:
    """What a notebook says first: what it is, how to install what it needs if the import
    fails (the files beside it, bundle.py), and the licence of its text and figures."""
    title = book.titles.get(page, page)
    name = bundle.TITLE_JA if language.language == "ja" else bundle.TITLE
    lines = [
        language.first.format(book=name, edition=language.edition[edition], title=title),
        language.install.format(pip=bundle.pip_magic(), readme=bundle.README),
    ]
    if answers:
        lines.append(language.answers_intro)
    lines.append(language.licence.format(page=page, cc_by=bundle.CC_BY))
    return "\n\n".join(lines)


def _what(text: str, language: str) -> str:
    # A result's description, as the self-check names it in the notebook's language.
    if language == "en":
        return text
    from elliptic_pendulum.selfcheck import _ja

    found = _ja.MESSAGES.get(text)
    if found is None:
        raise translation.Untranslated(f"self-check text without a translation: {text[:80]!r}")
    return found


def answer_cells(label: str, ctx: Context,
                 catalog: translation.Catalog | None = None) -> list[nbformat.NotebookNode]:
    """What a student gets under an exercise: for its results, a cell that names them and
    the self-check that reads them (elliptic_pendulum.selfcheck); for what it asks to prove
    or explain, a Markdown cell to write in and a folded hint. An exercise without a
    self-check gets one empty code cell."""
    exercise = selfcheck.EXERCISES.get(label)
    if exercise is None:
        return [nbformat.v4.new_code_cell("")]
    cells = []
    w = ctx.words
    if exercise.values:
        names = w.result_separator.join(
            w.result_name.format(name=v.name, what=_what(v.what, w.language))
            for v in exercise.values)
        cells.append(nbformat.v4.new_markdown_cell(w.results.format(names=names)))
        cells.append(nbformat.v4.new_code_cell(
            "\n".join(w.placeholder.format(name=v.name) for v in exercise.values)))
        cells.extend(self_check_cells(label, "student", w.language))
    if exercise.written is not None:
        # The site shows the same hint under the exercise (book/_ext/classroom.py), so the
        # page's catalog translates it.
        written = exercise.written
        if catalog is not None:
            written = translation.translate(written, catalog)
        hint = convert_markdown(written, ctx).strip()
        cells.append(nbformat.v4.new_markdown_cell(w.hint.format(hint=hint)))
        cell = nbformat.v4.new_markdown_cell(w.answer)
        cell.metadata["classroom"] = {"written": label}
        cells.append(cell)
    if not exercise.values:  # for the computations a proof exercise may ask for too
        cells.append(nbformat.v4.new_code_cell(""))
    return cells


def self_check_cells(label: str, edition: str,
                     language: str = "en") -> list[nbformat.NotebookNode]:
    """The cell that runs the self-check of exercise ``label`` on the names of its results:
    under the student's answer cell, and under the instructor's solution (which it checks
    against the self-check's independent reference every time the notebook runs)."""
    exercise = selfcheck.EXERCISES[label]
    if not exercise.values:
        return []
    args = ", ".join(f"{v.name}={v.name}" for v in exercise.values)
    # A translated edition's notebooks ask for their language: the check answers in it
    # whatever the student's environment says (English ones follow the environment).
    if language != "en":
        args = f"language={language!r}, {args}"
    cell = nbformat.v4.new_code_cell(
        f"from elliptic_pendulum.selfcheck import check\n\ncheck({label!r}, {args})")
    cell.metadata["classroom"] = {"self_check": label}
    return [cell]


def localize(book: Book, book_dir: Path, language: str) -> Book:
    """The book's titles and link texts in ``language``: page and section titles from the
    pages' catalogs, "Exercise 5", "Fig. 3", "Lemma 2" in the exporter's words."""
    if language == "en":
        return book
    w = words(language)
    catalogs = {page: translation.load(book_dir / "locale", language, page)
                for page in book.pages}
    titles = {page: catalogs[page].need(title) if page in catalogs else title
              for page, title in book.titles.items()}
    targets = {}
    for label, t in book.targets.items():
        title = t.title
        if t.kind in ("section", "page", "other") and t.page in catalogs:
            found = catalogs[t.page].get(title)
            title = found if found is not None else (
                catalogs[t.page].need(title) if t.kind == "section" else title)
        elif t.kind == "exercise":
            title = w.exercise.format(number=t.number).strip()
        elif t.kind == "figure" and t.number:
            title = w.figure.format(number=t.number)
        elif t.kind == "statement":
            kind = title.split(" ")[0].lower()
            title = " ".join(p for p in (w.statement(kind), t.number) if p)
        targets[label] = Target(t.page, t.kind, title, t.number)
    for catalog in catalogs.values():
        catalog.check()
    return Book(book.pages, book.exported, book.files, titles, targets, book.exercise_numbers)


def export_page(
    book_dir: Path, book: Book, page: str, edition: str, glue: dict[str, str] | None,
    language: str = "en",
) -> nbformat.NotebookNode:
    """One page as a plain notebook of one edition. glue=None leaves `name` placeholders.

    language: the page's text through its catalog (translation.py) before it is converted,
    and the exporter's own words in that language; ``book`` is then the localized one.
    """
    if edition not in EDITIONS:
        raise ValueError(f"edition must be one of {EDITIONS}, not {edition!r}")
    w = words(language)
    catalog = (None if language == "en"
               else translation.load(book_dir / "locale", language, page))
    bib = load_bib(book_dir / "references.bib")
    cited: list[str] = []

    def glued(key: str, fmt: str) -> str:
        if glue is None:
            return f"`{key}`"
        if key not in glue:  # an error only if the text is kept (a student drops solutions)
            return f"{SENTINEL}MISSING {key}{SENTINEL}"
        try:
            return format_glue(glue[key], fmt)
        except ValueError as err:  # myst-nb refuses it too ("Failed to format text/plain")
            raise ValueError(f"page {page!r}: glued {key!r} = {glue[key]!r} does not take "
                             f"the format {fmt!r} ({err}); glue a Python float") from err

    def cite(role: str, keys: list[str]) -> str:
        links = []
        for key in keys:
            if key not in bib:
                raise ValueError(f"page {page!r} cites {key!r}, which is not in references.bib")
            cited.append(key)
            who, year = bib_label(bib[key])
            text = f"{who} [{year}]" if role in {"cite:t", "cite:ts"} else f"{who}, {year}"
            links.append(f"[{text}](#ref-{key})")
        joined = "; ".join(links)
        return joined if role in {"cite:t", "cite:ts"} else f"\\[{joined}\\]"

    ctx = Context(page, book.files, book.titles, book.targets, glued, cite,
                  book.exercise_numbers, book.exported[1:], w)
    nb = jupytext.read(book_dir / f"{page}.md", fmt="md:myst")
    cells: list[nbformat.NotebookNode] = []
    in_solution, first_glue, answers, current = False, [True], False, ""

    def mark(cell: nbformat.NotebookNode) -> nbformat.NotebookNode:
        # The instructor's solution cells say whose they are (tools/classroom/nbgrader.py
        # turns them into nbgrader's answer cells).
        if in_solution:
            cell.metadata["classroom"] = {"solution": current}
        return cell

    for cell in nb.cells:
        if cell.cell_type == "code":
            if not in_solution or edition == "instructor":
                captions = _caption_cell(cell, book, ctx, catalog)
                _code_cell(cell, first_glue)
                cells.append(mark(cell))
                cells.extend(mark(nbformat.v4.new_markdown_cell(t)) for t in captions)
            continue
        source = cell.source if catalog is None else translation.translate(cell.source, catalog)
        text = convert_markdown(source, ctx)
        pieces = re.split(f"^{SENTINEL}(\\w[\\w:-]*){SENTINEL}$", text, flags=re.MULTILINE)
        for index, piece in enumerate(pieces):
            marker, _, label = piece.partition(":") if index % 2 else ("", "", "")
            if marker == "ANSWER":
                if edition == "student":
                    cells.extend(answer_cells(label, ctx, catalog))
                    answers = True
            elif marker == "SOLUTION-START":
                in_solution, current = True, label
            elif marker == "SOLUTION-END":
                in_solution = False
                if edition == "instructor" and current in selfcheck.EXERCISES:
                    cells.extend(self_check_cells(current, edition, ctx.words.language))
            elif piece.strip() and (not in_solution or edition == "instructor"):
                missing = re.search(f"{SENTINEL}MISSING (.*?){SENTINEL}", piece)
                if missing:
                    raise ValueError(f"page {page!r} pastes {missing[1]!r}, which no cell glues")
                cells.append(mark(nbformat.v4.new_markdown_cell(piece.strip("\n"))))
    if in_solution:
        raise ValueError(f"page {page!r}: a solution-start has no solution-end")
    if cited:
        keys = list(dict.fromkeys(cited))
        cells.append(nbformat.v4.new_markdown_cell(
            f"## {w.references}\n\n" + "\n".join(reference_line(k, bib[k]) for k in keys)))
    if catalog is not None:
        catalog.check()  # a Japanese notebook holds no English paragraph
    out = nbformat.v4.new_notebook()
    out.cells = [nbformat.v4.new_markdown_cell(first_cell(book, page, edition, answers, w)),
                 *cells]
    out.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3",
                                  "language": "python"}
    out.metadata["language_info"] = {"name": "python"}
    for i, c in enumerate(out.cells):  # stable ids: a re-export changes no unchanged cell
        c["id"] = f"cell-{i}"
    return out


def execute(nb: nbformat.NotebookNode, cwd: Path, kernel: str = "python3",
            timeout: int = 600, kernel_dirs: list[str] | None = None) -> nbformat.NotebookNode:
    """Run a notebook top to bottom in a fresh kernel; raise on the first error.

    kernel_dirs: look the kernel up only there (e.g. a plain venv's share/jupyter/kernels),
    not in the user's Jupyter folders.
    """
    from jupyter_client.kernelspec import KernelSpecManager
    from jupyter_client.manager import KernelManager
    from nbclient import NotebookClient

    km = None
    if kernel_dirs is not None:
        km = KernelManager(kernel_name=kernel,
                           kernel_spec_manager=KernelSpecManager(kernel_dirs=kernel_dirs))
    # cleanup_kc: shut the kernel down afterwards even though the client does not own km.
    NotebookClient(nb, km=km, timeout=timeout, kernel_name=kernel,
                   resources={"metadata": {"path": str(cwd)}}).execute(cleanup_kc=True)
    return nb


def harvest(nb: nbformat.NotebookNode, cwd: Path, kernel: str = "python3",
            timeout: int = 600, kernel_dirs: list[str] | None = None) -> dict[str, str]:
    """Execute a notebook plus one cell that prints what `glue` kept: {name: text/plain}."""
    nb.cells.append(nbformat.v4.new_code_cell(GLUE_HARVEST, id="harvest"))
    execute(nb, cwd, kernel, timeout, kernel_dirs)
    cell = nb.cells.pop()
    text = "".join(o.get("text", "") for o in cell.outputs if o.output_type == "stream")
    return dict(json.loads(text.split("GLUED", 1)[1]))


def glue_from_build(folder: Path, page: str) -> dict[str, str]:
    """The values myst-nb glued while building the book (``<page>.glue.json``)."""
    path = folder / f"{page}.glue.json"
    if not path.exists():
        return {}
    data = json.loads(path.read_text(encoding="utf-8"))
    return {k: v.get("data", {}).get("text/plain", "") for k, v in data.items()}


def export(book_dir: Path, out_dir: Path, *, run: bool = False, glue_from: Path | None = None,
           editions: tuple[str, ...] = EDITIONS, kernel: str = "python3",
           timeout: int = 600, pages: list[str] | None = None,
           language: str = "en") -> list[Path]:
    """Write out_dir/<edition>/NN-page.ipynb for every notebook page; return the files.

    language: "ja" writes the Japanese edition's notebooks (book/locale's catalogs); their
    code cells are the English ones, so they glue the same values.
    """
    words(language)  # an unknown language fails here, before anything is written
    english = scan(book_dir)
    book = localize(english, book_dir, language)
    written = []
    for page in pages if pages is not None else book.exported:
        glue: dict[str, str] | None = None
        if glue_from is not None:
            glue = glue_from_build(glue_from, page)
        elif run:  # in the folder the notebook will live in, as a student runs it
            (out_dir / "instructor").mkdir(parents=True, exist_ok=True)
            glue = harvest(export_page(book_dir, english, page, "instructor", None),
                           out_dir / "instructor", kernel, timeout)
        for edition in editions:
            nb = export_page(book_dir, book, page, edition, glue, language)
            target = out_dir / edition / book.files[page]
            target.parent.mkdir(parents=True, exist_ok=True)
            nbformat.write(nb, target)
            written.append(target)
    return written


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    parser.add_argument("book", type=Path, help="folder of the MyST pages (book/)")
    parser.add_argument("out", type=Path, help="folder for the editions (notebooks/)")
    how = parser.add_mutually_exclusive_group()
    how.add_argument("--execute", action="store_true",
                     help="run each instructor notebook once to fill in the glued values")
    how.add_argument("--glue-from", type=Path, help="a build's jupyter_execute folder")
    parser.add_argument("--timeout", type=int, default=600, help="seconds per cell")
    parser.add_argument("--language", default="en", choices=sorted(WORDS),
                        help="the edition's language (ja: the Japanese notebooks)")
    args = parser.parse_args(argv)
    for path in export(args.book, args.out, run=args.execute, glue_from=args.glue_from,
                       timeout=args.timeout, language=args.language):
        print(f"wrote {path}")
    for path in bundle.bundle_editions(args.out, EDITIONS, language=args.language):
        print(f"wrote {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
