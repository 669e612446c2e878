"""benchdragon: exact simulation, collisions, pictures and films of the Bench Dragon.

The Bench Dragon is Problem A of the 2024 China Undergraduate Mathematical Contest in Modeling:
a chain of 223 benches (224 handles) coiling in along an Archimedean spiral, turning around on an
S-curve and coiling out again. This package is the benchdragon C++ library, the same one the
``dragon`` tool runs, as Python data:

>>> import benchdragon as bd
>>> round(bd.collide(bd.Scenario()).time, 6)
412.473838

Lengths are in metres, times in seconds, speeds in m/s. A scenario's values are the tool's
scenario flags in snake_case (``--bench-count`` is ``bench_count``). Windows of the motion
(``from_``, ``to``) take seconds, or head travel as a string (``"-100m"``): the chain's shape
depends on the head's travel alone, so every geometric answer is the same at any head speed.

Answers are result objects whose keys are attributes too and whose ``to_dict()`` equals the
tool's ``--json`` for the same scenario; frames are numpy arrays; sweeps are pandas DataFrames,
computed on any ``concurrent.futures.Executor`` (a Dask ``distributed.Client`` too). Long calls
release the GIL and stop on Ctrl-C (KeyboardInterrupt).

Errors: ``InputError`` (a ``ValueError``: ``.field``, ``.value``, ``.allowed``, and ``.jam``
for a moment past the end of the dragon's valid motion), ``FileError`` (an ``OSError``),
``SolverError`` (a ``RuntimeError``).
"""

from __future__ import annotations

import io
import json
import logging
import os
import sys
import threading
import time
import warnings
from typing import Any, Callable, Iterable, Mapping, Optional, Sequence, Union

from . import _benchdragon as _core
from ._benchdragon import FileError, InputError, SolverError

__version__ = "0.1.0"
__all__ = [
    "Scenario", "Simulation", "Frame", "Frames", "ValidRange", "Result", "CollideResult", "MinPitchResult",
    "TurnaroundResult", "MaxSpeedResult", "SolveResult", "collide", "min_pitch", "turnaround", "max_speed",
    "solve", "sweep", "merge_sweep", "Picture", "render", "video", "film", "InputError", "FileError", "SolverError", "ASSETS",
]

#: The package's own assets (colour themes, scenario presets, storyboards).
ASSETS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "assets")

Moment = Union[None, float, str]


# ---- Scenarios -------------------------------------------------------------------------------


class Scenario:
    """A dragon, its path and its head's speed.

    Keyword values, each the ``dragon`` tool's scenario flag in snake_case, over the contest's
    defaults: ``pitch`` (0.55 m, the plain spiral's), ``speed`` (1 m/s, the head's),
    ``bench_count`` (223, head and tail included), ``head_length`` (3.41 m), ``body_length``
    (2.2 m), ``width`` (0.3 m), ``hole_offset`` (0.275 m), ``start_turn`` (16), ``turn_radius``
    (4.5 m), ``turn_pitch`` (1.7 m, the turnaround's spirals) and ``arc_ratio`` (2).

    Each value is checked on its own range when the scenario is made (``InputError`` names it by
    its keyword), and so are the rules between the benches' values (the holes within the boards);
    a bench count is a whole number (not a bool), checked before it is narrowed. Rules between a
    path's values and the benches (the pitch above the bench width) are checked where a
    computation reads them, as the tool does. Scenarios are immutable, compare equal by value, hash, and pickle.
    """

    __slots__ = ("_values",)

    def __init__(self, **values: float) -> None:
        object.__setattr__(self, "_values", _core._scenario(values))

    @classmethod
    def from_toml(cls, path: Union[str, os.PathLike], **overrides: float) -> "Scenario":
        """The scenario a TOML file describes (as ``dragon --scenario FILE``), keywords over it.

        An old name in the file (``[motion] head_speed``, the sections ``[dragon]``, ``[path]``,
        ``[motion]``) is read with a ``FutureWarning`` naming the key to write instead, one per
        old name."""
        values, _given, old_names = _core._scenario_from_toml(os.fspath(path))
        for message in old_names:
            warnings.warn(message, FutureWarning, stacklevel=2)
        return cls(**{**values, **overrides})

    def replace(self, **changes: float) -> "Scenario":
        """This scenario with some values changed."""
        return Scenario(**{**self._values, **changes})

    def to_dict(self) -> dict:
        """Every value, by keyword."""
        return dict(self._values)

    def __getattr__(self, name: str) -> Any:
        if name == "_values":  # not made (its __init__ raised): no values to look in
            raise AttributeError(name)
        try:
            return self._values[name]
        except KeyError:
            raise AttributeError(f"Scenario has no value {name!r}") from None

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError("a Scenario is immutable: use replace()")

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Scenario) and self._values == other._values

    def __hash__(self) -> int:
        return hash(tuple(sorted(self._values.items())))

    def __reduce__(self):
        return (Scenario._from_values, (dict(self._values),))

    @staticmethod
    def _from_values(values: dict) -> "Scenario":
        return Scenario(**values)

    def __repr__(self) -> str:
        default = _core._scenario({})
        changed = ", ".join(f"{k}={v!r}" for k, v in self._values.items() if default[k] != v)
        return f"Scenario({changed})"

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._values))


def _values(scenario: Optional[Scenario]) -> dict:
    if scenario is None:
        return {}
    if not isinstance(scenario, Scenario):
        raise TypeError(f"expected a Scenario, got {type(scenario).__name__}")
    return scenario.to_dict()


# ---- Results ---------------------------------------------------------------------------------


