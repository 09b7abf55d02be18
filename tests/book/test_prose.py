"""The measure of a chapter's thread (tests/book/prose.py), on pages whose answer is known
by construction: it counts what a reader sees, and only that."""

from __future__ import annotations

from pathlib import Path

from tests.book import prose

PAGE = """<html><body><nav>The check of the sidebar.</nav>
<article class="bd-article">
<h1>The swing</h1>
<p>The pendulum swings with the period <span class="math">\\(4K_1/\\omega_0\\)</span>, longer
than the small-angle one. The period grows without bound near the top.</p>
<p>SEEN The cell below checks the period against sympy.</p>
<div class="check-mark margin"><details><summary>✔ checked: (26)</summary>
<p>The check compares it with a quadrature; its mutant is rejected.</p></details></div>
<details class="hide"><summary>Show code</summary><p>The residual is small.</p></details>
<div class="cell_output"><p>✔ (26) holds: max residual 1e-16.</p></div>
<pre>assert period &gt; 0  # check</pre>
</article></body></html>
"""


def read(tmp_path: Path, text: str) -> prose.Prose:
    page = tmp_path / "page.html"
    page.write_text(text, encoding="utf-8")
    return prose.read(page)


def test_only_the_visible_thread_is_read(tmp_path: Path) -> None:
    text = read(tmp_path, PAGE)
    # Three sentences of the thread; the formula is one placeholder word inside the first.
    assert text.sentences == [
        "The pendulum swings with the period x , longer than the small-angle one.",
        "The period grows without bound near the top.",
        "SEEN The cell below checks the period against sympy.",
    ]
    assert text.machinery == ["SEEN The cell below checks the period against sympy."]
    assert round(text.share, 3) == round(1 / 3, 3)


def test_folds_margins_outputs_and_code_are_not_read(tmp_path: Path) -> None:
    text = read(tmp_path, PAGE.replace("SEEN The cell below checks the period against sympy.",
                                       "The swing is slower."))
    assert text.machinery == [] and text.share == 0
    # "The swing" (2), the paragraph (12 + 8 words, the formula one of them), and "The
    # swing is slower" (4).
    assert text.words == 2 + 12 + 8 + 4
