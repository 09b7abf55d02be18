"""The classroom notebooks of one build of the book, a student and an instructor edition.

``<outdir>/classroom/<edition>/NN-page.ipynb``, NN the page's place in the reading order of
the book's toctree (00 is the first page, which lists the chapters). Each notebook is written
from the doctree Sphinx resolved for its page in this build (doctree.py), so it says what the
page says, in the build's language, with the page's numbers and glued values. The student
edition is written from the tree without its solutions, and gets cells for the answers under
each exercise; the instructor edition keeps each solution, headed "Solution to Exercise N",
with the self-check cell after it.

The code needs only the package: ``from myst_nb import glue`` becomes a three-line stand-in
that keeps the values in a dict. The book's Sphinx extension (book/_ext/classroom.py) calls
:func:`export` once its pages are written; bundle.py then adds what a student needs to run
them.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import nbformat
from docutils import nodes
from myst_nb.core.read import read_myst_markdown_notebook

from elliptic_pendulum import selfcheck

from . import bundle, doctree
from .words import Words, words

EDITIONS = ("student", "instructor")
# Pages of the book that are not lessons and cannot run away from it: the registry of checks
# reads the checks the build found in the pages and displays MyST tables. They keep their
# place in the book's numbering, but get no notebook; a link to them keeps its text only.
BOOK_ONLY_PAGES = {"checks"}
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
BOOK_ONLY = re.compile(r"^\s*(import|from)\s+(myst_nb|sphinx\w*|docutils)\b", re.MULTILINE)
# The book's folding tags, as Jupyter's own collapsed metadata.
HIDDEN = {
    "hide-input": ("source_hidden",), "remove-input": ("source_hidden",),
    "hide-output": ("outputs_hidden",), "remove-output": ("outputs_hidden",),
    "hide-cell": ("source_hidden", "outputs_hidden"),
    "remove-cell": ("source_hidden", "outputs_hidden"),
}


def reading_order(env: Any, root: str = "index") -> list[str]:
    """The notebook pages (executed by myst-nb) in the order of the toctrees, root first."""
    order: list[str] = []

    def visit(doc: str) -> None:
        if doc in order:
            return
        order.append(doc)
        for child in env.toctree_includes.get(doc, []):
            visit(child)

    visit(root)
    # A page with a jupytext header (and so a kernel): myst-nb executes it as a notebook.
    return [d for d in order if {"jupytext", "kernelspec"} & set(env.metadata.get(d, {}))]


def notebook_files(env: Any) -> dict[str, str]:
    """docname -> its notebook's file name, for the pages that have one."""
    return {doc: f"{i:02d}-{doc}.ipynb" for i, doc in enumerate(reading_order(env))
            if doc not in BOOK_ONLY_PAGES}


def _numbers(env: Any, docname: str) -> dict[str, str]:
    found = env.toc_fignumbers.get(docname, {})
    return {i: ".".join(map(str, n)) for kind in found.values() for i, n in kind.items()}


def _exercise_numbers(env: Any) -> dict[str, str]:
    return {i: ".".join(map(str, n)) for found in env.toc_fignumbers.values()
            for i, n in found.get("exercise", {}).items()}


def code_cell(source: str, metadata: dict, first_glue: list[bool]) -> nbformat.NotebookNode:
    """A code cell of the book as a notebook's: no myst-nb, the book's folds as Jupyter's."""
    if GLUE_IMPORT.search(source):
        source = GLUE_IMPORT.sub("", source)
        if first_glue[0]:  # one stand-in per notebook, or the dict would start again
            # First in the cell: the rest of the cell may glue already.
            source = GLUE_STANDIN + "\n\n" + source
            first_glue[0] = False
        source = re.sub(r"\n{4,}", "\n\n\n", source).strip("\n")
    if BOOK_ONLY.search(source):
        raise ValueError(f"a code cell needs myst_nb or Sphinx: {source[:200]!r}")
    # A figure's caption is a Markdown cell under it (doctree.py); its options are the book's.
    metadata = {k: v for k, v in metadata.items() if k != "mystnb"}
    hidden = {k for tag in metadata.get("tags", []) for k in HIDDEN.get(tag, ())}
    if hidden:
        metadata.setdefault("jupyter", {}).update({k: True for k in sorted(hidden)})
    return nbformat.v4.new_code_cell(source, metadata=metadata)


def first_cell(title: str, page: str, edition: str, answers: bool, w: Words) -> str:
    """What a notebook says first: what it is, how to install what it needs if the import
    fails (the files beside it, bundle.py), and the licence of its text and figures."""
    name = bundle.TITLE_JA if w.language == "ja" else bundle.TITLE
    lines = [
        w.first.format(book=name, edition=w.edition[edition], title=title),
        w.install.format(pip=bundle.pip_magic(), readme=bundle.README),
    ]
    if answers:
        lines.append(w.answers_intro)
    lines.append(w.licence.format(page=page, cc_by=bundle.CC_BY))
    return "\n\n".join(lines)


