"""gearkit from Python: gear pairs, gear trains and planar mechanisms (docs/python.md).

The numbers come from gearkit's C++ libraries (libgear, libtrain, libkin) through the extension
module ``gearkit._gearkit``; the files are read by the same readers as the ``gearkit`` command,
and bad input raises ``ValueError`` with the command's exit-2 message. Quantities are given as
plain SI floats (metres, radians, rad/s, N*m) or as strings with their unit ("3 mm", "20 deg").

Build tree: ``PYTHONPATH=build/python python3 -c "import gearkit"``.
"""

from __future__ import annotations

import copy
import json
import os
from fractions import Fraction

from . import _gearkit
from ._layout import PLUGIN_DIR as _PLUGIN_DIR

__version__ = _gearkit.__version__

__all__ = [
    "Result",
    "GearPair",
    "gear_pair",
    "read_gear_pair",
    "Train",
    "solve_train",
    "Mechanism",
    "Position",
    "Sweep",
]


def _wrap(value):
    if isinstance(value, dict):
        return Result(value)
    if isinstance(value, list):
        return [_wrap(v) for v in value]
    return value


class Result:
    """A result as attributes: ``r.pair.a_mm`` reads ``r.to_dict()["pair"]["a_mm"]``.

    Keys carry their unit as the JSON of the ``gearkit`` command does (``d_a_mm``, ``alpha_wt_deg``,
    ``rad_s``). Nested dictionaries come back as Result objects, lists as lists.
    """

    __slots__ = ("_data",)

    def __init__(self, data: dict):
        object.__setattr__(self, "_data", data)

    def __getattr__(self, name):
        if name.startswith("_"):  # not a key: copy and pickle probe for special names
            raise AttributeError(name)
        try:
            return _wrap(self._data[name])
        except KeyError:
            raise AttributeError(f"{type(self).__name__} has no attribute {name!r} "
                                 f"(it has {', '.join(sorted(map(str, self._data)))})") from None

    def __setattr__(self, name, value):
        raise AttributeError(f"{type(self).__name__} is read-only")

    def __getitem__(self, key):
        return _wrap(self._data[key])

    def __contains__(self, key):
        return key in self._data

    def __dir__(self):
        own = {n for cls in type(self).__mro__ for n in vars(cls) if not n.startswith("_")}
        return sorted(set(map(str, self._data)) | own)

    def keys(self):
        return self._data.keys()

    def __reduce__(self):  # copy and pickle rebuild it from its dictionary
        return (type(self), (self._data,))

    def to_dict(self) -> dict:
        """A deep copy of the result as plain dictionaries, lists and numbers."""
        return copy.deepcopy(self._data)

    def __eq__(self, other):
        return isinstance(other, Result) and self._data == other._data

    def __repr__(self):
        keys = ", ".join(list(map(str, self._data))[:8])
        more = ", ..." if len(self._data) > 8 else ""
        return f"<{type(self).__name__}: {keys}{more}>"


# ---- gear pairs (libgear) ------------------------------------------------------------------

class GearPair(Result):
    """A gear pair's table (ISO 21771 symbols) and, when rated, its load capacity.

    The dictionary is the JSON of ``gearkit gear ... --format json``: ``gears`` (gear 1, gear 2),
    ``pair``, ``warnings`` and, for a pair file with a ``load:`` section, ``rating``.
    ``gear1`` and ``gear2`` are ``gears[0]`` and ``gears[1]``.
    """

    __slots__ = ()

    @property
    def gear1(self) -> Result:
        return Result(self._data["gears"][0])

    @property
    def gear2(self) -> Result:
        return Result(self._data["gears"][1])

    @property
    def rating(self):
        """The load capacity (``None`` when the pair has no load)."""
        r = self._data.get("rating")
        return None if r is None else Result(r)


