"""Sphinx extension: the classroom editions inside the book build, and the student book.

- ``build-finished`` (html builder): tools/classroom/export.py writes the notebooks into
  ``<outdir>/classroom/<edition>/NN-page.ipynb`` from the doctrees this build resolved for
  the pages (tools/classroom/doctree.py), so a notebook's text is the page's, with its
  numbers, links and glued values, in the build's language; then it adds what a student
  needs to run them (tools/classroom/bundle.py: the package's wheel, built from this
  repository, ``requirements.txt`` and a README on installing them) and zips each edition
  as ``classroom/<name>-<edition>.zip``.
- ``html-page-context``: each chapter page's download menu (sphinx-book-theme) offers the
  page's student notebook and the student zip, and in the instructor site (the default
  build) the instructor notebook and zip too, as relative links into the build: they work
  offline. Every page knows its edition (``classroom_edition``: the footer says that the
  instructor site, which holds the solutions, is for the teacher to keep private).
- ``-D hide_solutions=1`` (the student book, ``make book-student``; also
  ``-D classroom_edition=student``): sphinx-exercise's own option crashes the HTML writer
  (``departing unknown node type: solution_end_node``) and would leave a gated solution's text
  and cells in the page, so this extension takes the option over at ``config-inited``. The
  page is read and executed whole, exactly as in the instructor site, so both sites (and the
  PDFs) share one execution cache and each notebook runs once; the solutions are removed from
  the doctree at ``doctree-read`` (sphinx-exercise has merged each gated solution into one
  node by then), before anything is indexed or written; the instructor site's student
  notebooks are written from trees the same function stripped. The student site copies no
  page source (``html_copy_source``), and exports only the student edition: no file of the
  student site holds a solution (tests/book/test_site.py searches them all). The pages for
  the teacher alone
  (``INSTRUCTOR_ONLY``: the teacher's guide) are left out of the student site, with their
  toctree entries.
- ``source-read``, both sites: under each exercise, a folded hint (elliptic_pendulum.selfcheck:
  the hint for the parts to prove, and the results the chapter's notebook checks).
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

from docutils import nodes
from i18n import label
from sphinx.application import Sphinx
from sphinx.config import Config
from sphinx.errors import ConfigError
from sphinx.util import logging

from elliptic_pendulum import selfcheck
from tools.classroom import bundle, doctree
from tools.classroom import export as export_notebooks

logger = logging.getLogger(__name__)
# Pages for the teacher only: left out of the student site, their toctree entries with them.
INSTRUCTOR_ONLY = ("teachers_guide",)
_ENTRY = re.compile(r"^[ \t]*(" + "|".join(INSTRUCTOR_ONLY) + r")(\.md)?[ \t]*\n", re.M)
FOLDER = "classroom"
ZIP_NAME = bundle.ZIP_NAME


def _student(app: Sphinx) -> bool:
    return bool(app.config.classroom_edition == "student")


def _editions(app: Sphinx) -> tuple[str, ...]:
    return ("student",) if _student(app) else export_notebooks.EDITIONS


def _take_over_hide_solutions(app: Sphinx, config: Config) -> None:
    # sphinx-exercise must never see its own switch on (see the module docstring).
    if config.hide_solutions:
        config.classroom_edition = "student"
        config.hide_solutions = False
    if config.classroom_edition == "student":
        config.exclude_patterns = [*config.exclude_patterns,
                                   *(f"{page}.md" for page in INSTRUCTOR_ONLY)]
        # The pages' sources hold the solutions: the student site copies none (its download
        # menu offers the notebook, written from the page without them, and the PDF).
        config.html_copy_source = False
    if config.classroom_edition not in ("instructor", "student"):
        raise ConfigError(
            f"classroom_edition must be 'instructor' or 'student', not {config.classroom_edition!r}"
        )


def _drop_instructor_pages(app: Sphinx, docname: str, source: list[str]) -> None:
    if _student(app):
        source[0] = _ENTRY.sub("", source[0])


_EXERCISE = re.compile(
    r"^(?P<fence>:{3,})\{exercise\}[^\n]*\n:label: (?P<label>\S+)\n.*?^(?P=fence)[ \t]*\n",
    re.M | re.S)


def hint_block(label: str) -> str:
    """Return the folded hint under an exercise, in both sites.

    The hint of its self-check for the parts to prove, and which results the chapter's
    notebook checks.
    """
    exercise = selfcheck.EXERCISES.get(label)
    if exercise is None:
        return ""
    lines = []
    if exercise.written is not None:
        lines.append(exercise.written)
    if exercise.values:
        # Separated by semicolons: "P30, short30, one_percent" is a solution's own line.
        names = "; ".join(f"`{v.name}`" for v in exercise.values)
        lines.append(f"In this chapter's notebook, the cell under the exercise checks your "
                     f"results ({names}) and says what to look at if one is not right yet.")
    body = "\n\n".join(lines)
    return f"\n::::{{admonition}} Hint\n:class: dropdown hint\n\n{body}\n::::\n"


def _hints(app: Sphinx, docname: str, source: list[str]) -> None:
    # In the page text only (jupyter-cache keys on code cells: nothing runs again); the
    # notebooks get the same hint from the exporter, as a cell.
    source[0] = _EXERCISE.sub(lambda m: m[0] + hint_block(m["label"]), source[0])


def _remove_solutions(app: Sphinx, tree: nodes.document) -> None:
    # Before sphinx-exercise's own doctree-read (priority 500) registers the solutions'
    # labels, so nothing in the student site can refer to one. The student notebooks of the
    # instructor site are written from trees that the same function stripped.
    if _student(app):
        doctree.remove_solutions(tree)


def _download_buttons(
    app: Sphinx, pagename: str, templatename: str, context: dict[str, Any], doctree: Any
) -> None:
    if app.builder.name != "html":
        return
    if not app.config.html_copy_source:
        # The theme offers the page's source whether or not Sphinx copied it: a site that
        # copies none (the student site) offers none.
        for group in context.get("header_buttons", []):
            if group.get("label") == "download-buttons":
                group["buttons"] = [b for b in group["buttons"] if b.get("label") not in (
                    "download-source-button", "download-notebook-button")]
    files = export_notebooks.notebook_files(app.env)
    if pagename not in files:
        return
    up = "../" * pagename.count("/")

    def t(text: str) -> str:  # the menu in the edition's language (book/_ext/i18n.py)
        return label(app.config.language, text)

    buttons = [
        {"type": "link", "url": f"{up}{FOLDER}/student/{files[pagename]}",
         "text": t("notebook"), "icon": "fas fa-book-open",
         "tooltip": t("Download this chapter as a Jupyter notebook (student edition)"),
         "label": "download-student-notebook-button"},
        {"type": "link", "url": f"{up}{FOLDER}/{ZIP_NAME}-student.zip",
         "text": t("all notebooks"), "icon": "fas fa-file-archive",
         "tooltip": t("Download every chapter's student notebook (zip)"),
         "label": "download-student-zip-button"},
    ]
    if "instructor" in _editions(app):
        buttons += [
            {"type": "link", "url": f"{up}{FOLDER}/instructor/{files[pagename]}",
             "text": t("notebook (instructor)"), "icon": "fas fa-book",
             "tooltip": t("Download this chapter's notebook with its solutions (instructor "
                          "edition)"),
             "label": "download-instructor-notebook-button"},
            {"type": "link", "url": f"{up}{FOLDER}/{ZIP_NAME}-instructor.zip",
             "text": t("all notebooks (instructor)"), "icon": "fas fa-file-archive",
             "tooltip": t("Download every chapter's notebook with its solutions (zip)"),
             "label": "download-instructor-zip-button"},
        ]
    for group in context.get("header_buttons", []):
        if group.get("label") == "download-buttons":
            group["buttons"][:0] = buttons
            break
    else:
        context.setdefault("header_buttons", []).append(
            {"type": "group", "tooltip": t("Download this page"), "icon": "fas fa-download",
             "buttons": buttons, "label": "download-buttons"}
        )


def _edition(
    app: Sphinx, pagename: str, templatename: str, context: dict[str, Any], doctree: Any
) -> None:
    context["classroom_edition"] = app.config.classroom_edition


def _export(app: Sphinx, exception: BaseException | None) -> None:
    if exception is not None or app.builder.name != "html":
        return
    out = Path(app.outdir) / FOLDER
    editions = _editions(app)
    try:
        changed = export_notebooks.export(app.env, app.builder, out, editions, _language(app))
    except ValueError as err:  # a page the notebooks cannot hold: say which, and why
        logger.warning(f"classroom notebooks not exported: {err}", type="classroom")
        return
    if not changed and not _bundles_stale(out, editions, _language(app)):
        return  # the same notebooks and package as the bundles hold: nothing to make again
    try:
        bundle.bundle_editions(out, editions, language=_language(app))
    except RuntimeError as err:  # the wheel did not build: pip's output says why
        logger.warning(f"classroom bundles not made: {err}", type="classroom")
        return
    logger.info(f"classroom notebooks ({', '.join(editions)}) in {out}")


def _bundles_stale(out: Path, editions: tuple[str, ...], language: str) -> bool:
    # A zip missing, or older than a file of the package whose wheel it holds, or than the
    # catalog of the cells' texts that a translated edition's zip holds.
    package = Path(bundle.ROOT) / "src" / "elliptic_pendulum"
    sources = [*package.rglob("*.py")]
    if language != "en":
        sources.append(bundle.catalog_source(language))
    newest = max(p.stat().st_mtime for p in sources)
    zips = [out / f"{ZIP_NAME}-{edition}.zip" for edition in editions]
    return any(not z.is_file() or z.stat().st_mtime < newest for z in zips)


def _language(app: Sphinx) -> str:
    # The edition's notebooks in its own language: the doctrees of a translated build hold
    # the translation already; the writer's own words (words.py) follow it.
    return str(app.config.language or "en")


def _builder_inited(app: Sphinx) -> None:
    app.config.html_static_path.append(str(Path(__file__).parent / "static"))
    # Sphinx falls back to a builder's format ("html") for node visitors only when no
    # extension registered visitors under the builder's own name. Some register for
    # "singlehtml", and then myst-nb's HideCodeCellNode (html only) has none there: copy them.
    handlers = app.registry.translation_handlers
    if app.builder.name == "singlehtml":  # the page that tools/pdf prints
        # Equation numbers (\tag) are MathJax text: in the page's font they are real text
        # in the PDF (searchable, and what tests/book/test_pdf.py reads), not glyph drawings.
        config = dict(app.config.mathjax3_config or {})
        config["chtml"] = {**config.get("chtml", {}), "mtextInheritFont": True}
        app.config.mathjax3_config = config
        # The single page writes no search index (Sphinx's singlehtml has no search page),
        # but would still feed every word to the indexer: for the Japanese edition a
        # segmenter run on the whole book, ten seconds of nothing.
        app.builder.search = False  # type: ignore[attr-defined]
    if app.builder.name != "html" and app.builder.format == "html":
        own = handlers.setdefault(app.builder.name, {})
        for node, visitors in handlers.get("html", {}).items():
            own.setdefault(node, visitors)


def setup(app: Sphinx) -> dict[str, Any]:
    """Register the classroom hooks."""
    app.connect("builder-inited", _builder_inited)
    # Printing (Chromium's PDF or a reader's Ctrl-P): no navigation, outputs wrapped.
    app.add_css_file("classroom_print.css", media="print")
    app.add_config_value("classroom_edition", "instructor", "env", types=[str])
    app.connect("config-inited", _take_over_hide_solutions)
    app.connect("source-read", _drop_instructor_pages)
    app.connect("source-read", _hints)
    app.connect("doctree-read", _remove_solutions, priority=400)
    # After sphinx-book-theme builds its header buttons (priority 501).
    app.connect("html-page-context", _download_buttons, priority=510)
    app.connect("html-page-context", _edition)
    app.connect("build-finished", _export)
    return {"version": "1.0", "parallel_read_safe": True, "parallel_write_safe": True}
