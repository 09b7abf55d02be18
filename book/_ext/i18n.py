"""Sphinx extension: the book's other editions, built from the English pages and gettext catalogs.

The English MyST pages are the only source of code, equations, figures and labels; a
translation is ``book/locale/<lang>/LC_MESSAGES/<page>.po`` (``sphinx-build -D language=ja``;
``make book-ja`` builds it into ``<site>/ja``, beside the English, running its cells in Japanese:
book/_ext/kernels.py).
What Sphinx, myst-parser and myst-nb do not do right for a translated notebook page is fixed
here:

* Cell outputs (verdict lines, sympy output, tables of numbers) and display math are not
  messages: both are the same in every language, a translated display equation is parsed as
  reST's ``::`` by Sphinx, and a translated output would go stale with every run. They are
  marked untranslatable before the gettext builder extracts and before Sphinx's Locale
  transform (priority 20) translates; figure captions and alt texts stay translatable.
* A translated message is parsed by myst-nb's parser without the page's notebook renderer,
  and every ``{glue}`` role in it fails ("No key ... found in glue data"): the page's renderer
  is lent to the parse of its messages.
* myst-parser stores each parsed message's heading slugs as the page's own, so a translated
  heading would overwrite the page's slug table and break every ``(#slug)`` link into it: the
  page's table is put back after each message. HTML ids stay the English slugs, so an anchor
  is the same in every edition (the language switch keeps it).
* The language switch on every page, to the same page in the other edition, with relative
  links (``file://`` and any server) and ``hreflang`` alternates
  (``_templates/language-switch.html``).
* Interface strings that the packages lack in Japanese: myst-nb's code-cell toggles, the
  theme's search box, sphinx-exercise's "Solution" (and its title order, "演習 3 の解答").
  Strings of our templates and of sphinx-exercise come from our own catalogs,
  ``locale/<lang>/LC_MESSAGES/sphinx.po`` and ``exercise.po``; those that Sphinx and the
  theme have in their own ja catalogs but leave empty (the permalinks' "Link to this
  heading", the colour switch) from ``locale/packages``; three of the theme's templates that
  write English without the catalogs (the sidebar toggles, the navigation's name) are ours,
  with ``_()``.
* The animation player's controls (matplotlib's ``to_jshtml``), which are interface inside
  an output: their titles and labels in the page's language.
* Each translated message is parsed as a document of its own, whose settings hold the whole
  build environment; the text nodes taken from it keep a reference to that document, so
  every pickled doctree carried a copy of the environment (10 MB a page instead of a few
  hundred kB, and a second to load each time a later build or the PDF reads it). The
  references are dropped once the page is read: a node without one asks its parent.
"""

from __future__ import annotations

import re
import shutil
from pathlib import Path
from typing import Any

from docutils import nodes
from myst_nb.sphinx_ import Parser as NbParser
from sphinx.application import Sphinx
from sphinx.config import Config
from sphinx.transforms import SphinxTransform
from sphinx.transforms.post_transforms import SphinxPostTransform

LOCALE = Path(__file__).resolve().parents[1] / "locale"
# Japanese for strings of Sphinx and the theme that their own catalogs leave empty, in the
# "sphinx" domain; added after theirs, so it fills only their gaps. Kept out of LOCALE's
# language folders: our sphinx.po there is the templates' catalog, which i18n-update merges.
PACKAGES = LOCALE / "packages"
# The editions and where each one's site lies, relative to the English site's root.
EDITIONS = {"en": ".", "ja": "ja"}
NAMES = {"en": "English", "ja": "日本語"}
# What the packages write in English, per language (myst-nb's toggles, the theme's search box,
# the book's title).
INTERFACE = {
    "ja": {
        "nb_code_prompt_show": "コードを表示",
        "nb_code_prompt_hide": "コードを隠す",
        "search_bar_text": "本書を検索…",
        "html_title": "単振り子と楕円関数",
    },
}


# Our own strings written from Python (the download menu of book/_ext/classroom.py), which no
# template catalog reaches.
LABELS = {
    "ja": {
        "notebook": "ノートブック",
        "all notebooks": "全ノートブック",
        "notebook (instructor)": "ノートブック（教員用）",
        "all notebooks (instructor)": "全ノートブック（教員用）",
        "Download this chapter as a Jupyter notebook (student edition)":
            "この章を Jupyter ノートブックとしてダウンロード（学生用）",
        "Download every chapter's student notebook (zip)":
            "全章の学生用ノートブックをダウンロード（zip）",
        "Download this chapter's notebook with its solutions (instructor edition)":
            "この章のノートブックを解答付きでダウンロード（教員用）",
        "Download every chapter's notebook with its solutions (zip)":
            "全章のノートブックを解答付きでダウンロード（zip）",
        "Download this page": "このページをダウンロード",
        # The home page's list of the site's parts (book/_ext/site_links.py).
        "The PDF of this edition": "この版の PDF",
        "The notebooks of this edition (zip)": "この版のノートブック（zip）",
        "The student edition (no solutions), to give to students":
            "学生用の版（解答なし）：学生に配布するもの",
        "The PDF of this edition, with the solutions": "この版の PDF（解答付き）",
        "The PDF of the student edition": "学生用の版の PDF",
        "The student notebooks (zip)": "学生用ノートブック（zip）",
        "The notebooks with their solutions (zip)": "解答付きノートブック（zip）",
        "The reference of the library": "ライブラリのリファレンス",
        "The English edition": "英語版（English edition）",
    },
}