class Result(dict):
    """An answer: a dict of the tool's ``--json`` keys, each also an attribute.

    Keys that are Python keywords take a trailing underscore as attributes (``r.from_`` is
    ``r["from"]``). ``to_dict()`` is a plain copy, equal to ``json.loads`` of the command's
    ``--json`` for the same scenario.
    """

    def __getattr__(self, name: str) -> Any:
        if name in self:
            return self[name]
        if name.endswith("_") and name[:-1] in self:
            return self[name[:-1]]
        raise AttributeError(f"{type(self).__name__} has no {name!r}")

    def __dir__(self):
        return sorted(set(super().__dir__()) | {k if k.isidentifier() and k != "from" else k + "_" for k in self})

    def to_dict(self) -> dict:
        return json.loads(json.dumps(self))

    def __repr__(self) -> str:
        keys = ", ".join(list(self)[:6])
        return f"<{type(self).__name__}: {keys}{', ...' if len(self) > 6 else ''}>"


class CollideResult(Result):
    """Q2: the first contact (``dragon collide --json``).

    ``time`` (s) and ``travel`` (m of head travel) of the first contact, or None; ``benches``
    (the two touching, numbered from 1 at the head); ``head_radius`` (m); ``point`` (the contact
    point, m); ``tolerance`` (s); the window searched (``from``/``to`` in s, ``from_travel``/
    ``to_travel`` in m); ``jam`` (where the dragon's valid motion ended the search, or None);
    ``handles`` (every handle then, rounded as the tool prints). ``frame`` (not in ``to_dict``)
    is that moment as a :class:`Frame`.

    What the search proved, as ``dragon collide --json`` says it: ``enclosure`` (None without a
    contact) holds the first contact's ``travel`` [lo, hi] (m of head travel: no contact is
    proved before lo, benches touch at hi) and ``time`` [lo, hi] (s); ``proof`` says how:
    ``method`` ("enclosure": every step proved contact-free by enclosing each bench over it, with
    ``prove=True``; "rate": each step rests on the rate bound checked at its end, without it;
    "enclosure+rate": some steps, ``unproved_steps`` over ``unproved_travel`` m, where a link
    turned too far for the enclosures), ``steps`` (proved), ``subdivisions``,
    ``least_separation`` (m, the least separation the proved steps proved, or None) and
    ``covered_travel`` [from, to] (m of head travel the accepted steps cover).
    """


class MinPitchResult(Result):
    """Q3: the smallest pitch reaching the turning space collision-free (``dragon min-pitch --json``).

    ``pitch`` (m, to 1e-9 m), or None with ``below_range`` / ``above_range`` saying which side it
    lies on; ``intervals`` (feasible and infeasible pitches over the range), ``grid``, ``jam``
    and ``guarantee`` (what the search proves).

    What was proved, as ``dragon min-pitch --json`` says it: ``proof`` with ``method``
    ("enclosure cells" with ``prove=True``, "enclosure cells, incomplete" when some feasible
    pitches, those within a fraction of a micrometre of a change, are left to the runs; "runs"
    without it), ``proved`` ([lo, hi] ranges of pitches, m, every pitch inside proved feasible),
    ``unproved`` (the feasible intervals' parts not proved; None without ``prove``),
    ``proved_colliding`` and ``unproved_colliding`` (the same for the intervals that collide:
    every pitch in a proved range meets a contact before the boundary), ``least_feasible``
    ([lo, hi] m: the least feasible pitch of the range is proved to lie in it; None without
    ``prove``), ``cells``, ``pitch_ranges``, ``subdivisions`` and ``least_separation`` (m, or None).
    """


class TurnaroundResult(Result):
    """Q4: the S-curve, whether it can be shorter, its first contact and clearance (``dragon turnaround --json``).

    With the clearance check, ``enclosure`` and ``proof`` say what its first-contact search
    proved, as :class:`CollideResult`'s do (every step with ``prove=True``). ``proof["clearance"]``
    is None without ``prove=True``; with it, ``proved``, ``at_least`` (m: no two benches come
    closer anywhere in the window, within 1e-6 m under ``clearance["distance"]``; None when not
    proved), ``steps`` and ``subdivisions``.
    """


class MaxSpeedResult(Result):
    """Q5: the largest head speed with every handle at or under the limit (``dragon max-speed --json``).

    ``max_head_speed`` (m/s), ``ratio`` (the fastest handle over the head), ``handle`` and
    ``tied`` (which reach it), ``time`` (s) and ``travel`` (m), the window, ``jam`` and
    ``unbounded`` (a handle's speed without bound before the window ends). Where the end of
    the valid motion cuts the window short (``jam`` set), ``max_head_speed`` is None: the dragon
    cannot make the turn at any speed.

    What was proved, as ``dragon max-speed --json`` says it: with ``prove=True``, ``enclosure``
    [lo, hi] (m/s: every head speed up to lo keeps every handle to the limit, any over hi does
    not; None if not every stretch could be bounded) and ``proof``: ``method`` ("lipschitz
    bound", or "lipschitz bound, incomplete"), ``ratio`` [lo, hi] (the largest ratio's
    enclosure, hi None when not proved), ``tolerance`` (relative), ``stretches``,
    ``subdivisions``, ``evaluations``, ``unproved``, ``unproved_travel`` (m) and ``narrowest``
    (m of head travel). Without it, ``enclosure`` is None and ``proof`` is
    ``{"method": "sampled"}``: the maximum is the scan's and its refinement's.
    """


class SolveResult(Result):
    """The contest's five questions (``dragon solve``'s summary.json): keys ``q1`` .. ``q5``."""


class Jam(Result):
    """The end of the dragon's valid motion: ``time`` (s), ``travel`` (m), ``handle`` (which
    would have to jump), ``kind`` (``root_vanishes`` or ``nearer_root``, as time runs forward),
    ``ahead`` (the motion is valid until it, else from it), ``point``, ``tolerance`` (s)."""