def gear_pair(*, z1: int, z2: int, module, pressure_angle=None, helix_angle=0.0, x1=None, x2=None,
              centre_distance=None, split: str = "", face_width=0.0, allowance1=0.0, allowance2=0.0,
              internal: bool = False, transverse: bool = False, tip_shortening: bool = True) -> GearPair:
    """The gear table of a cylindrical involute pair (libgear ``compute_gear_pair``).

    Lengths in metres or as strings with a unit ("8 mm"), angles in radians or "20 deg".
    ``module`` is m_n (m_t with ``transverse=True``); ``pressure_angle`` alpha_n (default 20 deg);
    ``helix_angle`` beta of gear 1 (positive: right hand). Give the profile shifts ``x1``, ``x2`` or
    a ``centre_distance`` (then ``x1`` fixes the split, else ``split`` = "balanced" (equal
    maximum specific sliding), "proportional" or "min-shift"). ``internal=True`` makes gear 2 a
    ring. ``allowance1``/``allowance2``: normal tooth thickness allowances A_sn (<= 0).
    Raises ValueError naming the argument at fault.
    """
    return GearPair(json.loads(_gearkit.gear_pair_json(
        z1=z1, z2=z2, module=module, pressure_angle=pressure_angle, helix_angle=helix_angle, x1=x1, x2=x2,
        centre_distance=centre_distance, split=split, face_width=face_width, allowance1=allowance1,
        allowance2=allowance2, internal=internal, transverse=transverse, tip_shortening=tip_shortening)))


def read_gear_pair(path) -> GearPair:
    """A gear-pair file (docs/rating.md): its table and, with a ``load:`` section, its rating,
    the same numbers and warnings as ``gearkit gear FILE --format json``.
    Raises ValueError with file:line:column for bad input."""
    return GearPair(json.loads(_gearkit.gear_pair_file_json(os.fspath(path))))


# ---- gear trains (libtrain) ----------------------------------------------------------------

def _fraction(text):
    return None if text is None else Fraction(text)


def _strings(value, name):
    if value is None:
        return []
    if isinstance(value, str):
        return [value]
    if isinstance(value, dict):
        return [f"{k}={v}" for k, v in value.items()]
    try:
        return [str(v) for v in value]
    except TypeError:
        raise ValueError(f"argument '{name}': expected a string or a list of strings, found {type(value).__name__}") from None


class Train(Result):
    """A gear train solved under its conditions (libtrain, exact rational arithmetic).

    ``ratio``: w_output / w_input as a ``fractions.Fraction`` (``None`` without one input and an
    output); ``speed_ratios``: each member's speed per unit input speed (single input) as
    Fractions, ``None`` for a member the conditions leave free; ``speeds_rad_s``: the speeds
    for the given input speeds; ``power_flow``: torques [N*m], powers [W] and the efficiency
    when a torque was given.
    """

    __slots__ = ()

    @property
    def ratio(self):
        return _fraction(self._data["ratio"])

    @property
    def speeds_per_input(self) -> dict:
        """{member: [Fraction per input] or None}: w = sum_i f_i * (speed of input i)."""
        return {m: None if f is None else [Fraction(x) for x in f] for m, f in self._data["speeds"]["per_input"].items()}

    @property
    def speed_ratios(self) -> dict:
        """{member: Fraction or None}: w_member / w_input for a train with one input."""
        if len(self._data["inputs"]) != 1:
            raise ValueError(f"speed ratios need exactly one input, the train has {len(self._data['inputs'])}")
        return {m: None if f is None else f[0] for m, f in self.speeds_per_input.items()}

    @property
    def speeds_rad_s(self) -> dict:
        return dict(self._data["speeds"]["rad_s"])

    @property
    def power_flow(self):
        p = self._data["power_flow"]
        return None if p is None else Result(p)

    @property
    def efficiency_exact(self):
        p = self._data["power_flow"]
        return None if p is None else _fraction(p["efficiency_exact"])


def solve_train(path, *, fix=None, couple=None, input=None, output=None, torque=None, mesh_efficiency=1.0) -> Train:
    """Loads a train file (docs/train.md) and solves its speeds exactly.

    Conditions as ``gearkit train`` takes them: ``fix="ring"`` (or a list), ``couple="5=1"``,
    ``input="sun=3000 rpm"`` (or ``{"sun": "3000 rpm"}``; a speed needs its unit), ``output="carrier"``;
    without any, the file's ``analysis:`` section. ``torque="sun=10 N*m"`` adds the power flow.
    ``mesh_efficiency``: eta_0 of meshes without their own. Raises ValueError for bad input.
    """
    return Train(_gearkit.solve_train(os.fspath(path), fix=_strings(fix, "fix"), couple=_strings(couple, "couple"),
                                      input=_strings(input, "input"), output=output, torque=torque,
                                      mesh_efficiency=float(mesh_efficiency)))