# The controls of matplotlib's animation player (an output's HTML, Animation.to_jshtml):
# its button titles, aria labels and the labels of its repetition modes.
PLAYER = {
    "ja": {
        "Frame": "コマ", "Decrease speed": "遅くする", "First frame": "最初のコマ",
        "Previous frame": "前のコマ", "Play backwards": "逆再生", "Pause": "一時停止",
        "Play": "再生", "Next frame": "次のコマ", "Last frame": "最後のコマ",
        "Increase speed": "速くする", "Repetition mode": "繰り返し方",
        "Once": "1 回", "Loop": "ループ", "Reflect": "往復",
    },
}
_PLAYER_TEXT = re.compile(r'(?P<head>(?:title|aria-label)="|<label for="[^"]*">)(?P<text>[^"<]+)')


def label(language: str | None, text: str) -> str:
    """``text`` in ``language`` when LABELS has it, else as it is (English)."""
    return LABELS.get(language or "en", {}).get(text, text)


class _KeepRenderer(dict):
    """A document's attributes that remember the notebook renderer.

    myst-nb removes it at the end of a page's parse; the page's translated messages need it.
    """

    def __init__(self, attributes: dict[str, Any], keep: dict[str, Any], docname: str):
        super().__init__(attributes)
        self._keep, self._docname = keep, docname

    def pop(self, key: str, *default: Any) -> Any:
        value = super().pop(key, *default)
        if key == "nb_renderer":
            self._keep[self._docname] = value
        return value


class Parser(NbParser):
    """myst-nb's parser, lending a page's renderer and keeping its slugs for its messages."""

    renderers: dict[str, Any] = {}

    def parse(self, inputstring: str, document: nodes.document) -> None:
        """Parse a page, or one of its translated messages with the page's renderer."""
        env = getattr(document.settings, "env", None) or self.env
        docname = env.docname
        if not str(document.current_source or "").endswith("<translated>"):
            # Only the page being read: its messages are parsed next, by Locale.
            self.renderers.clear()
            document.attributes = _KeepRenderer(document.attributes, self.renderers, docname)
            try:
                super().parse(inputstring, document)
            finally:  # a plain dict again, which pickles with the doctree
                document.attributes = dict(document.attributes)
            return
        metadata = env.metadata[docname]
        slugs = metadata.get("myst_slugs")
        renderer = self.renderers.get(docname)
        if renderer is not None:
            document.attributes["nb_renderer"] = renderer
        try:
            super().parse(inputstring, document)
        finally:
            document.attributes.pop("nb_renderer", None)
            if slugs is None:
                metadata.pop("myst_slugs", None)
            else:
                metadata["myst_slugs"] = slugs


class Untranslatable(SphinxTransform):
    """Display math and cell outputs are no messages (see the module's docstring)."""

    default_priority = 15  # before Locale (20), and run by the gettext builder too

    def apply(self, **kwargs: Any) -> None:
        """Mark display math and the text of cell outputs (captions aside) untranslatable."""
        for math in self.document.findall(nodes.math_block):
            math["translatable"] = False
        for output in self.document.findall(nodes.container):
            if "cell_output" not in output.get("classes", []):
                continue
            for node in output.findall(nodes.TextElement):
                # Inline nodes are never messages, and Sphinx's RemoveTranslatableInline
                # unwraps every inline that has the key at all (a link would lose its text).
                if not isinstance(node, nodes.Inline) and not _in_caption(node, output):
                    node["translatable"] = False


def _in_caption(node: nodes.Node, top: nodes.Node) -> bool:
    while node is not None and node is not top:
        if isinstance(node, (nodes.caption, nodes.legend)):
            return True
        node = node.parent
    return False


class SolutionTitle(SphinxPostTransform):
    """A solution's title in Japanese order: 演習 3 の解答.

    sphinx-exercise writes "Solution to" followed by the exercise's title, an order fixed in
    its code.
    """

    default_priority = 999  # after sphinx-exercise's own title post-transform

    def run(self, **kwargs: Any) -> None:
        """Move 解答 behind the exercise's title, as の解答."""
        if self.config.language != "ja":
            return
        for title in self.document.findall(nodes.title):
            parent = title.parent
            if "solution" not in parent.get("classes", []):
                continue
            text = title.children[0] if title.children else None
            if isinstance(text, nodes.Text) and str(text).startswith("解答"):
                title.remove(text)
                title.append(nodes.Text(" の解答"))
                first = title.children[0]
                if isinstance(first, nodes.Text):
                    title.replace(first, nodes.Text(str(first).lstrip()))
                elif isinstance(first, nodes.Element) and first.children and isinstance(
                    first.children[0], nodes.Text
                ):
                    first.replace(first.children[0], nodes.Text(str(first.children[0]).lstrip()))


