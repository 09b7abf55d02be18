"""The search page of a Japanese build cuts a query into the words of the search index.

book/_ext/ja_search.py gives the ``ja`` search language a JavaScript ``splitQuery`` built on
TinySegmenter. A tiny Sphinx project (three reST pages, ``language = "ja"``, no other
extension) is built with ``-W`` in a temporary folder, then the built ``_static`` files run in
node: ``language_data.js`` and ``searchtools.js`` with stubs for the browser (``window``,
``_ready``, ``localStorage``), and ``searchindex.js``, which hands the index to ``Search``. The
query goes through ``Search._parseQuery`` and ``Search.performTermsSearch``, the functions the
search page calls, so what is checked is what a reader's query finds.

Where the expectations come from: the index is written by Sphinx's own Python indexer
(``sphinx.search.ja``, the Python port of TinySegmenter, then lowercased and filtered by
``SearchJapanese.word_filter``), independently of the JavaScript under test. So:

* the queries, cut by the JavaScript, give terms of the built ``searchindex.js``, and those
  terms (and the search) lead to the page that has the phrase, not to the page that has not;
* on sentences of the kind the book has (kanji, kana, katakana, ASCII symbols and formulas), the
  JavaScript cuts exactly as the Python indexer does, word for word;
* the check can fail: with Sphinx's stock ``splitQuery`` (cut at non-letters only), 楕円関数
  stays one term that the index does not hold, and the search finds nothing; the vendored
  TinySegmenter left with its own UQ3 table cuts the sentences with formulas otherwise than
  the indexer (and the sentences with characters outside the BMP fail if the wrapper hands
  it UTF-16 units).

An English build with the extension gets the same ``language_data.js`` and ``searchtools.js``
as one without it.

The test takes a few seconds (three small builds, node runs): part of the quick tier.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
from sphinx.search.ja import SearchJapanese

EXT = Path(__file__).resolve().parents[2] / "book" / "_ext"

CONF = f"""\
import sys
sys.path.insert(0, {str(EXT)!r})
project = "search"
language = "ja"
extensions = ["ja_search"]
"""

PAGES = {
    "index": "目次\n====\n\n.. toctree::\n\n   period\n   other\n",
    "period": (
        "第一章\n======\n\n"
        "この章では楕円関数の周期を求める。"
        "単振り子の運動は、振幅が大きいと調和振動から外れる。\n"
    ),
    "other": "第二章\n======\n\nこの本の使い方を説明します。図と表を見てください。\n",
}

# Query -> the only page it must find.
QUERIES = {
    "楕円関数": "period",
    "楕円関数の周期": "period",
    "周期を求める": "period",
    "単振り子の運動": "period",
    "調和振動": "period",
}

# Sentences of the kind a physics textbook has, with ASCII symbols and formulas among them;
# eight of them are cut otherwise by the JavaScript TinySegmenter left with its UQ3 table.
SENTENCES = [
    "楕円関数の周期を求める。",
    "単振り子の運動を考える。",
    "θ(t) の周期 T は K(k) で表される。",
    "振幅が小さいとき、周期は 2π√(L/g) に近づく。",
    "第一種完全楕円積分 K(k) は k → 1 で発散する。",
    "エネルギー保存則から角速度が求まる。",
    "重力加速度 g = 9.81 m/s² とする。",
    "減衰がない場合、力学的エネルギーは一定である。",
    "セパラトリクスの上では振り子は無限の時間をかけて倒立点に近づく。",
    "数値積分にはルンゲ＝クッタ法を用いた。",
    "図3に位相空間の軌道を示す。",
    "ヤコビの楕円関数 sn(u, k) を使うと解が閉じた形で書ける。",
    "糸の長さ L を 1.0 m とし、初期角度を 60° とする。",
    "回転運動と秤動の境目では周期が対数的に発散する。",
    "Python の scipy.special.ellipk で K(m) を計算できる。",
    # Characters outside the BMP (two UTF-16 units in JavaScript, one code point in Python).
    "𠮷田さんが振り子の周期を測った。",
    "𝜃(𝑡) の周期を求める。",
]

NODE_HARNESS = r"""
const fs = require("fs");
const path = require("path");
const vm = require("vm");
const [staticDir, indexFile, mode] = process.argv.slice(1);
const read = (name) => fs.readFileSync(path.join(staticDir, name), "utf8");
const context = {
  window: {},
  _ready: () => {},
  localStorage: { setItem: () => {} },
  SPHINX_HIGHLIGHT_ENABLED: false,
};
vm.createContext(context);
if (mode === "stock") {
  // What language_data.js of a stock Sphinx "ja" build holds: no stopwords, no stemming,
  // no splitQuery, so searchtools.js defines its default one.
  vm.runInContext(
    "const stopwords = new Set(); var Stemmer = function () { this.stemWord = (w) => w; };",
    context,
  );
} else {
  vm.runInContext(read("language_data.js"), context);
}
vm.runInContext(read("searchtools.js"), context);
vm.runInContext(fs.readFileSync(indexFile, "utf8"), context);
const run = vm.runInContext(`(query) => {
  const [, searchTerms, excluded] = Search._parseQuery(query);
  return {
    split: splitQuery(query),
    terms: [...searchTerms],
    found: Search.performTermsSearch(searchTerms, excluded).map((result) => result[0]),
  };
}`, context);
const queries = JSON.parse(fs.readFileSync(0, "utf8"));
process.stdout.write(JSON.stringify(queries.map(run)));
"""

# The vendored segmenter with the wrapper's strip and filter but with its own UQ3 table.
RAW_SEGMENTER = r"""
const TinySegmenter = require(process.argv[1]);
const segmenter = new TinySegmenter();
const words = (s) =>
  segmenter
    .segment(s)
    .map((word) => word.trim())
    .filter((word) => Array.from(word.toLowerCase()).length > 1);