def _jam(d: Optional[dict]) -> Optional[Jam]:
    return None if d is None else Jam(d)


# ---- Simulations -----------------------------------------------------------------------------


class Frame:
    """The whole chain at one moment, as numpy arrays (float64).

    ``time`` (s), ``travel`` (m), ``positions`` (H, 2) and ``tangents`` (H, 2) of the H handles
    (0: the head's front), ``speeds`` (H,) signed along the path (negative: backing up), and the
    benches' rectangles: ``bench_centres`` (N, 2), ``bench_axes`` (N, 2, unit, rear to front) and
    ``bench_half_sizes`` (N, 2: half length, half width).
    """

    __slots__ = ("time", "travel", "positions", "speeds", "tangents", "bench_centres", "bench_axes",
                 "bench_half_sizes")

    def __init__(self, d: dict) -> None:
        for k in self.__slots__:
            setattr(self, k, d[k])

    def __eq__(self, other: object) -> bool:
        return type(other) is type(self) and _same_slots(self, other)

    __hash__ = None  # holds arrays: equal by value, not hashable

    def __repr__(self) -> str:
        return f"<Frame t={self.time:g} s: {len(self.speeds)} handles>"


class Frames:
    """Frames at several moments: ``times`` (T,), ``positions`` (T, H, 2), ``speeds`` (T, H);
    ``scenario`` and ``path`` of the simulation they come from."""

    __slots__ = ("times", "positions", "speeds", "scenario", "path")

    def __init__(self, times, positions, speeds, scenario: Optional["Scenario"] = None, path: str = "spiral") -> None:
        self.times, self.positions, self.speeds = times, positions, speeds
        self.scenario, self.path = scenario, path

    def to_xarray(self):
        """An ``xarray.Dataset`` over dimensions time x handle x coordinate: ``position`` (m) and
        ``speed`` (m/s, signed along the path), coordinates ``time`` (s), ``handle`` (0..H-1) and
        ``coordinate`` ("x", "y"); the units in each variable's ``units`` attribute, the scenario's
        values as attributes ``scenario_<name>`` and the path as ``path``. ``.to_netcdf(file)``
        writes it (with python3-netcdf4 or scipy installed)."""
        import numpy as np
        import xarray as xr

        t_count, h_count = self.speeds.shape
        attrs = {"title": "Bench Dragon handles (benchdragon)", "path": self.path}
        if self.scenario is not None:
            attrs.update({f"scenario_{k}": v for k, v in self.scenario.to_dict().items()})
        return xr.Dataset(
            {
                "position": (("time", "handle", "coordinate"), self.positions,
                             {"units": "m", "long_name": "handle centre position"}),
                "speed": (("time", "handle"), self.speeds,
                          {"units": "m/s", "long_name": "handle speed, signed along the path"}),
            },
            coords={
                "time": ("time", np.asarray(self.times), {"units": "s", "long_name": "time"}),
                "handle": ("handle", np.arange(h_count), {"long_name": "handle (0: head front)"}),
                "coordinate": ("coordinate", np.array(["x", "y"])),
            },
            attrs=attrs,
        )

    def __eq__(self, other: object) -> bool:
        return type(other) is type(self) and _same_slots(self, other)

    __hash__ = None

    def __len__(self) -> int:
        return len(self.times)

    def __repr__(self) -> str:
        return f"<Frames: {self.positions.shape[0]} times x {self.positions.shape[1]} handles>"


def _same_slots(a: Any, b: Any) -> bool:
    """Every slot of `a` and `b` equal, arrays element by element (NaN equal to NaN)."""
    import numpy as np

    for k in type(a).__slots__:
        x, y = getattr(a, k), getattr(b, k)
        if isinstance(x, np.ndarray) or isinstance(y, np.ndarray):
            if not (np.shape(x) == np.shape(y) and np.array_equal(x, y, equal_nan=True)):
                return False
        elif x != y and not (x != x and y != y):  # NaN (an unbounded window's end) equals NaN
            return False
    return True


class ValidRange:
    """Where the dragon can follow its path: ``from_`` .. ``to`` (s; -inf/inf when it never
    stops), the same as head travel (``from_travel``, ``to_travel``, m), and the :class:`Jam`
    that ends it on each side (``before``, ``after``), or None."""

    __slots__ = ("from_", "to", "from_travel", "to_travel", "before", "after")

    def __init__(self, d: dict) -> None:
        self.from_, self.to = d["from"], d["to"]
        self.from_travel, self.to_travel = d["from_travel"], d["to_travel"]
        self.before, self.after = _jam(d["before"]), _jam(d["after"])

    def __eq__(self, other: object) -> bool:
        return type(other) is type(self) and _same_slots(self, other)

    __hash__ = None

    def __repr__(self) -> str:
        return f"<ValidRange {self.from_:g} .. {self.to:g} s>"


