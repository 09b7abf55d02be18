"""The classroom notebooks' own words, in each language of the book.

The pages' text comes translated from the catalogs (translation.py); what the exporter writes
itself (headings of exercises and solutions, the names of proofs and boxes, the figure
numbers, the cells around a student's answer, the notebook's first cell) is here. The
Japanese follows the Japanese edition of the book: 演習 3, 演習 3 の解答, 図 3, 補題 2, 証明.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class Words:
    """Templates with ``{}`` fields; English by default."""

    language: str = "en"
    exercise: str = "Exercise {number}"
    solution: str = "Solution to Exercise {number}"
    solution_unnumbered: str = "Solution"
    figure: str = "Fig. {number}"
    # A figure's number before its caption, in bold in the caption cell and in italics
    # under an image.
    figure_caption: str = "**Fig. {number}.** {caption}"
    figure_italic: str = "Fig. {number}. "
    proof: str = "Proof"
    # A statement or box heading with its title, and what ends the bold heading.
    titled: str = "{heading} ({title})"
    heading_end: str = "."
    statements: dict[str, str] = field(default_factory=dict)  # prf kind -> its name
    boxes: dict[str, str] = field(default_factory=dict)  # admonition -> its heading
    contents: str = "Contents"
    in_book: str = "*{text}* (in the book)"
    references: str = "References"
    figure_alt: str = "figure"
    edition: dict[str, str] = field(default_factory=dict)  # edition -> its name
    first: str = "*{book}*, classroom notebook ({edition} edition): **{title}**."
    install: str = ("If `import elliptic_pendulum` fails, run `{pip}` in a cell here "
                    "(the files beside this notebook, see `{readme}`), then restart the kernel.")
    answers_intro: str = ("Write your answers in the cells under each exercise; a self-check "
                          "cell tells you whether a result is right.")
    licence: str = ("Text and figures © 2024-2026 elliptic-pendulum contributors, from the "
                    "book's page `{page}.md`, under [CC BY 4.0]({cc_by}); code under the MIT "
                    "licence.")
    results: str = ("**Your results.** Work in the cell below, and leave in it {names}. Then "
                    "run the self-check under it: it says whether each result is right and, "
                    "if not, what to look at.")
    result_name: str = "`{name}`, {what}"
    result_separator: str = "; "
    placeholder: str = "{name} = ...  # replace ... by your result"
    hint: str = ("<details><summary><b>Hint</b> for the parts to prove or explain</summary>"
                 "\n\n{hint}\n\n</details>")
    # A check's note, folded above its cell (book/_ext/checkmarks.py: the page's mark).
    check: str = "<details><summary>✔ What the next cell checks</summary>\n\n{note}\n\n</details>"
    answer: str = ("**Your answer** to the parts to prove or explain (double-click to write "
                   "here).")
    # A translated edition's notebook asks the library for its language in a code cell
    # under the first (export.py); English is the library's own, and needs none.
    language_cell: str = ""

    def statement(self, kind: str) -> str:
        """The name of a sphinx-proof statement kind ("lemma" -> "Lemma")."""
        return self.statements.get(kind, kind.capitalize())


BOXES_EN = {
    "note": "Note", "warning": "Warning", "tip": "Tip", "important": "Important",
    "hint": "Hint", "caution": "Caution", "attention": "Attention", "danger": "Danger",
    "error": "Error", "seealso": "See also",
}

ENGLISH = Words(boxes=BOXES_EN, edition={"student": "student", "instructor": "instructor"})

# The names Sphinx (admonitions) and sphinx-proof give these in Japanese, and the edition
# names of the Japanese PDFs and download menu.
JAPANESE = Words(
    language="ja",
    exercise="演習 {number}",
    solution="演習 {number} の解答",
    solution_unnumbered="解答",
    figure="図 {number}",
    figure_caption="**図 {number}**　{caption}",
    figure_italic="図 {number}　",
    proof="証明",
    titled="{heading}（{title}）",
    heading_end="",
    statements={"lemma": "補題", "proposition": "命題", "theorem": "定理",
                "definition": "定義", "corollary": "系", "remark": "注意",
                "example": "例", "conjecture": "予想", "axiom": "公理",
                "criterion": "基準", "assumption": "仮定", "property": "性質",
                "observation": "観察", "algorithm": "アルゴリズム"},
    boxes={"note": "注釈", "warning": "警告", "tip": "ヒント", "important": "重要",
           "hint": "ヒント", "caution": "注意", "attention": "注目", "danger": "危険",
           "error": "エラー", "seealso": "参考"},
    contents="目次",
    in_book="*{text}*（本書のみ）",
    references="参考文献",
    figure_alt="図",
    edition={"student": "学生用", "instructor": "教員用"},
    first="*{book}*　授業用ノートブック（{edition}）：**{title}**",
    install=("`import elliptic_pendulum` が失敗するときは、このノートブックのセルで `{pip}` を"
             "実行し（このノートブックと同じフォルダにあるファイルを使う。`{readme}` を参照）、"
             "カーネルを再起動すること。"),
    answers_intro=("答えは各演習の下のセルに書くこと。自己チェックのセルが、結果が正しいか"
                   "どうかを教えてくれる。"),
    licence=("本文と図は © 2024-2026 elliptic-pendulum contributors、本書のページ "
             "`{page}.md` から作成したもので、[CC BY 4.0]({cc_by}) の下で利用できる。"
             "コードは MIT ライセンスである。"),
    results=("**あなたの結果**　下のセルで計算し、{names}をそのセルに残すこと。続いてその下の"
             "自己チェックを実行すると、それぞれの結果が正しいかどうか、正しくなければ"
             "どこを見直せばよいかが表示される。"),
    result_name="`{name}`（{what}）",
    result_separator="、",
    placeholder="{name} = ...  # ... をあなたの結果に置き換える",
    check="<details><summary>✔ 次のセルが検証すること</summary>\n\n{note}\n\n</details>",
    hint=("<details><summary><b>ヒント</b>（証明・説明を求める部分）</summary>"
          "\n\n{hint}\n\n</details>"),
    answer="**あなたの答え**（証明・説明を求める部分。ダブルクリックしてここに書く）",
    language_cell=(
        "# 検証の判定や図の文字を日本語で書かせる。elliptic_pendulum は書く言語を環境変数\n"
        "# LANGUAGE から読み、セルが渡す英語の文の訳を、ELLIPTIC_PENDULUM_MESSAGES が指す\n"
        "# カタログ（このノートブックと同じフォルダの {catalog}）から読む。\n"
        "import os\n"
        "\n"
        "os.environ[\"LANGUAGE\"] = \"ja\"\n"
        "if os.path.exists(\"{catalog}\"):\n"
        "    os.environ[\"ELLIPTIC_PENDULUM_MESSAGES\"] = os.path.abspath(\"{catalog}\")"),
)

WORDS = {"en": ENGLISH, "ja": JAPANESE}


def words(language: str | None) -> Words:
    """The exporter's words in ``language`` (None: English)."""
    key = language or "en"
    if key not in WORDS:
        raise ValueError(f"language must be one of {sorted(WORDS)}, not {language!r}")
    return WORDS[key]