const sentences = JSON.parse(require("fs").readFileSync(0, "utf8"));
process.stdout.write(JSON.stringify(sentences.map(words)));
"""


def reference_words(text: str) -> list[str]:
    """The words the Python indexer puts in the index for ``text``, in order (IndexBuilder.feed:
    split, lowercase, keep what ``word_filter`` keeps)."""
    language = SearchJapanese({})
    words = (word.lower() for word in language.split(text))
    return [word for word in words if language.word_filter(word)]


@pytest.fixture(scope="module")
def node() -> str:
    found = shutil.which("node")
    if found is None:
        if os.environ.get("CI", "").lower() == "true":
            pytest.fail("node is missing; CI must run the Japanese search check", pytrace=False)
        pytest.skip("node is missing")
    return found


def build(srcdir: Path, outdir: Path, *options: str) -> Path:
    subprocess.run(
        [sys.executable, "-m", "sphinx", "-W", "-q", "-b", "html", *options, srcdir, outdir],
        check=True,
        timeout=120,
    )
    return outdir


@pytest.fixture(scope="module")
def project(tmp_path_factory: pytest.TempPathFactory) -> Path:
    srcdir = tmp_path_factory.mktemp("ja_search_src")
    (srcdir / "conf.py").write_text(CONF, encoding="utf-8")
    for name, text in PAGES.items():
        (srcdir / f"{name}.rst").write_text(text, encoding="utf-8")
    return srcdir


@pytest.fixture(scope="module")
def site(project: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    return build(project, tmp_path_factory.mktemp("ja_search_html"))


def search_index(site: Path) -> dict[str, Any]:
    text = (site / "searchindex.js").read_text(encoding="utf-8").strip()
    prefix, suffix = "Search.setIndex(", ")"
    assert text.startswith(prefix) and text.endswith(suffix), text[:80]
    return json.loads(text[len(prefix) : -len(suffix)])


def pages_of(index: dict[str, Any], term: str) -> set[str]:
    """The pages whose text or title holds ``term``."""
    found: set[str] = set()
    for table in ("terms", "titleterms"):
        files = index[table].get(term)
        if files is not None:
            found |= {index["docnames"][i] for i in ([files] if isinstance(files, int) else files)}
    return found


def search(node: str, site: Path, queries: list[str], mode: str = "ja_search") -> list[dict]:
    result = subprocess.run(
        [node, "-e", NODE_HARNESS, "--", site / "_static", site / "searchindex.js", mode],
        input=json.dumps(queries),
        capture_output=True,
        text=True,
        check=True,
        timeout=60,
    )
    return json.loads(result.stdout)


def test_the_page_uses_the_extension_splitter(site: Path) -> None:
    language_data = (site / "_static" / "language_data.js").read_text(encoding="utf-8")
    assert "function TinySegmenter()" in language_data
    assert "var splitQuery" in language_data


def test_queries_find_the_page_with_the_phrase(node: str, site: Path) -> None:
    index = search_index(site)
    results = search(node, site, list(QUERIES))
    assert results[0]["terms"] == ["楕円", "関数"], results[0]
    for (query, page), result in zip(QUERIES.items(), results, strict=True):
        for term in result["terms"]:
            assert pages_of(index, term) == {page}, (query, term, pages_of(index, term))
        assert result["found"] == [page], (query, result)


def test_javascript_cuts_as_the_python_indexer(node: str, site: Path) -> None:
    results = search(node, site, SENTENCES)
    differing = {
        sentence: ([word.lower() for word in result["split"]], reference_words(sentence))
        for sentence, result in zip(SENTENCES, results, strict=True)
        if [word.lower() for word in result["split"]] != reference_words(sentence)
    }
    assert not differing, f"{len(SENTENCES) - len(differing)}/{len(SENTENCES)} agree: {differing}"


def test_stock_splitter_finds_nothing(node: str, site: Path) -> None:
    index = search_index(site)
    [result] = search(node, site, ["楕円関数"], mode="stock")
    assert result["terms"] == ["楕円関数"]
    assert pages_of(index, "楕円関数") == set()
    assert result["found"] == []
    assert pages_of(index, "楕円") == pages_of(index, "関数") == {"period"}


def test_tiny_segmenter_without_the_uq3_table_disagrees(node: str) -> None:
    # JavaScript TinySegmenter scores with its UQ3 table where Sphinx's Python port reuses UQ1;
    # left so, it cuts the sentences with ASCII symbols otherwise than the indexer: the
    # comparison above has something to find.
    result = subprocess.run(
        [node, "-e", RAW_SEGMENTER, "--", EXT / "vendor" / "tiny_segmenter.js"],
        input=json.dumps(SENTENCES),
        capture_output=True,
        text=True,
        check=True,
        timeout=60,
    )
    raw = json.loads(result.stdout)
    differing = [
        sentence
        for sentence, words in zip(SENTENCES, raw, strict=True)
        if [word.lower() for word in words] != reference_words(sentence)
    ]
    assert "θ(t) の周期 T は K(k) で表される。" in differing, differing


def test_english_build_keeps_the_stock_language_data(
    project: Path, tmp_path_factory: pytest.TempPathFactory
) -> None:
    stock = tmp_path_factory.mktemp("en_stock_src")
    shutil.copytree(project, stock, dirs_exist_ok=True)
    conf = CONF.replace('extensions = ["ja_search"]', "extensions = []")
    assert conf != CONF
    (stock / "conf.py").write_text(conf, encoding="utf-8")
    with_extension = build(project, tmp_path_factory.mktemp("en_html"), "-D", "language=en")
    without = build(stock, tmp_path_factory.mktemp("en_stock_html"), "-D", "language=en")
    for name in ("language_data.js", "searchtools.js"):
        built = (with_extension / "_static" / name).read_text(encoding="utf-8")
        assert built == (without / "_static" / name).read_text(encoding="utf-8"), name
    assert "TinySegmenter" not in (with_extension / "_static" / "language_data.js").read_text(
        encoding="utf-8"
    )
