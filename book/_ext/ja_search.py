"""Sphinx extension: the HTML search of the Japanese edition finds Japanese words.

Japanese is written without spaces. Sphinx's indexer for ``ja`` (``SearchJapanese``) cuts the
text into words with the Python port of TinySegmenter, but the search page cuts a query only at
non-letters (the default ``splitQuery`` of ``searchtools.js``), so a query such as 楕円関数 stays
one term, while the index holds 楕円 and 関数: nothing is found. This extension registers a
``ja`` search language whose ``splitQuery`` runs TinySegmenter in JavaScript on the query, so
the query is cut into the words the index holds.

``vendor/tiny_segmenter.js`` is ``lib/index.js`` of the npm package ``tiny-segmenter`` 0.2.0,
byte for byte (TinySegmenter 0.2, (c) 2008 Taku Kudo, new BSD licence, as its header says);
``vendor/tiny_segmenter.LICENSE`` is that package's own licence file (MIT, for the npm
packaging). It is not in ``static/``, which classroom.py adds to every build's static files:
the page gets the segmenter only inside ``language_data.js``, and only in Japanese.

The segmenter's model tables are those of the Python port in ``sphinx.search.ja``; the two
differ only in what the wrapper below corrects, so that the query is cut as the text was:

* the Python port scores the third unigram-with-previous-tag feature with the table ``UQ1``
  where the JavaScript original uses ``UQ3``; the index was built with the Python port, so the
  JavaScript one is given the Python port's table;
* the Python port steps through code points, the JavaScript one through UTF-16 units (a
  character outside the BMP, such as 𠮷, would be two);
* the Python port strips white space from each word, and the index keeps only words of more
  than one character (``SearchJapanese.word_filter``; there are no Japanese stopwords and no
  stemming); a query term the index cannot hold would only make the search find nothing.

Lowercasing stays with ``searchtools.js``: it lowercases after ``splitQuery``, as the indexer
lowercases after splitting (and it drops terms that are only digits, as for every language).

The JavaScript cuts as the default splitter does: a build that sets ``html_search_options``
``{"type": ...}`` to MeCab or Janome indexes with that one, and its queries would not match.

Only the ``ja`` search language is registered: a build in another language gets Sphinx's own
language data. The registration lives in Sphinx's table of languages for the whole process,
which is what ``app.add_search_language`` does.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from sphinx.application import Sphinx
from sphinx.search.ja import SearchJapanese

TINY_SEGMENTER_JS = Path(__file__).resolve().parent / "vendor" / "tiny_segmenter.js"

# The package file ends in ``module.exports = TinySegmenter;`` (CommonJS): a local ``module``
# takes it, and only ``splitQuery`` reaches the page's global scope, as a ``var`` so that the
# ``typeof splitQuery === "undefined"`` test of searchtools.js sees it.
_WRAPPER = """\
var splitQuery = (() => {{
  const TinySegmenter = (() => {{
    const module = {{ exports: {{}} }};
{segmenter}
    return module.exports;
  }})();
  const segmenter = new TinySegmenter();
  segmenter.UQ3__ = segmenter.UQ1__;
  return (query) => {{
    const codePoints = Array.from(query);
    const text = Object.assign(new String(query), {{ split: () => codePoints }});
    return segmenter
      .segment(text)
      .map((word) => word.trim())
      .filter((word) => Array.from(word.toLowerCase()).length > 1);
  }};
}})();
"""


def splitter_code() -> str:
    """Return the JavaScript of ``splitQuery``, with the vendored TinySegmenter inside it."""
    return _WRAPPER.format(segmenter=TINY_SEGMENTER_JS.read_text(encoding="utf-8").rstrip())


class SearchJapaneseQuery(SearchJapanese):
    """``SearchJapanese`` whose search page cuts the query as the indexer cut the text."""

    js_splitter_code = splitter_code()


def setup(app: Sphinx) -> dict[str, Any]:
    """Register the ``ja`` search language."""
    app.add_search_language(SearchJapaneseQuery)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
