"""animate() takes any integral number of frames and refuses bools and floats by name."""


import numpy as np
import pytest

import elliptic_pendulum as ep
from elliptic_pendulum.plotting.animation import animate


def test_animate_accepts_numpy_integer_frames():
    import matplotlib.pyplot as plt

    anim = animate([ep.solve(1.0)], frames=np.int64(3))
    try:
        # The frames' times are a linspace of that many points, as for the int 3.
        assert len(anim.frame_times) == 3
    finally:
        anim._draw_was_started = True  # never rendered on purpose: no warning at deletion
        plt.close(anim._fig)


@pytest.mark.parametrize("bad", [True, 3.0, np.float64(3.0)])
def test_animate_refuses_non_integer_frames(bad):
    with pytest.raises(TypeError, match="frames"):
        animate([ep.solve(1.0)], frames=bad)