def language_cells(w: Words) -> list[nbformat.NotebookNode]:
    """The code cell that sets a translated notebook's language, or none in English.

    The library writes its verdicts and figures in the language of the environment, read at
    each call, and translates the texts a cell passes it from the catalog the environment
    names (the book's catalog of its cells' texts, shipped beside the notebooks, bundle.py):
    the book's build sets both for each edition (book/_ext/kernels.py), and this cell does
    the same in the student's kernel, whatever the machine's locale.
    """
    if not w.language_cell:
        return []
    cell = nbformat.v4.new_code_cell(w.language_cell.format(catalog=bundle.CATALOG))
    cell.metadata["classroom"] = {"language": w.language}
    return [cell]


def _what(text: str, language: str) -> str:
    # A result's description, as the self-check names it in the notebook's language.
    if language == "en":
        return text
    from elliptic_pendulum.selfcheck import _ja

    found = _ja.MESSAGES.get(text)
    if found is None:
        raise ValueError(f"self-check text without a translation: {text[:80]!r}")
    return found


def answer_cells(label: str, w: Words) -> list[nbformat.NotebookNode]:
    """What a student gets under an exercise (after its folded hint, which the page has).

    For its results, a cell that names them and the self-check that reads them
    (elliptic_pendulum.selfcheck); for what it asks to prove or explain, a Markdown cell to
    write in. An exercise without a self-check gets one empty code cell.
    """
    exercise = selfcheck.EXERCISES.get(label)
    if exercise is None:
        return [nbformat.v4.new_code_cell("")]
    cells = []
    if exercise.values:
        names = w.result_separator.join(
            w.result_name.format(name=v.name, what=_what(v.what, w.language))
            for v in exercise.values)
        cells.append(nbformat.v4.new_markdown_cell(w.results.format(names=names)))
        cells.append(nbformat.v4.new_code_cell(
            "\n".join(w.placeholder.format(name=v.name) for v in exercise.values)))
        cells.extend(self_check_cells(label, w.language))
    if exercise.written is not None:
        cell = nbformat.v4.new_markdown_cell(w.answer)
        cell.metadata["classroom"] = {"written": label}
        cells.append(cell)
    if not exercise.values:  # for the computations a proof exercise may ask for too
        cells.append(nbformat.v4.new_code_cell(""))
    return cells


def self_check_cells(label: str, language: str = "en") -> list[nbformat.NotebookNode]:
    """The cell that runs the self-check of exercise ``label`` on the names of its results:
    under the student's answer cell, and under the instructor's solution (which it checks
    against the self-check's independent reference every time the notebook runs)."""
    exercise = selfcheck.EXERCISES.get(label)
    if exercise is None or not exercise.values:
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


def notebook(tree: Any, docname: str, edition: str, language: str, files: dict[str, str],
             numbers: dict[str, str], exercises: dict[str, str],
             sources: list[str] | None = None) -> nbformat.NotebookNode:
    """One page's resolved doctree as the notebook of one edition."""
    if edition not in EDITIONS:
        raise ValueError(f"edition must be one of {EDITIONS}, not {edition!r}")
    w = words(language)
    tree = tree.deepcopy()
    if edition == "student":
        doctree.remove_solutions(tree)
    first_glue = [True]
    page = doctree.Page(
        docname, edition, w, files, numbers, exercises=exercises, sources=sources or [],
        answer_cells=lambda label: answer_cells(label, w),
        check_cells=lambda label: self_check_cells(label, language),
        code_cell=lambda source, metadata: code_cell(source, metadata, first_glue),
    )
    cells = doctree.cells(tree, page)
    title = doctree.Writer(page).inline(tree.next_node(nodes.title)) or docname
    answers = any(c.metadata.get("classroom", {}).get("self_check") for c in cells
                  ) and edition == "student"
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_markdown_cell(first_cell(title, docname, edition, answers, w)),
                *language_cells(w), *cells]
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3",
                                 "language": "python"}
    nb.metadata["language_info"] = {"name": "python"}
    for i, c in enumerate(nb.cells):  # stable ids: a re-export changes no unchanged cell
        c["id"] = f"cell-{i}"
    return nb


def export(env: Any, builder: Any, out_dir: Path, editions: tuple[str, ...] = EDITIONS,
           language: str = "en") -> list[Path]:
    """Write out_dir/<edition>/NN-page.ipynb for every notebook page; return those changed.

    Each page's doctree is the one this build resolved for its HTML (read from the build's
    doctrees: nothing is parsed again, nothing executed).
    """
    words(language)  # an unknown language fails here, before anything is written
    files = notebook_files(env)
    exercises = _exercise_numbers(env)
    written = []
    for docname, name in files.items():
        tree = env.get_and_resolve_doctree(docname, builder)
        # The code cells' sources as myst-nb read them (their cell_index is into this list).
        text = Path(env.doc2path(docname)).read_text(encoding="utf-8")
        sources = [c.source for c in read_myst_markdown_notebook(text).cells]
        for edition in editions:
            nb = notebook(tree, docname, edition, language, files, _numbers(env, docname),
                          exercises, sources)
            target = out_dir / edition / name
            target.parent.mkdir(parents=True, exist_ok=True)
            text = nbformat.writes(nb) + "\n"
            # An unchanged notebook is left as it is (its bundle need not be made again).
            if not target.is_file() or target.read_text(encoding="utf-8") != text:
                target.write_text(text, encoding="utf-8")
                written.append(target)
    return written


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