class Simulation:
    """A scenario made runnable on a path: ``"spiral"`` (the contest's Q1-Q3) or ``"turnaround"``
    (Q4, Q5; t = 0 where the head enters the S-curve).

    Moments past the end of the dragon's valid motion (where a handle would have to jump) raise
    ``InputError`` with ``.jam``. A Simulation may be shared by threads; it pickles (as its
    scenario and path: another process makes it anew) and compares equal by both.
    """

    def __init__(self, scenario: Optional[Scenario] = None, path: str = "spiral") -> None:
        self.scenario = scenario if scenario is not None else Scenario()
        self.path = path
        self._sim = _core._Simulation(_values(self.scenario), path)

    @property
    def valid_range(self) -> ValidRange:
        """Where the dragon can follow its path (searched once, then kept)."""
        return ValidRange(self._sim.valid_range())

    def frame(self, t: float) -> Frame:
        """The chain at time t (s)."""
        return Frame(self._sim.frame(float(t)))

    def frames(self, times: Iterable[float], *, workers: int = 0) -> Frames:
        """The chain at each of `times` (s), computed in parallel straight into numpy arrays, on
        `workers` threads (0: one per core) made for the call and joined before it returns."""
        return Frames(*self._sim.frames(_as_times(times), _workers(workers)), scenario=self.scenario, path=self.path)

    def to_pandas(self, times: Iterable[float]):
        """The frames at `times` in the tool's CSV layout: one row per handle per time, columns
        ``t, handle, x, y, speed`` (unrounded)."""
        import numpy as np
        import pandas as pd

        f = self.frames(times)
        t_count, h_count = f.speeds.shape
        return pd.DataFrame({
            "t": np.repeat(f.times, h_count),
            "handle": np.tile(np.arange(h_count), t_count),
            "x": f.positions[:, :, 0].ravel(),
            "y": f.positions[:, :, 1].ravel(),
            "speed": f.speeds.ravel(),
        })

    def time_of(self, travel: float) -> float:
        """The time (s) at which the head has travelled `travel` metres from its place at t = 0."""
        return self._sim.time_of(float(travel))

    def __reduce__(self):
        return (Simulation, (self.scenario, self.path))

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Simulation) and (self.scenario, self.path) == (other.scenario, other.path)

    def __hash__(self) -> int:
        return hash((self.scenario, self.path))

    def __repr__(self) -> str:
        return f"Simulation({self.scenario!r}, path={self.path!r})"


def _as_times(times: Iterable[float]):
    import numpy as np

    return np.ascontiguousarray(np.asarray(list(times) if not hasattr(times, "__array__") else times, dtype=float))


# ---- Progress --------------------------------------------------------------------------------


# As the tool draws its progress line: nothing before half a second (quick calls show nothing),
# then at most ten redraws a second.
_PROGRESS_FIRST = 0.5
_PROGRESS_EVERY = 0.1


def _in_jupyter() -> bool:
    """Whether this is a Jupyter kernel (whose front end shows the bar), not a plain interpreter."""
    ipython = sys.modules.get("IPython")
    shell = ipython.get_ipython() if ipython is not None else None
    return shell is not None and getattr(shell, "kernel", None) is not None


def _widgets_shown() -> bool:
    """Whether a Jupyter front end can show ipywidgets: version 7 on, whose messages today's front
    ends and nbconvert read (version 6, Debian 12's, opens its widgets in a form neither reads)."""
    try:
        import ipywidgets
    except ImportError:
        return False
    try:
        return int(str(ipywidgets.__version__).split(".")[0]) >= 7
    except ValueError:
        return False


def _progress_shown() -> bool:
    """Where the tool would show progress: stderr a terminal, or a Jupyter kernel. Never on a
    stderr redirected to a file or a pipe (a log would fill with redraws)."""
    if _in_jupyter():
        return True
    try:
        return sys.stderr is not None and sys.stderr.isatty()
    except (AttributeError, ValueError):  # no stderr, or a closed one
        return False


def _progress(progress, unit: str, description: str):
    """A (callback, closer) pair: the callback hears (done, total). progress=True shows a tqdm
    bar as the tool shows its progress line: only on a terminal or in Jupyter, not in the first
    half second, redrawn at most ten times a second (None is given to the library otherwise, so
    nothing is called); a callable is called as is, with every update; False or None shows
    nothing."""
    if callable(progress):
        return progress, lambda: None
    if not progress or not _progress_shown():
        return None, lambda: None
    try:
        if _in_jupyter() and _widgets_shown():
            from tqdm.notebook import tqdm
        else:  # a terminal, or a kernel with no widgets: tqdm's text line (Jupyter honours its \r)
            from tqdm import tqdm
    except ImportError:
        return None, lambda: None
    bar = None
    started = time.monotonic()
    drawn = 0.0

    def update(done: int, total: int) -> None:
        nonlocal bar, drawn
        now = time.monotonic()
        if now - started < _PROGRESS_FIRST or now - drawn < _PROGRESS_EVERY:
            return
        drawn = now
        if bar is None:
            bar = tqdm(total=total, unit=unit, desc=description, leave=False, mininterval=_PROGRESS_EVERY)
        bar.n = done
        bar.refresh()

    return update, lambda: bar.close() if bar is not None else None


# ---- The contest's questions -----------------------------------------------------------------


def _workers(workers: Any) -> int:
    """`workers` as the calls take it: 0 (one per core) or 1 to 1024 threads, made for the call and
    joined before it returns (nothing is left running, so a forked process finds no threads)."""
    if isinstance(workers, bool) or not isinstance(workers, int) or not 0 <= workers <= 1024:
        error = InputError(f"workers = {workers!r} is not allowed: give 0 (one per core) or 1 to 1024 threads")
        error.field, error.value, error.allowed, error.jam = "workers", repr(workers), "0 (one per core) or 1 to 1024", None
        raise error
    return workers


