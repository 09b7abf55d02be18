"""tools/i18n/library_texts.py finds the texts a page's cells pass to the library.

The expectation is a page written here, with each kind of call the book makes, and the .pot
format read back by babel (the book's catalog tool).
"""

from __future__ import annotations

import io

from babel.messages.pofile import read_po

from tools.i18n.library_texts import main, pot, texts

PAGE = '''# A page

```{code-cell} ipython3
---
tags: [hide-input]
---
display(verify.fact("§3, case II", ok, "xi stays in [-1, 1]"))
verify.numeric("(26)", residual, f, g, tol=1e-12, over="20 swings",
               measure="max relative error", mutant_label="$8K_1/\\\\omega_0$")
verify.fact("(30)", ok, f"over {n} rotations")
s = sym.Identity("split", "(16)", lhs, rhs, mutant=m, mutant_label="the other branch")
epp.plot_motion(motions, t, labels=["a swing", "$c_1 = 0$"])
epp.plot_phase_portrait(label=False)
```

```{code-cell} ipython3
fig, ax = plt.subplots()
ax.plot(t, x, label="a swing")
ax.axhline(0, label=r"$\\theta = 0$")
ax.set_xlabel("time $t$")
ax.set(ylabel=r"angle $\\theta$ (rad)", title="Two swings", xlim=(0, 1))
ax.text(0.5, 0.5, "the top", fontsize=9)
ax.annotate("a turning point", xy=(1, 2))
ax.legend(["one", "two"], title="kicks")
fig.suptitle(f"{n} swings")
bar.set_label("energy")
epp.localize(fig)
```
'''


def test_every_kind_of_text_is_found_with_its_line(tmp_path) -> None:
    (tmp_path / "page.md").write_text(PAGE, encoding="utf-8")
    found = texts(tmp_path)
    assert [(t.text, t.line, t.argument, t.literal) for t in found] == [
        ("§3, case II", 7, "claim", True),
        ("xi stays in [-1, 1]", 7, "fact", True),
        ("20 swings", 8, "over", True),
        ("max relative error", 8, "measure", True),
        ("f'over {n} rotations'", 10, "fact", False),
        ("the other branch", 11, "Identity mutant_label", True),
        ("a swing", 12, "plot_motion labels", True),
        ("a swing", 18, "plot label", True),
        ("time $t$", 20, "set_xlabel", True),
        ("angle $\\theta$ (rad)", 21, "set ylabel", True),
        ("Two swings", 21, "set title", True),
        ("the top", 22, "text", True),
        ("a turning point", 23, "annotate", True),
        ("one", 24, "legend", True),
        ("two", 24, "legend", True),
        ("kicks", 24, "legend title", True),
        ("f'{n} swings'", 25, "suptitle", False),
        ("energy", 26, "set_label", True),
    ]
    catalog = read_po(io.StringIO(pot(found)))
    assert [m.id for m in catalog if m.id] == ["§3, case II", "xi stays in [-1, 1]", "20 swings",
                                               "max relative error", "the other branch",
                                               "a swing", "time $t$", "angle $\\theta$ (rad)",
                                               "Two swings", "the top", "a turning point",
                                               "one", "two", "kicks", "energy"]
    swing = catalog.get("a swing")
    assert swing.auto_comments == ["plot_motion labels, plot label"]
    assert swing.locations == [("page.md", 12), ("page.md", 18)]


def test_the_book_passes_texts_and_the_command_writes_them(tmp_path, capsys) -> None:
    from tests.conftest import ROOT

    assert main([str(ROOT / "book"), str(tmp_path / "out.pot")]) == 0
    written = read_po(io.StringIO((tmp_path / "out.pot").read_text(encoding="utf-8")))
    assert len([m for m in written if m.id]) > 100
    assert "distinct literals written" in capsys.readouterr().out


def test_a_text_built_by_an_f_string_fails_the_command(tmp_path, capsys) -> None:
    # No catalog can key it, so a translated edition would show it in English.
    (tmp_path / "page.md").write_text(PAGE, encoding="utf-8")
    assert main([str(tmp_path), str(tmp_path / "out.pot")]) == 1
    assert "page.md:10 fact: f'over {n} rotations'" in capsys.readouterr().out