class PlayerControls(SphinxPostTransform):
    """The animation player's controls in the page's language.

    They are interface, not a result: the frames, the numbers of the output, stay as run.
    """

    default_priority = 999

    def run(self, **kwargs: Any) -> None:
        """Rewrite the controls of each animation output."""
        words = PLAYER.get(self.config.language or "en")
        if not words:
            return
        for raw in list(self.document.findall(nodes.raw)):
            text = raw.astext()
            if "anim-controls" not in text:
                continue
            new = _PLAYER_TEXT.sub(
                lambda m: m["head"] + words.get(m["text"], m["text"]), text)
            raw.replace_self(nodes.raw("", new, format=raw.get("format", "html")))


def _configure(app: Sphinx, config: Config) -> None:
    for name, value in INTERFACE.get(config.language, {}).items():
        if name == "search_bar_text":
            config.html_theme_options = {**config.html_theme_options, name: value}
        else:
            setattr(config, name, value)


def _language_links(
    app: Sphinx, pagename: str, templatename: str, context: dict[str, Any], doctree: Any
) -> None:
    """``language_links``: (language, name, href) of every edition of this page, relative."""
    here = app.config.language if app.config.language in EDITIONS else "en"
    up = "../" * pagename.count("/")
    root = "../" if EDITIONS[here] != "." else ""  # from this edition's root to the English
    links = []
    for lang, folder in EDITIONS.items():
        prefix = root + ("" if folder == "." else folder + "/")
        links.append((lang, NAMES[lang], f"{up}{prefix}{pagename}.html"))
    context["language_links"] = links
    context["page_language"] = here
    context["metatags"] = context.get("metatags", "") + "".join(
        f'\n<link rel="alternate" hreflang="{lang}" href="{href}" />'
        for lang, _, href in links
    )


def _compile_own_catalogs(language: str) -> None:
    """Compile our catalogs of other packages' strings to the .mo files gettext reads.

    exercise.po, and packages/'s sphinx.po. Sphinx compiles only the pages' catalogs, and
    later than extensions load theirs.
    """
    from babel.messages.mofile import write_mo
    from babel.messages.pofile import read_po

    folder = LOCALE / language / "LC_MESSAGES"
    packages = PACKAGES / language / "LC_MESSAGES"
    for po in [*folder.glob("exercise.po"), *packages.glob("sphinx.po")]:
        mo = po.with_suffix(".mo")
        if not mo.exists() or mo.stat().st_mtime < po.stat().st_mtime:
            with po.open("rb") as src:
                catalog = read_po(src, locale=language)
            with mo.open("wb") as out:
                write_mo(out, catalog)


def _drop_executed_notebooks(app: Sphinx, exception: BaseException | None) -> None:
    """Remove the executed notebooks an edition inside the English site wrote into it.

    myst-nb writes them to ``<outdir>/../jupyter_execute``: for an edition built inside the
    English site's folder that is inside the site, and the student site's would hold every
    solution (its pages execute whole). The classroom export (book/_ext/classroom.py, at the
    default priority) has read them by then.
    """
    if app.config.language in (None, "", "en"):
        return
    folder = Path(app.outdir).parent / "jupyter_execute"
    if folder.is_dir() and (Path(app.outdir).parent / "index.html").exists():
        shutil.rmtree(folder)


def _forget_message_documents(app: Sphinx, doctree: nodes.document) -> None:
    """Drop the nodes' references to their translated messages' own documents.

    See the module's docstring; ``node.document`` then finds the page's own.
    """
    for node in doctree.findall():
        if vars(node).get("_document") not in (None, doctree):
            node._document = None


def setup(app: Sphinx) -> dict[str, Any]:
    """Register the parser, transforms and hooks.

    Loaded before sphinx-exercise (book/conf.py), so that our exercise catalog is read first.
    """
    app.add_source_parser(Parser, override=True)
    app.add_transform(Untranslatable)
    app.add_post_transform(SolutionTitle)
    app.add_post_transform(PlayerControls)
    if app.config.language and app.config.language != "en":
        _compile_own_catalogs(app.config.language)
        app.add_message_catalog("exercise", str(LOCALE))
        app.add_message_catalog("sphinx", str(PACKAGES))
    app.connect("config-inited", _configure)
    app.connect("html-page-context", _language_links)
    app.connect("doctree-read", _forget_message_documents)
    app.connect("build-finished", _drop_executed_notebooks, priority=900)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