def collide(scenario: Optional[Scenario] = None, *, path: str = "spiral", from_: Moment = None,
            to: Moment = None, workers: int = 0, prove: bool = False) -> CollideResult:
    """Q2: the first moment two non-adjacent benches touch, to 1e-9 s (``dragon collide``).

    Searched over `from_` .. `to` (seconds, or head travel as "-100m"): by default on the plain
    spiral from t = 0 as far as the dragon can follow it, on the turnaround path 100 m of head
    travel either side of the turn. Benches already overlapping where the search starts are the
    answer's ``overlap_at_start`` (their benches and depth: the chain collided before it), as
    ``dragon collide --json`` says. `workers`: threads the search runs on (0: one per core),
    made for the call and joined before it returns.

    ``prove=True`` (``dragon collide --prove``) proves every step of the search contact-free by
    enclosing each bench over it: slower (about four times the evaluations on the contest's Q2),
    the same contact, and the result's ``enclosure`` and ``proof`` say what was proved (see
    :class:`CollideResult`). `prove` is True or False; anything else is an InputError naming it.
    """
    text, frame = _core._collide(_values(scenario), path, from_, to, _workers(workers), prove)
    result = CollideResult(json.loads(text))
    result.frame = Frame(frame) if frame is not None else None
    return result


def min_pitch(scenario: Optional[Scenario] = None, *, lo: Optional[float] = None, hi: Optional[float] = None,
              grid: float = 0.0025,
              progress: Union[bool, Callable[[int, int], None], None] = True, workers: int = 0,
              prove: bool = False) -> MinPitchResult:
    """Q3: the smallest pitch (m) with which the head reaches the turning space collision-free
    (``dragon min-pitch``), searched over `lo` .. `hi` on a first scan of spacing `grid`, each
    change of feasibility narrowed to 1e-9 m. Left out, `lo` and `hi` are the scenario's own range
    as the command searches it (0.35 .. 0.55 m, moved up for a dragon too wide for it).
    `progress` hears the first scan's runs; `workers` (0: one per core) runs the pitches.

    ``prove=True`` (``dragon min-pitch --prove``) proves every pitch of the feasible intervals
    feasible, not only the pitches run, by enclosing the benches over cells of head radius and
    pitch: slower (about 1.5 s of CPU for the contest). The result's ``proof`` says what was
    proved (see :class:`MinPitchResult`). `prove` is True or False; anything else is an
    InputError naming it."""
    callback, close = _progress(progress, "pitches", "min_pitch")
    try:
        return MinPitchResult(json.loads(_core._min_pitch(_values(scenario), None if lo is None else float(lo),
                                                          None if hi is None else float(hi), float(grid),
                                                          callback, _workers(workers), prove)))
    finally:
        close()


def turnaround(scenario: Optional[Scenario] = None, *, from_: Moment = None, to: Moment = None,
               clearance: bool = True, progress: Union[bool, Callable[[int, int], None], None] = True,
               workers: int = 0, prove: bool = False) -> TurnaroundResult:
    """Q4: the S-curve's design, whether it can be shorter (its length against the radius ratio
    and the entry radius, and whether this dragon can follow each), and over `from_` .. `to`
    (default: 100 m of head travel either side of the turn) its first contact and the smallest
    clearance before it (``dragon turnaround``; `clearance=False` leaves that check out).
    `workers`: threads the check runs on (0: one per core).

    ``prove=True`` (``dragon turnaround --prove``) proves every step of the first-contact check,
    as ``collide(prove=True)`` does; the result's ``enclosure`` and ``proof`` say what was proved
    (absent with `clearance=False`, which `prove=True` cannot go with)."""
    workers = _workers(workers)
    callback, close = _progress(progress, "samples", "turnaround")
    try:
        return TurnaroundResult(json.loads(_core._turnaround(_values(scenario), from_, to, bool(clearance), callback,
                                                             workers, prove)))
    finally:
        close()


def max_speed(scenario: Optional[Scenario] = None, *, limit: float = 2.0, from_: Moment = None,
              to: Moment = None, workers: int = 0, prove: bool = False) -> MaxSpeedResult:
    """Q5: the largest head speed (m/s) keeping every handle at or under `limit` (m/s) over the
    turnaround's window (default: 100 m of head travel either side of the turn) (``dragon max-speed``).
    `workers`: threads the search runs on (0: one per core).

    ``prove=True`` (``dragon max-speed --prove``) bounds every handle's speed over every stretch
    of the window: slower (about 1.4 times the search on two cores), and the result's ``enclosure`` holds
    the largest head speed (see :class:`MaxSpeedResult`). `prove` is True or False; anything
    else is an InputError naming it."""
    return MaxSpeedResult(json.loads(_core._max_speed(_values(scenario), float(limit), from_, to, _workers(workers),
                                                      prove)))


def solve(scenario: Optional[Scenario] = None, out: Union[None, str, os.PathLike] = None, *,
          only: Optional[Sequence[Union[int, str]]] = None, lo: Optional[float] = None, hi: Optional[float] = None,
          grid: float = 0.0025, limit: float = 2.0, from_: Moment = None, to: Moment = None,
          workers: int = 0, prove: bool = False) -> SolveResult:
    """The contest's five questions (``dragon solve``): the result is summary.json's content. With
    `out`, result1/2/4.xlsx and summary.json are written there too, all new or all as they were.
    `only` picks questions (``[1, 4]`` or ``["q1", "q4"]``); `lo`, `hi`, `grid` are Q3's range
    and scan, `limit` Q5's, `from_`/`to` the window of Q4's table and Q5's search; `workers` the
    threads it runs on (0: one per core). `prove` proves every answer as ``dragon solve --prove``
    does (each question's ``proof``, and Q4's check for a contact in ``q4["proof"]``)."""
    workers = _workers(workers)
    questions = []
    for q in only or []:
        questions.append(int(q[1:]) if isinstance(q, str) and q[:1] in "qQ" else int(q))
    text = _core._solve(_values(scenario), None if out is None else os.fspath(out), questions, lo, hi, float(grid),
                        float(limit), from_, to, workers, prove)
    return SolveResult(json.loads(text))


# ---- Pictures and films ----------------------------------------------------------------------


