"""Tests of animation.py: what the frames show, and a player that needs no network.

References: ep.integrate (solve_ivp on (3), independent of the closed form) for where each bob
and phase point must be at each frame's time; the HTML itself for the network check.
"""

import gc
import math
import re
import warnings

import pytest
from matplotlib import pyplot as plt

import elliptic_pendulum as ep
from elliptic_pendulum.plotting.animation import animate, animation_html

MOTIONS = [ep.solve(0.0), ep.solve(2.0), ep.solve(0.0, 2.0), ep.solve(0.3, -2.6, 1.5)]


def test_frames_show_each_pendulum_where_an_integration_puts_it():
    anim = animate(MOTIONS, frames=12)
    try:
        for j, t in enumerate(anim.frame_times):
            anim.draw_frame(j)
            for i, m in enumerate(MOTIONS):
                theta, dtheta = ep.integrate(m.theta0, m.dtheta0, m.omega0, t=float(t))
                (x,), (y,) = anim.bobs[i].get_data()
                assert abs(x - (2.5 * i + math.sin(theta))) < 1e-7
                assert abs(y + math.cos(theta)) < 1e-7
                (px,), (py,) = anim.points[i].get_data()
                assert -math.pi < px <= math.pi
                assert abs(math.remainder(px - theta, 2 * math.pi)) < 1e-7
                assert abs(py - dtheta) < 1e-7
    finally:
        anim._draw_was_started = True  # drawn by hand: no warning about an unrendered animation
        plt.close(anim._fig)


def test_duration_defaults_to_the_longest_finite_period():
    anim = animate(MOTIONS, frames=3)
    try:
        longest = max(m.period for m in MOTIONS if math.isfinite(m.period))
        assert anim.frame_times[-1] == longest
        assert anim.frame_times[0] == 0.0
    finally:
        anim._draw_was_started = True
        plt.close(anim._fig)


def test_html_player_is_self_contained_and_closes_its_figure():
    before = plt.get_fignums()
    html = animation_html(MOTIONS[:2], frames=4, duration=3.0)
    assert plt.get_fignums() == before
    assert html.count("data:image/png;base64") == 4
    assert "http://" not in html and "https://" not in html
    assert "fa fa-" not in html and "\u25b6" in html  # the icons are plain characters


def test_html_player_controls_have_names():
    # WCAG 4.1.2 (name, role, value), as axe-core's rules button-name and label check it:
    # every button has an aria-label, the characters drawn on them are hidden from screen
    # readers, and the frame slider, which matplotlib leaves unnamed, is labelled.
    html = animation_html(MOTIONS[:1], frames=2, duration=1.0)
    buttons = re.findall(r"<button[^>]*>.*?</button>", html, re.S)
    assert len(buttons) == 9
    for button in buttons:
        assert re.search(r'aria-label="[A-Z][a-z ]+"', button), button
        assert re.search(r'<span aria-hidden="true">[^<]+</span></button>', button), button
    sliders = re.findall(r"<input[^>]*type=\"range\"[^>]*>", html)
    assert len(sliders) == 1 and 'aria-label="Frame"' in sliders[0]


@pytest.mark.parametrize("kwargs, error", [
    ({"motions": []}, ValueError),
    ({"motions": [ep.solve(1.0)] * 7}, ValueError),
    ({"motions": [ep.solve(1.0)], "frames": 1}, ValueError),
    ({"motions": [ep.solve(1.0)], "duration": -1.0}, ValueError),
    ({"motions": [1.0]}, TypeError),
])
def test_animate_refuses_bad_input(kwargs, error):
    with pytest.raises(error):
        animate(**kwargs)


def test_frames_drawn_by_hand_count_as_rendering():
    # matplotlib warns from Animation.__del__ when an animation is dropped unrendered; the
    # book's checks draw frames with draw_frame and must leave the build quiet. The mutant
    # (an animation never drawn) does warn, so the check can fail.
    def dropped(draw: bool) -> list[str]:
        anim = animate([ep.solve(1.0)], frames=3)
        if draw:
            anim.draw_frame(1)
        plt.close(anim.bobs[0].figure)
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            del anim
            gc.collect()
        return [str(w.message) for w in caught]

    assert dropped(draw=True) == []
    assert any("without rendering" in m for m in dropped(draw=False))
