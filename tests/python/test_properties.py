"""Properties of the motion on random scenarios (hypothesis): inside the valid range no handle
jumps, and the exact speeds are the finite differences of the positions."""

import math

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import benchdragon as bd

scenarios = st.builds(
    bd.Scenario,
    pitch=st.floats(0.45, 1.2),
    speed=st.floats(0.3, 3.0),
    bench_count=st.integers(3, 223),
    body_length=st.floats(1.6, 2.6),
    head_length=st.floats(2.6, 3.6),
    start_turn=st.floats(6.0, 16.0),
)
# No example database (runs leave nothing in the source tree) and the same draw every run, so a
# CI run is reproducible; raise max_examples locally to search further.
SETTINGS = settings(max_examples=20, deadline=None, database=None, derandomize=True,
                    suppress_health_check=[HealthCheck.too_slow])


def window(sim: bd.Simulation, span: float):
    """Up to `span` s of the valid motion from t = 0, short of its end by 2 % (speeds grow
    without bound at a vanishing root)."""
    r = sim.valid_range
    end = min(span, r.to - 0.02 * (r.to - max(r.from_, 0.0))) if math.isfinite(r.to) else span
    return max(r.from_, 0.0), end


@SETTINGS
@given(scenarios, st.floats(0.0, 1.0))
def test_no_handle_jumps_inside_the_valid_range(s, where):
    sim = bd.Simulation(s)
    t0, t1 = window(sim, 400.0 / s.speed)
    t = t0 + where * (t1 - t0)
    h = 1e-3 * (t1 - t0) / 1000.0 + 1e-4
    times = np.clip(t + h * np.arange(40), t0, t1)
    f = sim.frames(times)
    step = np.linalg.norm(np.diff(f.positions, axis=0), axis=2)   # (39, H) distance moved per step
    dt = np.diff(f.times)[:, None]
    fastest = np.maximum(np.abs(f.speeds[:-1]), np.abs(f.speeds[1:]))
    # Between two moments h apart a handle moves at most its speed over h (plus the speed's
    # change over the step, far below the margin): a jump would move it by a link's length.
    assert np.all(step <= 1.5 * fastest * dt + 1e-9)


@SETTINGS
@given(scenarios, st.floats(0.0, 1.0))
def test_speeds_are_the_derivative_of_the_positions(s, where):
    sim = bd.Simulation(s)
    t0, t1 = window(sim, 400.0 / s.speed)
    t = t0 + 1e-3 + where * (t1 - t0 - 2e-3)
    d = 1e-5
    f = sim.frames([t - d, t, t + d])
    velocity = (f.positions[2] - f.positions[0]) / (2 * d)   # central difference, (H, 2)
    np.testing.assert_allclose(np.linalg.norm(velocity, axis=1), np.abs(f.speeds[1]), rtol=1e-5, atol=1e-6)
    # Signed along the path: the tangent's direction says which way.
    tangents = sim.frame(t).tangents
    along = np.sum(velocity * tangents, axis=1)
    np.testing.assert_allclose(along, f.speeds[1], rtol=1e-5, atol=1e-6)