class Picture:
    """A moment drawn as ``dragon render`` draws it: the file's bytes in ``data`` (``format`` is
    "png", "svg" or "pdf"), shown inline by Jupyter, written by :meth:`save` all-or-nothing.
    ``time`` is the moment drawn (s), ``size`` (width, height) in pixels. Pictures pickle and
    compare equal by their bytes, format, moment and size."""

    def __init__(self, data: bytes, format: str, time: float, size: tuple, drawing: tuple) -> None:
        self.data = data
        self.format = format
        self.time = time
        self.size = size
        # What render() drew (the simulation and its keywords): to_numpy() draws it again as pixels.
        self._drawing = drawing

    def __reduce__(self):
        return (Picture, (self.data, self.format, self.time, self.size, self._drawing))

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Picture) and (self.data, self.format, self.time, tuple(self.size)) == (
            other.data, other.format, other.time, tuple(other.size))

    def __hash__(self) -> int:
        return hash((self.data, self.format, self.time))

    def _repr_png_(self) -> Optional[bytes]:
        return self.data if self.format == "png" else None

    def _repr_svg_(self) -> Optional[str]:
        return self.data.decode("utf-8") if self.format == "svg" else None

    def to_numpy(self):
        """The picture's pixels as a (height, width, 4) uint8 RGBA array (opaque: alpha 255)."""
        sim, when, collision, width, height, look, printed = self._drawing
        return _core._render_rgba(sim._sim, when, collision, width, height, look, printed, ASSETS)

    def save(self, path: Union[str, os.PathLike]) -> None:
        """Writes the picture to `path` as the tool writes its files: all new or as it was. The
        name's extension is the picture's format (``.png`` for a PNG); InputError otherwise."""
        _core._save_bytes(self.data, os.fspath(path), self.format)

    def __bytes__(self) -> bytes:
        return self.data

    def __repr__(self) -> str:
        return f"Picture({self.format}, {self.size[0]}x{self.size[1]} px, t = {self.time:.6f} s, {len(self.data)} bytes)"


def _picture_size(size: Sequence[int]) -> tuple:
    if isinstance(size, str) or len(size) != 2:
        raise InputError(f"size {size!r} is not allowed: give (width, height) in pixels")
    return int(size[0]), int(size[1])


def render(sim: Union[Simulation, Scenario, None] = None, t: Optional[float] = None, *, collision: bool = False,
           size: Sequence[int] = (1600, 1600), format: str = "png", theme: str = "light",
           speed_colours: bool = False, zoom: Optional[float] = None, centre: Optional[Sequence[float]] = None,
           follow_head: bool = False, guides: bool = True, text: bool = True, annotation: Optional[str] = None,
           legend: bool = False, inset: bool = False, lang: str = "en", print_size: Optional[str] = None,
           width_in: Optional[float] = None, width_cm: Optional[float] = None, font_pt: Optional[float] = None,
           dpi: Optional[float] = None) -> Picture:
    """One moment of the dragon drawn (``dragon render``): at time `t` (s), or at the motion's
    first contact with ``collision=True`` (the touching benches marked, the one every command
    reports).

    `size` is (width, height) in pixels; `format` "png", "svg" or "pdf" (vector, fonts embedded).
    `theme`: "light", "dark" or a .toml file. `speed_colours` colours each bench by its speed
    (m/s) with a colour bar. `zoom` shows a square this many metres wide, about the head, the
    contact, or `centre` (x, y in metres); `follow_head` centres on the head. `guides`, `text`,
    `legend`, `inset` switch the path, all text, the key to the colours and the whole-dragon
    inset; `annotation` replaces the top-left text ("" for none). `lang` is the language of the
    picture's own words: "en" or "zh" (the contest's terms: 龙头, 龙身, 龙尾, 把手).

    For a paper, a print size instead of pixels (the tool's --print flags): `print_size`
    "column", "page" or "a4", or `width_in` / `width_cm` on the page, `font_pt` for the body
    text and `dpi` for a PNG (default a 3.5 in column, 8 pt, 300 dpi); `size` then gives only
    the shape. SVG and PDF are pages of exactly that width; a PNG states its dpi.
    """
    if not isinstance(sim, Simulation):
        sim = Simulation(sim)
    width, height = _picture_size(size)
    look = {"theme": os.fspath(theme), "speed_colours": speed_colours, "zoom": zoom,
            "centre": None if centre is None else tuple(float(c) for c in centre), "follow_head": follow_head,
            "guides": guides, "text": text, "annotation": annotation, "legend": legend, "inset": inset, "lang": lang}
    when = None if t is None else float(t)
    printed = {"print_size": print_size, "width_in": width_in, "width_cm": width_cm, "font_pt": font_pt, "dpi": dpi}
    data, time, drawn_w, drawn_h = _core._render(sim._sim, when, bool(collision), width, height, format, look,
                                                 printed, ASSETS)
    return Picture(data, format, time, (drawn_w, drawn_h), (sim, when, bool(collision), width, height, look, printed))