# ---- mechanisms (libkin) -------------------------------------------------------------------

def _plugin_dir():
    return os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), _PLUGIN_DIR))


class Position(Result):
    """The mechanism at one input: ``q``, ``qd``, ``qdd`` (NumPy arrays, x [m], y [m], theta [rad]
    per body, see ``Mechanism.coordinates``), ``outputs`` {name: (value, rate, acceleration)} in SI,
    ``converged``, ``singular``, ``message``."""

    __slots__ = ()


class Sweep(Result):
    """A sweep of one driver: NumPy arrays filled by the C++ sweep without per-row copies.

    ``input`` (n,), ``q``/``qd``/``qdd`` (n, coordinates), ``values``/``rates``/``accelerations``
    (n, outputs) in SI (m, rad, per second, per second squared), ``on_change_point`` (n,);
    ``dead_points`` [(input, description)], ``change_points`` [(input, bifurcation, switched)],
    ``complete``, ``message``. ``output(name)`` is one output's value column.
    """

    __slots__ = ()

    def output(self, name: str):
        """The values of output ``name`` over the sweep (a view of ``values``)."""
        names = self._data["output_names"]
        if name not in names:
            raise ValueError(f"argument 'name': expected an output of the mechanism ({', '.join(names)}), found {name!r}")
        return self._data["values"][:, names.index(name)]

    def to_dataframe(self):
        """A pandas DataFrame, one row per position: input, each output with its rate and
        acceleration (``<name>``, ``<name>_rate``, ``<name>_acceleration``), then the coordinates."""
        import pandas as pd

        d = self._data
        columns = {"input": d["input"]}
        for i, name in enumerate(d["output_names"]):
            columns[name] = d["values"][:, i]
            columns[f"{name}_rate"] = d["rates"][:, i]
            columns[f"{name}_acceleration"] = d["accelerations"][:, i]
        for i, name in enumerate(d["coordinate_names"]):
            columns[name] = d["q"][:, i]
        return pd.DataFrame(columns)

    def __len__(self):
        return len(self._data["input"])


class Mechanism:
    """A mechanism file (docs/kin.md) read into the planar solver, as ``gearkit kin`` reads it.

    Element types of other plugins (gear meshes, cams) are found in the plugins of this build
    or install. Raises ValueError with file:line:column for a bad file.
    """

    def __init__(self, path):
        self._m = _gearkit.Mechanism(os.fspath(path), _plugin_dir())

    @property
    def title(self) -> str:
        return self._m.title

    @property
    def coordinates(self) -> list:
        """Names of the coordinates: ``<link>.x``, ``<link>.y``, ``<link>.theta`` per link."""
        return self._m.coordinates

    @property
    def outputs(self) -> list:
        return self._m.outputs

    @property
    def drivers(self) -> list:
        return self._m.drivers

    def dof(self) -> Result:
        """Degrees of freedom at the drawn configuration: Gruebler count and the rank of Phi_q."""
        return Result(self._m.dof())

    def solve(self, at, *, driver=None) -> Position:
        """Solves at input ``at`` of ``driver`` (default: the first), in rad or m or with a unit
        ("30 deg"), from the drawn configuration; velocities and accelerations at the driver's speed."""
        return Position(self._m.solve(at, driver))

    def sweep(self, start=None, end=None, step=None, *, driver=None, switch_branch=False) -> Sweep:
        """Sweeps ``driver`` from ``start`` to ``end`` by ``step`` (default: the driver's ``range`` in
        the file), starting on the drawing's branch as ``gearkit kin --sweep`` does."""
        if start is None or end is None or step is None:
            r = self._m.driver_range(driver)
            if r is None:
                raise ValueError("argument 'start': the driver has no range in the file; give start, end and step")
            start, end, step = (r[i] if v is None else v for i, v in enumerate((start, end, step)))
        d = self._m.sweep(start, end, step, driver, switch_branch)
        d["output_names"] = self._m.outputs
        d["coordinate_names"] = self._m.coordinates
        return Sweep(d)

    def __repr__(self):
        return f"<Mechanism {self.title!r}: {len(self.coordinates)} coordinates, drivers {self.drivers}>"
