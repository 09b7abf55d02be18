"""Rewrite one MyST Markdown cell of the book as Markdown that plain Jupyter renders.

Jupyter renders neither MyST roles nor directives. Cross-references become links (to an
anchor of this notebook or of another one: ``<a id="label"></a>`` is placed where the book
puts the label), citations become links to the reference list at the end, glued numbers
become their values, proofs and admonitions bold headings over block quotes, exercises a
``### Exercise N`` heading. Exercises and solutions leave marker lines (``SENTINEL``) in the
text so that the notebook assembler can add the student's answer cell and keep or drop the
solution's cells (a gated solution spans several cells).
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass, field

from .words import ENGLISH, Words

SENTINEL = "\x00"
DIRECTIVE_OPEN = re.compile(r"^(?P<fence>`{3,}|:{3,})\{(?P<name>[^}]+)\}\s*(?P<arg>.*)$")
PLAIN_FENCE = re.compile(r"^(?P<fence>`{3,}|~{3,})[^`{]*$")
OPTION = re.compile(r"^\s*:(?P<key>[\w-]+):\s*(?P<value>.*)$")
ROLE = re.compile(r"\{(?P<role>[\w:+-]+)\}`(?P<content>[^`]*)`")
TARGET = re.compile(r"^\s*\((?P<label>[^()\s]+)\)=\s*$")
DMATH_LABEL = re.compile(r"^(?P<close>.*\$\$)\s*\((?P<label>[^()\s]+)\)\s*$")
TEXT_AND_TARGET = re.compile(r"^(?P<text>.*?)\s*<(?P<target>[^<>]+)>$", re.DOTALL)
MD_LINK = re.compile(r"\]\((?P<page>[\w./-]+?)\.md(?P<frag>#[^)\s]*)?\)")
HEADING = re.compile(r"^#{1,6}\s+(?P<title>.*?)\s*#*\s*$")

# Directives shown as a bold heading over a block quote, with that heading.
BOXED = {
    "note": "Note", "warning": "Warning", "tip": "Tip", "important": "Important",
    "hint": "Hint", "caution": "Caution", "attention": "Attention", "danger": "Danger",
    "error": "Error", "seealso": "See also", "admonition": "", "dropdown": "",
    "epigraph": "", "topic": "", "sidebar": "", "margin": "", "card": "",
}
# Nothing to show in a notebook: navigation, the bibliography (each notebook ends with its
# own list) and glued figures, which the code cell above already draws.
DROPPED = {"toctree", "bibliography", "contents", "tableofcontents", "glue:figure",
           "glue", "glue:any", "glue:math", "glue:md", "index", "only"}
CODE = {"code-block", "code", "sourcecode"}
SEPARATE = ("exercise", "exercise-start", "exercise-end", "solution", "solution-start",
            "solution-end")


@dataclass
class Target:
    """Where a label points: the notebook (page stem), what it is, the link text."""

    page: str
    kind: str
    title: str
    number: str = ""


@dataclass
class Context:
    """What the conversion of one page needs to know about the whole book."""

    page: str
    files: dict[str, str]  # page stem -> notebook file name
    titles: dict[str, str]  # page stem -> page title
    targets: dict[str, Target]
    glue: Callable[[str, str], str]
    cite: Callable[[str, list[str]], str]
    exercise_numbers: dict[str, str] = field(default_factory=dict)  # exercise label -> number
    chapters: list[str] = field(default_factory=list)  # the pages after the first, in order
    words: Words = ENGLISH  # what the exporter writes itself, in the notebook's language


def link(ctx: Context, label: str, text: str) -> str:
    """A Markdown link to a label, inside this notebook or into another one."""
    target = ctx.targets.get(label)
    if target is None:
        raise ValueError(f"cross-reference to unknown label {label!r} in page {ctx.page!r}")
    if target.page not in ctx.files:  # a page of the book without a notebook
        return ctx.words.in_book.format(text=text)
    here = target.page == ctx.page
    if target.kind == "page":
        return f"[{text}]({ctx.files[target.page]})"
    return f"[{text}]({'' if here else ctx.files[target.page]}#{label})"


def _page_link(m: re.Match[str], ctx: Context) -> str:
    """A Markdown link to another page of the book becomes a link to its notebook."""
    page = _doc_label(m["page"])
    if page not in ctx.titles:
        raise ValueError(f"link to unknown page {m['page']}.md in page {ctx.page!r}")
    if page not in ctx.files:  # no notebook: the link goes, its text stays
        return "]"
    return f"]({ctx.files[page]}{m['frag'] or ''})"


def _split(content: str) -> tuple[str | None, str]:
    m = TEXT_AND_TARGET.match(content)
    return (m["text"].strip(), m["target"].strip()) if m else (None, content.strip())


def _doc_label(name: str) -> str:
    return re.sub(r"\.(md|ipynb)$", "", name.strip().lstrip("/").removeprefix("./"))


def convert_roles(text: str, ctx: Context) -> str:
    """Rewrite the MyST roles of one Markdown text."""

    def replace(match: re.Match[str]) -> str:
        role, content = match["role"], match["content"]
        if role == "math":
            return f"${content}$"
        if role.startswith("glue"):
            key, _, fmt = content.rpartition(":") if ":" in content else (content, "", "s")
            return ctx.glue(key.strip(), fmt.strip())
        if role.startswith("cite"):
            return ctx.cite(role, [k.strip() for k in content.split(",") if k.strip()])
        if role.startswith("py:") or role in {"func", "class", "meth", "mod", "attr", "obj"}:
            text_, target = _split(content)
            shown = text_ or (target[1:].split(".")[-1] if target.startswith("~") else target)
            return f"`{shown}`"
        text_, label = _split(content)
        if role == "doc":
            page = _doc_label(label)
            if page not in ctx.titles:
                raise ValueError(f"{{doc}} to unknown page {page!r} in page {ctx.page!r}")
            if page not in ctx.files:
                return ctx.words.in_book.format(text=text_ or ctx.titles[page])
            return f"[{text_ or ctx.titles[page]}]({ctx.files[page]})"
        if role == "eq":
            target = ctx.targets.get(label)
            return link(ctx, label, text_ or (target.title if target else label))
        if role in {"ref", "prf:ref", "numref", "any"}:
            target = ctx.targets.get(label)
            if target is None:
                raise ValueError(f"{{{role}}} to unknown label {label!r} in page {ctx.page!r}")
            if text_ is None:
                shown = target.title
            else:  # numref's text may hold %s (the number) and {name} (the title)
                shown = text_.replace("%s", target.number).replace("{number}", target.number)
                shown = shown.replace("{name}", target.title)
            return link(ctx, label, shown)
        return text_ if text_ is not None else content

    return ROLE.sub(replace, text)


def _quote(lines: list[str]) -> list[str]:
    return [("> " + line).rstrip() for line in lines]


def _anchor(label: str) -> list[str]:
    # A blank line after it: otherwise Markdown would swallow the next line into the HTML.
    return [f'<a id="{label}"></a>', ""]


def convert_markdown(text: str, ctx: Context) -> str:
    """Rewrite a MyST Markdown cell to plain Markdown (with marker lines, see SENTINEL)."""
    lines = text.splitlines()
    out: list[str] = []
    verbatim: list[str] = []
    i = 0
    while i < len(lines):
        line = lines[i]
        stripped = line.strip()
        opened = DIRECTIVE_OPEN.match(stripped)
        plain_fence = PLAIN_FENCE.match(stripped)
        if opened or plain_fence:
            m = opened or plain_fence
            assert m is not None
            fence = m["fence"]
            closing = re.compile(r"^\s*" + re.escape(fence[0]) + "{" + str(len(fence)) + r",}\s*$")
            body: list[str] = []
            i += 1
            while i < len(lines) and not closing.match(lines[i]):
                body.append(lines[i])
                i += 1
            i += 1  # the closing fence
            if opened:
                out.extend(_directive(opened["name"].strip(), opened["arg"].strip(), body, ctx))
            else:  # a code block: kept verbatim, roles in it are not roles
                verbatim.append("\n".join([line, *body, fence]))
                out.append(f"{SENTINEL}V{len(verbatim) - 1}{SENTINEL}")
            continue
        target = TARGET.match(line)
        if target:
            out.extend(_anchor(target["label"]))
            i += 1
            continue
        if stripped.startswith("% ") or stripped == "%" or stripped == "+++":
            i += 1
            continue
        if line.startswith(": ") and out and out[-1].strip() and i > 0:  # a definition list
            out[-1] = f"**{out[-1].strip()}**: {line[2:].strip()}"
            i += 1
            continue
        labelled = DMATH_LABEL.match(line)
        if labelled:
            out.extend([labelled["close"], "", *_anchor(labelled["label"])])
            i += 1
            continue
        out.append(line)
        i += 1
    joined = convert_roles("\n".join(out), ctx)  # whole text: a role may span two lines
    joined = MD_LINK.sub(lambda m: _page_link(m, ctx), joined)
    joined = re.sub(SENTINEL + r"V(\d+)" + SENTINEL, lambda m: verbatim[int(m[1])], joined)
    return re.sub(r"\n{3,}", "\n\n", joined).strip("\n")


def _directive(name: str, arg: str, body: list[str], ctx: Context) -> list[str]:
    options: dict[str, str] = {}
    while body and OPTION.match(body[0]):
        m = OPTION.match(body[0])
        assert m is not None
        options[m["key"]] = m["value"].strip()
        body = body[1:]
    if name == "toctree":  # the first notebook lists the chapters with links
        caption = options.get("caption", ctx.words.contents)
        items = [f"{i}. [{ctx.titles[p]}]({ctx.files[p]})" for i, p in enumerate(ctx.chapters, 1)]
        return ["", f"**{caption}**", "", *items, ""]
    if name in DROPPED:
        return []
    if name in CODE:
        return ["```" + (arg or "python"), *body, "```", ""]
    label = options.get("label") or options.get("name") or ""
    anchor = _anchor(label) if label else []
    if name == "math":
        return ["", *anchor, "$$", *body, "$$", ""]
    inner = convert_markdown("\n".join(body), ctx).splitlines()
    if name in {"figure", "image"}:
        alt = options.get("alt", ctx.words.figure_alt)
        number = ctx.targets[label].number if label in ctx.targets else ""
        block = ["", *anchor, f"![{alt}]({arg})", ""]
        if inner:
            prefix = ctx.words.figure_italic.format(number=number) if number else ""
            block += [f"*{prefix}{' '.join(inner)}*", ""]
        return block
    if name in SEPARATE:
        return _exercise_part(name, arg, label, inner, ctx)
    if name.startswith("prf:") or name in BOXED:
        words = ctx.words
        if name in BOXED:
            kind = words.boxes.get(name, BOXED[name])
        else:
            kind = words.statement(name.split(":")[-1])
        target = ctx.targets.get(label)
        if name == "prf:proof":
            heading = words.proof
        else:
            number = target.number if target else ""
            heading = " ".join(p for p in (kind, number) if p)
            title = convert_roles(arg, ctx)
            if heading and title:
                heading = words.titled.format(heading=heading, title=title)
            else:
                heading = heading or title
        head = [f"> **{heading}{words.heading_end}**", ">"] if heading else []
        return ["", *anchor, *head, *_quote(inner), ""]
    return ["", *anchor, *inner, ""]


def _exercise_part(name: str, arg: str, label: str, inner: list[str], ctx: Context) -> list[str]:
    if name in {"exercise", "exercise-start"}:
        number = ctx.exercise_numbers.get(label, "")
        title = convert_roles(arg, ctx)
        heading = ctx.words.exercise.format(number=number).strip()
        if title:
            heading = ctx.words.titled.format(heading=heading, title=title)
        heading = "### " + heading
        block = ["", *(_anchor(label) if label else []), heading, "", *inner, ""]
        if name == "exercise":
            block += [f"{SENTINEL}ANSWER:{label}{SENTINEL}", ""]
        return block
    if name == "exercise-end":
        return ["", f"{SENTINEL}ANSWER{SENTINEL}", ""]
    if name == "solution-end":
        return ["", f"{SENTINEL}SOLUTION-END{SENTINEL}", ""]
    # solution or solution-start: the argument is the exercise's label.
    number = ctx.exercise_numbers.get(arg, "")
    words = ctx.words
    heading = "#### " + (words.solution.format(number=number) if number
                         else words.solution_unnumbered)
    block = ["", f"{SENTINEL}SOLUTION-START:{arg}{SENTINEL}", "", heading, "", *inner, ""]
    if name == "solution":
        block += [f"{SENTINEL}SOLUTION-END{SENTINEL}", ""]
    return block


def strip_solutions(text: str) -> str:
    """Remove every solution from a MyST page: ``{solution}`` blocks and everything from a
    ``{solution-start}`` to its ``{solution-end}``, the solution's code cells included.

    The student book applies this at Sphinx's source-read: sphinx-exercise's own
    ``hide_solutions`` drops the solution-start node but leaves the solution's text and cells
    and an orphan solution-end node, which crashes the HTML writer.
    """
    lines = text.splitlines(keepends=True)
    out: list[str] = []
    skipping = False
    i = 0
    while i < len(lines):
        opened = DIRECTIVE_OPEN.match(lines[i].strip())
        name = opened["name"].strip() if opened else ""
        if opened and name in {"solution", "solution-start", "solution-end"}:
            fence = opened["fence"]
            closing = re.compile(r"^\s*" + re.escape(fence[0]) + "{" + str(len(fence)) + r",}\s*$")
            i += 1
            while i < len(lines) and not closing.match(lines[i]):
                i += 1
            i += 1
            skipping = name == "solution-start"
            continue
        if not skipping:
            out.append(lines[i])
        i += 1
    if skipping:
        raise ValueError("a solution-start has no solution-end")
    return "".join(out)