def video(scenario: Optional[Scenario] = None, out: Union[str, os.PathLike] = "dragon.mp4", *, path: str = "spiral",
          from_: Moment = None, to: Moment = None, speedup: float = 10.0, hold: Optional[float] = None,
          fps: float = 30.0, size: Sequence[int] = (1280, 720), crf: Optional[int] = None,
          preset: Optional[str] = None, tune: Optional[str] = None, threads: Optional[int] = None,
          colours: Optional[int] = None, follow_head: bool = False,
          zoom: Optional[float] = None, theme: str = "light", speed_colours: bool = False, guides: bool = True,
          text: bool = True, legend: bool = True, inset: bool = True, lang: str = "en",
          progress: Union[bool, Callable[[int, int], None], None] = True, workers: int = 0) -> dict:
    """A film of the motion (``dragon video``) written to `out` (.mp4 H.264, .webm VP9 or .gif),
    all-or-nothing; returns what was written (frames, seconds, size, fps, encode_seconds).

    `from_` and `to` are moments: seconds, head travel as "-100m", and for `to` also
    "collision" (the first contact, marked; the default on the spiral), "boundary" (the head at
    the turning space) or "end" (the end of the valid motion). Defaults: 0 .. collision on the
    spiral, -100m .. 100m on the turnaround path. `speedup` is simulated seconds per second of
    film; `hold` seconds the last moment stays (1 at a collision). `crf`, `preset`, `tune`,
    `threads`, `colours` are the encoder's, as the tool's flags (None: the tool's defaults, a
    preset "faster" and tune "animation" for .mp4, a palette of 64 colours for .gif, 256 with
    `speed_colours`; a preset or tune for .webm or .gif, or colours for a video, is refused as
    the tool refuses it); `zoom` needs pixels doubles resolve, as the tool's; `lang` ("en" or "zh") the
    language of its captions, clock and legend; `workers` the threads that draw its frames (0:
    one per core). Ctrl-C stops it within a frame, leaving no file.
    """
    workers = _workers(workers)
    width, height = _picture_size(size)
    encoder = {"width": width, "height": height, "fps": float(fps), "crf": crf, "preset": preset, "tune": tune,
               "threads": threads, "colours": colours}
    look = {"theme": os.fspath(theme), "speed_colours": speed_colours, "zoom": zoom, "follow_head": follow_head,
            "guides": guides, "text": text, "legend": legend, "inset": inset, "lang": lang}
    callback, close = _progress(progress, "frames", "video")
    try:
        return _core._video(_values(scenario), path, os.fspath(out), from_, to, float(speedup), hold, encoder, look,
                            ASSETS, callback, workers)
    finally:
        close()


def film(storyboard: Union[str, os.PathLike], out: Union[str, os.PathLike], *, at: Optional[float] = None,
         size: Optional[Sequence[int]] = None, fps: Optional[float] = None, crf: Optional[int] = None,
         preset: Optional[str] = None, tune: Optional[str] = None, colours: Optional[int] = None,
         progress: Union[bool, Callable[[int, int], None], None] = True, workers: int = 0) -> dict:
    """A storyboard's shots assembled into one film (``dragon film``): `out` is .mp4, .webm or
    .gif, or .png with `at` (s into the film) for one poster frame. `size` (width, height) and
    `fps` override the storyboard's [film] settings; `crf`, `preset`, `tune`, `colours` are the
    encoder's; `workers` the threads that draw its frames (0: one per core). Storyboards are TOML
    (see ``ASSETS/films/contest.toml``); an old name in a scenario file a shot names is read with a
    ``FutureWarning`` naming the key to write instead."""
    workers = _workers(workers)
    encoder = {"crf": crf}
    if preset is not None:
        encoder["preset"] = preset
    if tune is not None:
        encoder["tune"] = tune
    if colours is not None:
        encoder["colours"] = colours
    dims = None if size is None else _picture_size(size)
    callback, close = _progress(progress, "frames", "film")
    try:
        return _core._film(os.fspath(storyboard), os.fspath(out), dims, fps, at, encoder, ASSETS, callback, workers,
                           lambda message: warnings.warn(message, FutureWarning, stacklevel=3))
    finally:
        close()


# ---- Sweeps ----------------------------------------------------------------------------------


def _axis(name: str, spec: Any) -> str:
    flag = name.replace("_", "-")
    if isinstance(spec, str):
        return f"{flag}={spec}"
    if isinstance(spec, (int, float)):
        spec = [spec]
    return f"{flag}=" + ",".join(repr(int(v)) if float(v).is_integer() and flag == "bench-count" else repr(float(v))
                                 for v in spec)


def _sweep_rows(spec: str, indices: Sequence[int], stop: Optional[Callable[[], bool]] = None) -> list:
    """A chunk of a sweep's rows (CSV lines), by index: what an executor's worker runs. Only
    text and numbers cross to it, so it runs in another process or on a Dask worker too."""
    return _core._sweep_rows(spec, list(indices), stop)


def _shard(shard: Any) -> str:
    """`shard` as the library reads it: "K/N" (None: the whole sweep)."""
    if shard is None:
        return ""
    if isinstance(shard, str):
        return shard
    if isinstance(shard, (tuple, list)) and len(shard) == 2 and all(isinstance(v, int) and not isinstance(v, bool)
                                                                   for v in shard):
        return f"{shard[0]}/{shard[1]}"
    allowed = 'give "K/N" or (K, N), the K-th of N parts'
    error = InputError(f"shard {shard!r} is not allowed: {allowed}")
    error.field, error.value, error.allowed, error.jam = "shard", repr(shard), allowed, None
    raise error


def _rows_frame(header: Sequence[str], rows: Iterable[tuple], spec: str):
    """The rows (scenario, CSV line) as the DataFrame sweep() returns: in the grid's order."""
    import pandas as pd

    text = ",".join(header) + "\n" + "".join(line + "\n" for _, line in sorted(rows, key=lambda r: r[0]))
    frame = pd.read_csv(io.StringIO(text))
    frame.attrs["sweep"] = spec[len("# dragon sweep "):]
    return frame


