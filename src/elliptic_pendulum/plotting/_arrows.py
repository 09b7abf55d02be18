"""The phase portrait's arrowheads: one on each curve, in the direction of the motion.

Where they go is the whole problem: nested swings side by side would take theirs side by
side, and a head must not cover a curve's label. :func:`arrowheads_in_view` spreads them.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from ._base import layout, text_size

__all__ = ["arrowheads_in_view", "visible"]


def _arrowhead(ax: Any, th: np.ndarray, dth: np.ndarray, i: int, color: str) -> Any:
    """Draw an arrowhead on the curve at sample i, pointing to sample i + 1.

    The samples are in time order, so the head shows the direction of the motion itself.
    """
    return ax.annotate("", xy=(th[i + 1], dth[i + 1]), xytext=(th[i], dth[i]),
                       arrowprops=dict(arrowstyle="-|>", color=color, lw=0,
                                       mutation_scale=text_size(ax, 1.4), shrinkA=0,
                                       shrinkB=0))


def visible(th: np.ndarray, dth: np.ndarray, view: Any) -> np.ndarray:
    (x0, x1), (y0, y1) = view
    return (th >= x0) & (th <= x1) & (dth >= y0) & (dth <= y1)


def _same_curve(a: tuple, b: tuple) -> bool:
    """Whether two (shift, theta, ...) entries are copies of one curve, 2 pi k apart."""
    return len(a[1]) == len(b[1]) and bool(np.allclose(a[1] - a[0], b[1] - b[0]))


def _curves(entries: list) -> list[list]:
    """Group the entries by curve (its copies 2 pi k apart), in the order drawn."""
    groups: list[list] = []
    for entry in entries:
        for group in groups:
            if _same_curve(group[0], entry):
                group.append(entry)
                break
        else:
            groups.append([entry])
    return groups


# Offsets tried, in turn, from a head's chosen place when a label is in the way (radians of
# the swing's phase angle, or fractions of the view's width).
_NUDGES = (0.0, 0.25, -0.25, 0.5, -0.5, 0.75, -0.75, 1.0, -1.0)


def arrowheads_in_view(ax: Any, drawn: dict, view: Any, labels: Sequence[Any] = ()) -> None:
    """Draw one arrowhead on each curve, where no two heads crowd each other.

    Nested swings would take their heads side by side if all sat at one place: so swing i
    goes on copy i mod 3 of those in view (the centre's, then its neighbours'), in the
    upper right of its oval for even i and the lower left for odd i, which leaves two heads
    per copy, three curves apart, on opposite sides. Each branch of the separatrix takes its
    head on the central copy, upper left and lower right, between those of the swings; the
    rotations above the axis near the view's left edge, those below near its right edge,
    where no label is. A head that would cover a label moves along its curve (_NUDGES).
    """
    renderer = layout(ax)
    # A head keeps half a letter's height from every label: touching, it reads as a sign.
    pad = text_size(ax) * ax.figure.dpi / 72 * 0.5
    boxes = [t.get_window_extent(renderer).padded(pad) for t in labels]
    (x0, x1), (y0, y1) = view
    centre, width = (x0 + x1) / 2, x1 - x0
    # Heads stay off the frame: a head in a corner is half cut and reads as clutter.
    inner = ((x0 + 0.06 * width, x1 - 0.06 * width),
             (y0 + 0.06 * (y1 - y0), y1 - 0.06 * (y1 - y0)))

    def put(th: np.ndarray, dth: np.ndarray, color: str, score: Any, near: float) -> bool:
        # The visible sample nearest the chosen place (score 0), if within ``near`` of it,
        # that covers no label.
        seen = np.flatnonzero(visible(th, dth, inner))[:-1]
        if len(seen) == 0:
            return False
        for nudge in _NUDGES:
            scores = score(seen, nudge)
            if scores.min() > near:
                continue
            i = int(seen[np.argmin(scores)])
            head = _arrowhead(ax, th, dth, i, color)
            head.update_positions(renderer)
            extent = head.arrow_patch.get_window_extent(renderer)
            if not any(extent.overlaps(box) for box in boxes):
                boxes.append(extent)
                return True
            head.remove()
        return False

    def copies_of(group: list) -> list:
        # The copies with a part in view, the nearest the centre first.
        shown = [e for e in group if np.any(visible(e[1], e[2], view))]
        return sorted(shown, key=lambda e: (abs(e[0] - centre), e[0]))

    def along(th: np.ndarray, where: float) -> Any:
        return lambda idx, n: np.abs(th[idx] - where - n * 0.1 * width)

    # A close-up may show no part of a curve near its chosen place: then the swings take
    # their heads at a turning point (where they cross the axis upright), the separatrix and
    # the rotations near the view's middle.
    odd_pi = math.pi * (2 * round((centre - math.pi) / (2 * math.pi)) + 1)
    for i, group in enumerate(_curves(drawn["II"])):
        shown = copies_of(group)
        order = shown[i % 3:] + shown[:i % 3] if shown else []
        targets = ((math.pi / 4, 0.0, math.pi) if i % 2 == 0
                   else (-3 * math.pi / 4, math.pi, 0.0))
        done = False
        for target in targets:
            for shift, th, dth, color in order:
                x, y = th - shift, dth
                phase = np.arctan2(y / np.max(np.abs(y)), x / np.max(np.abs(x)))
                if put(th, dth, color, lambda idx, n, ph=phase, tg=target: np.abs(
                        np.angle(np.exp(1j * (ph[idx] - tg - n)))), near=0.3):
                    done = True
                    break
            if done:
                break
    for group in _curves(drawn["III"]):
        for shift, th, dth, color in copies_of(group):
            upper = np.mean(dth) > 0
            places = (shift - math.pi / 2 if upper else shift + math.pi / 2,
                      odd_pi - width / 4 if upper else odd_pi + width / 4)
            if any(put(th, dth, color, along(th, w), near=0.05 * width) for w in places):
                break
    for group in _curves(drawn["IV"]):
        for _shift, th, dth, color in copies_of(group):
            # Where the rotations lie farthest apart, at an odd multiple of pi: the upper ones
            # left of the labels there, the lower ones right (none is labelled below).
            upper = np.mean(dth) > 0
            wide = width > 4 * math.pi  # several copies in view, with their labels
            spots = [odd_pi - 2 * math.pi if upper and wide else odd_pi, odd_pi]
            if any(put(th, dth, color, along(th, w), near=0.05 * width) for w in spots):
                break