def sweep(vary: Mapping[str, Any], measure: Union[str, Sequence[str]], fixed: Optional[Mapping[str, float]] = None,
          *, lo: Union[None, float, str] = None, hi: Union[None, float, str] = None, grid: Optional[float] = None,
          limit: Optional[float] = None, from_: Moment = None, to: Moment = None,
          out: Union[None, str, os.PathLike] = None, resume: bool = False, shard: Union[None, str, Sequence[int]] = None,
          executor: Any = None, chunk: Optional[int] = None,
          progress: Union[bool, Callable[[int, int], None], None] = True):
    """Answers over the design space (``dragon sweep``), as a pandas DataFrame with the tool's
    columns: a column per varied value, then each measure's answer with its keys prefixed by the
    measure (``min-pitch.pitch``), then ``status``; a row per scenario, in the grid's order (the
    first value varies slowest).

    `vary` maps a scenario value (a Scenario keyword) to ``"FROM:TO:COUNT"`` or a sequence of
    values; `measure` is one or more of collide, min-pitch, turnaround, max-speed; `fixed` holds
    the other values (Scenario keywords). `lo`, `hi` (a pitch, or "width+X"), `grid` are
    min-pitch's, `limit` max-speed's, `from_`/`to` the window of collide, turnaround and
    max-speed. The rows are computed in chunks on `executor`: any object with
    ``submit(fn, *args)`` returning futures with ``result()`` (a ThreadPoolExecutor, a
    ProcessPoolExecutor, a Dask ``distributed.Client``, mpi4py's MPIPoolExecutor); by default a
    thread pool with a worker per core (the rows release the GIL).

    `out` (a .csv path) also writes the rows to a file exactly as ``dragon sweep -o`` does: into
    ``OUT.csv.partial``, each chunk's rows made durable as the chunk is done, renamed to `out`
    when all are there. ``resume=True`` goes on with such a file, the tool's or this function's,
    after a kill: the rows it holds are taken (checked, a torn last line cut off, failed rows made
    again) and only the rest computed; the DataFrame holds them all, and ``attrs["resumed"]``
    says how many came from the file (the lines the tool prints, "resuming: ...", go to the
    ``benchdragon`` logger). Without `resume`, an unfinished sweep's file is refused, never
    overwritten. A row whose measure failed (not the scenario's fault) leaves the file
    unfinished, with a RuntimeWarning: resume it to make that row again. `shard` ("K/N" or
    (K, N)) makes only the K-th of N disjoint parts, as the tool's ``--shard``; merge_sweep()
    joins the parts' files.
    """
    measures = [measure] if isinstance(measure, str) else list(measure)
    spec, header, count, part, parts = _core._sweep_setup([_axis(k, v) for k, v in vary.items()], measures,
                                                          dict(fixed or {}), lo, hi, grid, limit, from_, to,
                                                          _shard(shard))
    rows_file = None
    resumed: list = []
    if out is None:
        _core._check_sweep_output("", bool(resume))
        todo = list(range(part - 1, count, parts))
    else:
        rows_file = _core._SweepFile(spec, os.fspath(out), bool(resume))
        resumed = rows_file.resumed
        for note in rows_file.notes:
            logging.getLogger("benchdragon").info(note)
        todo = rows_file.todo()
    workers = os.cpu_count() or 1
    if chunk is None:
        chunk = max(1, min(64, len(todo) // (4 * workers) or 1))
    chunks = [todo[j:j + chunk] for j in range(0, len(todo), chunk)]
    own = executor is None
    if own:
        from concurrent.futures import ThreadPoolExecutor

        executor = ThreadPoolExecutor(max_workers=workers)
    threads = own or type(executor).__name__ == "ThreadPoolExecutor"
    stopping = threading.Event()
    callback, close = _progress(progress, "scenarios", "sweep")
    lines: list = [None] * len(chunks)
    failed = 0
    try:
        futures = [executor.submit(_sweep_rows, spec, c, stopping.is_set if threads else None) for c in chunks]
        done = 0
        try:
            # In the grid's order: each chunk's rows are appended (and made durable) once it and
            # those before it are done.
            for j, f in enumerate(futures):
                lines[j] = f.result()
                if rows_file is not None:
                    failed += rows_file.append(chunks[j], lines[j])
                done += len(chunks[j])
                if callback:
                    callback(done, len(todo))
        except BaseException:
            stopping.set()
            for f in futures:
                f.cancel()
            raise
    finally:
        close()
        if own:
            executor.shutdown(wait=True, cancel_futures=True)
    if rows_file is not None:
        if failed == 0:
            rows_file.finish()
        else:
            warnings.warn(f"{failed} of {len(todo)} rows failed (their status says why): the rows stay in "
                          f"{rows_file.partial}, and resume=True makes the failed ones again", RuntimeWarning,
                          stacklevel=2)
    made = ((scenario, line) for c, chunk_lines in zip(chunks, lines) for scenario, line in zip(c, chunk_lines))
    frame = _rows_frame(header, [*resumed, *made], spec)
    frame.attrs["resumed"] = len(resumed)
    return frame


def merge_sweep(out: Union[str, os.PathLike], parts: Sequence[Union[str, os.PathLike]]):
    """A sweep's parts (the files of its shards, the tool's or sweep()'s) joined into `out` (a
    .csv), as ``dragon sweep merge OUT.csv PART.csv...`` joins them, byte for byte: the rows in
    the files' order, every scenario checked to be there exactly once, `out` written
    all-or-nothing. Returns the whole sweep as sweep() would (a DataFrame in the grid's order,
    ``attrs["sweep"]`` the whole sweep's description). Raises InputError naming the file and the
    line at fault: a part of another sweep, a torn last line (resume that part first), a row that
    is no scenario of the sweep, a scenario twice, or scenarios missing."""
    spec, header, rows = _core._merge_sweep(os.fspath(out), [os.fspath(p) for p in parts])
    return _rows_frame(header, rows, spec)
