"""plyimpact from Python: decks, laminates and impact runs as Python objects.

    import plyimpact
    deck = plyimpact.load("examples/thesis-3.6-v268.toml")
    run = plyimpact.impact(deck.replace({"impactor.velocity": 2.0}))
    print(run.summary["peak_force"], run.history["force_N"].max())

Everything runs in the C++ engine that the ``plyimpact`` command runs (the deck parser, the impact
facade, the summary of ``summary.json``); this package only turns its results into dicts and numpy
arrays. The engine releases the GIL, so cases run side by side on Python threads. Units are SI
(docs/deck.md); history columns carry their unit in their name, as in ``history.csv``.
"""
from __future__ import annotations

import csv
import io
import json
import os
import tempfile
import tomllib
from typing import Any, Iterator, Mapping

import numpy as np

# CHOLMOD runs parts of its factorization on an OpenMP team of every core. Cases on several Python
# threads would each start such a team and oversubscribe the cores (2 threads ran 8 cases in 0.65x the
# time of 1 thread with it, 0.50x without: bench/README.md). So one OpenMP thread per case, unless the
# user has set OMP_NUM_THREADS; libgomp reads it when _core loads CHOLMOD, just below.
os.environ.setdefault("OMP_NUM_THREADS", "1")

try:
    from . import _core  # noqa: E402 (after the OpenMP setting)
except ImportError as missing:  # the package's files without the compiled module beside them
    raise ImportError(
        "plyimpact's compiled module (_core) is not built beside " + os.path.dirname(__file__) + ": build it "
        "with `cmake --build --preset release --target plyimpact_python` (./scripts/test builds it too; "
        "docs/python.md)") from missing
from ._core import DeckError, FolderHoldsResults, FolderInUse  # noqa: E402

__version__: str = _core.__version__

__all__ = [
    "Deck",
    "DeckError",
    "FolderHoldsResults",
    "FolderInUse",
    "ImpactRun",
    "ImpactStudy",
    "Laminate",
    "deck",
    "impact",
    "laminate",
    "buckling",
    "load",
    "modal",
    "parse",
    "static",
    "sweep",
    "threshold",
]


def _toml_text(values: Mapping[str, Any]) -> str:
    import tomli_w  # Debian python3-tomli-w; only needed to write decks

    return tomli_w.dumps(values)


def _flatten(values: Mapping[str, Any], prefix: str = "") -> Iterator[tuple[str, Any]]:
    for key, value in values.items():
        dotted = f"{prefix}{key}"
        if isinstance(value, Mapping):
            yield from _flatten(value, dotted + ".")
        else:
            yield dotted, value


class Deck:
    """A validated deck: read-only, dict-like by dotted key (``deck["impactor.velocity"]``).

    ``replace`` returns a new deck with some values changed; it is validated again, exactly like a
    deck file (a bad value raises :class:`DeckError` naming the key).
    """

    def __init__(self, core: _core.Deck):
        self._core = core
        self._tree: dict[str, Any] | None = None

    @property
    def source(self) -> str:
        """The file name (or the name given) used in messages."""
        return self._core.source

    @property
    def text(self) -> str:
        """The deck's TOML text, as recorded in a results folder's deck.toml."""
        return self._core.text

    @property
    def title(self) -> str:
        return self._core.title

    @property
    def analysis(self) -> str:
        """The deck's analysis: impact, static, modal, buckling, threshold or laminate."""
        return self._core.analysis

    @property
    def warnings(self) -> list[str]:
        """Plausibility warnings (values that look like unit slips), as the command prints them."""
        return list(self._core.warnings)

    def to_dict(self) -> dict[str, Any]:
        """The deck's tables and values as written (a fresh copy, free to edit)."""
        return tomllib.loads(self.text)

    def _values(self) -> dict[str, Any]:
        if self._tree is None:
            self._tree = self.to_dict()
        return self._tree

    def __getitem__(self, key: str) -> Any:
        node: Any = self._values()
        for part in key.split("."):
            if not isinstance(node, dict) or part not in node:
                raise KeyError(f"{self.source}: the deck has no key '{key}'")
            node = node[part]
        return node

    def get(self, key: str, default: Any = None) -> Any:
        try:
            return self[key]
        except KeyError:
            return default

    def __contains__(self, key: str) -> bool:
        return self.get(key, _missing) is not _missing

    def keys(self) -> list[str]:
        """Every value's dotted key, in the order written."""
        return [k for k, _ in _flatten(self._values())]

    def replace(self, values: Mapping[str, Any] | None = None, /, **tables: Mapping[str, Any]) -> "Deck":
        """A new deck with values replaced: by dotted key (``{"impactor.velocity": 3.0}``) and/or by
        table (``impactor={"velocity": 3.0}``). Tables and keys that do not exist are added."""
        tree = self.to_dict()
        changed = dict(values or {})
        for table, entries in tables.items():
            changed.update({f"{table}.{k}": v for k, v in _flatten(entries)})
        for key, value in changed.items():
            node = tree
            parts = key.split(".")
            for part in parts[:-1]:
                node = node.setdefault(part, {})
                if not isinstance(node, dict):
                    raise DeckError(f"{self.source}: cannot set '{key}': '{part}' is a value, not a table")
            node[parts[-1]] = value
        edited = ", ".join(f"{k} = {v!r}" for k, v in changed.items())
        _anchor_mesh_file(tree, self.source)
        return parse(_toml_text(tree), source=f"{self.source} (with {edited})")

    def __repr__(self) -> str:
        return f"<plyimpact.Deck {self.source!r}: {self.analysis}, {self.title!r}>"


_missing = object()


def _anchor_mesh_file(tree: dict[str, Any], source: str) -> None:
    """A deck's ``[mesh] file`` (or ``geo``) is relative to the deck's folder; an edited deck is named after
    its edits, not a file, so the path is made absolute from the folder of the deck it came from."""
    mesh = tree.get("mesh")
    for key in ("file", "geo"):
        if isinstance(mesh, dict) and isinstance(mesh.get(key), str) and not os.path.isabs(mesh[key]):
            mesh[key] = os.path.abspath(os.path.join(os.path.dirname(source), mesh[key]))


def load(path: str | os.PathLike[str]) -> Deck:
    """Reads and validates a deck file (docs/deck.md). Raises DeckError with file:line:column."""
    return Deck(_core.load_deck(os.fspath(path)))


def parse(text: str, source: str = "<string>") -> Deck:
    """Validates deck text; ``source`` names it in messages."""
    return Deck(_core.parse_deck(text, source))


def deck(values: Mapping[str, Any], source: str = "<dict>") -> Deck:
    """A deck built from Python values, table by table as a deck file writes them::

        plyimpact.deck({"materials": {"cfrp": {...}}, "laminate": {...}, "plate": {...}, ...})
    """
    return parse(_toml_text(values), source)


class ImpactRun:
    """The result of an impact: ``summary`` (the dict of summary.json), ``history`` (numpy arrays
    keyed by the columns of history.csv) and ``notes`` (what the run could not do)."""

    def __init__(self, summary: dict[str, Any], notes: list[str], columns: list[str], rows: np.ndarray):
        self.summary = summary
        self.notes = notes
        self.history = {name: rows[:, j].copy() for j, name in enumerate(columns)}

    @property
    def warnings(self) -> list[str]:
        """What the run suspects of its own result (also in summary.json)."""
        return list(self.summary.get("warnings", []))

    def __getitem__(self, key: str) -> Any:
        return self.summary[key]

    def __repr__(self) -> str:
        peak = self.summary.get("peak_force")
        return f"<plyimpact.ImpactRun peak_force={peak!r} N, {len(next(iter(self.history.values()), []))} rows>"


def impact(
    case: Deck | str | os.PathLike[str],
    output_dir: str | os.PathLike[str] | None = None,
    *,
    overwrite: bool = False,
    nonlinear: bool = False,
    history: bool = True,
) -> ImpactRun:
    """Runs the impact of a deck (or a deck file) as ``plyimpact impact DECK [-o output_dir]`` does.

    With ``output_dir`` the results folder is written too (summary.json, history.csv, ...);
    ``nonlinear`` is the command's ``--nonlinear``; ``history=False`` keeps no history in memory.
    """
    d = case if isinstance(case, Deck) else load(case)
    out = None if output_dir is None else os.fspath(output_dir)
    summary, notes, columns, rows = _core.run_impact(d._core, out, overwrite, nonlinear, history)
    return ImpactRun(json.loads(summary), list(notes), list(columns), rows)


class ImpactStudy:
    """A plate built once and hit by many impactors: the matrices, the factorization and, for a linear
    plate under a point load with the trapezoidal rule, the plate's impulse response at the impact point
    (one run's worth of work) are kept, so each further impactor on a linear plate costs a convolution
    (docs/sweep.md, "Reusing the plate's response"). ``run`` takes the keys of ``[impactor]`` and
    ``contact_k`` and returns summary.json's dict with ``plate_response`` ("contact point" or "full").
    The time step must not change between runs: give ``[time] dt`` a number, not "auto"."""

    def __init__(self, case: Deck | str | os.PathLike[str], *, nonlinear: bool = False):
        self.deck = case if isinstance(case, Deck) else load(case)
        self._core = _core.ImpactStudy(self.deck._core, nonlinear)

    def run(self, *, contact_k: float | None = None, **impactor: Any) -> dict[str, Any]:
        """The impact of the study's plate by the deck's impactor with ``impactor`` keys replaced
        (``velocity=3.0``, ``mass=0.5``, ...) and ``contact_k`` as ``[contact] k``."""
        values: dict[str, Any] = {f"impactor.{k}": v for k, v in impactor.items()}
        if contact_k is not None:
            values["contact.k"] = contact_k
        d = self.deck.replace(values) if values else self.deck
        return json.loads(self._core.run(d._core))

    def __repr__(self) -> str:
        return f"<plyimpact.ImpactStudy {self.deck.source!r}>"


class Laminate:
    """A laminate's stiffness and inertia, as ``plyimpact laminate --json`` reports them (SI).

    ``Laminate("[45/90/-45/0]3s", material, ply_thickness=0.19375e-3)`` with ``material`` a dict of
    the deck's material keys (E1, E2, G12, G13, G23, nu12, rho, ...) or a Deck with a [laminate].
    A, B, D (3×3) and F (2×2, transverse shear) are numpy arrays.
    """

    def __init__(self, layup: str | Deck, material: Mapping[str, Any] | None = None, ply_thickness: float | None = None):
        if isinstance(layup, Deck):
            source = layup
        else:
            if material is None or ply_thickness is None:
                raise TypeError("Laminate(layup, material, ply_thickness): give the material and the ply thickness")
            source = deck(
                {
                    "analysis": "laminate",
                    "materials": {"ply": dict(material)},
                    "laminate": {"material": "ply", "layup": layup, "ply_thickness": ply_thickness},
                },
                source=f"Laminate({layup!r})",
            )
        self.report: dict[str, Any] = json.loads(_core.laminate_json(source._core))
        for name in ("A", "B", "D", "F"):
            setattr(self, name, np.array(self.report[name], dtype=float))
        self.thickness: float = self.report["thickness"]
        self.plies: list[dict[str, Any]] = self.report["plies"]
        self.inertia = np.array(self.report["inertia"], dtype=float)

    @property
    def ABD(self) -> np.ndarray:
        """The 6×6 in-plane and bending stiffness [[A, B], [B, D]]."""
        return np.block([[self.A, self.B], [self.B, self.D]])

    def __repr__(self) -> str:
        return f"<plyimpact.Laminate {self.report['layup']!r}, {len(self.plies)} plies, h = {self.thickness:g} m>"


def laminate(case: Deck | str | os.PathLike[str]) -> Laminate:
    """The laminate of a deck (or a deck file)."""
    return Laminate(case if isinstance(case, Deck) else load(case))


def _plate_analysis(kind: str, case: Any, output_dir: Any, overwrite: bool, nonlinear: bool = False) -> dict[str, Any]:
    d = case if isinstance(case, Deck) else load(case)
    out = None if output_dir is None else os.fspath(output_dir)
    _text, summary = _core.run_plate_analysis(d._core, kind, out, overwrite, nonlinear)
    return json.loads(summary)


def static(
    case: Deck | str | os.PathLike[str],
    output_dir: str | os.PathLike[str] | None = None,
    *,
    overwrite: bool = False,
    nonlinear: bool = False,
) -> dict[str, Any]:
    """``plyimpact static DECK [-o DIR] [--nonlinear]``: the dict of its summary.json (deflections [m])."""
    return _plate_analysis("static", case, output_dir, overwrite, nonlinear)


def modal(
    case: Deck | str | os.PathLike[str], output_dir: str | os.PathLike[str] | None = None, *, overwrite: bool = False
) -> dict[str, Any]:
    """``plyimpact modal DECK [-o DIR]``: the dict of its summary.json (``frequencies_hz``, ...)."""
    return _plate_analysis("modal", case, output_dir, overwrite)


def buckling(
    case: Deck | str | os.PathLike[str], output_dir: str | os.PathLike[str] | None = None, *, overwrite: bool = False
) -> dict[str, Any]:
    """``plyimpact buckling DECK [-o DIR]``: the dict of its summary.json (``load_factors``, ...)."""
    return _plate_analysis("buckling", case, output_dir, overwrite)


def threshold(
    case: Deck | str | os.PathLike[str],
    criterion: str = "",
    *,
    tolerance: float = 0.0,
    nonlinear: bool = False,
) -> dict[str, Any]:
    """The smallest impact velocity at which ``criterion`` is reached (``plyimpact threshold``): the
    dict of its summary.json (``threshold_velocity``, ``trials``, ...; no ``wall_time``).

    ``criterion`` and ``tolerance`` default to the deck's [threshold] (the command's --criterion and
    --tolerance)."""
    d = case if isinstance(case, Deck) else load(case)
    return json.loads(_core.run_threshold(d._core, criterion, tolerance, nonlinear))


def _value_text(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return repr(value)  # the shortest text that reads back to the same double
    text = str(value)
    if "," in text:
        raise ValueError(f"sweep value {text!r}: a swept string cannot contain a comma")
    return text


class SweepTable:
    """sweep.csv as columns: ``columns[name]`` is a numpy array for numbers, a list otherwise; ``text``
    is the file's text (byte-identical to ``plyimpact sweep``'s table)."""

    def __init__(self, text: str, factorizations: int):
        self.text = text
        self.factorizations = factorizations
        rows = list(csv.reader(io.StringIO(text)))
        self.names: list[str] = rows[0] if rows else []
        self.columns: dict[str, Any] = {}
        for j, name in enumerate(self.names):
            values = [r[j] for r in rows[1:]]
            try:
                self.columns[name] = np.array([float(v) if v != "" else np.nan for v in values])
            except ValueError:
                self.columns[name] = values

    def __getitem__(self, name: str) -> Any:
        return self.columns[name]

    def __len__(self) -> int:
        return max((len(c) for c in self.columns.values()), default=0)

    def __repr__(self) -> str:
        return f"<plyimpact.SweepTable {len(self)} cases x {len(self.names)} columns>"


def sweep(
    case: Deck | str | os.PathLike[str],
    values: Mapping[str, Any] | None = None,
    *,
    mode: str = "",
    jobs: int = 1,
    output_dir: str | os.PathLike[str] | None = None,
    overwrite: bool = False,
) -> SweepTable:
    """A parameter sweep through the sweep engine of ``plyimpact sweep`` (threads; MPI stays with the
    command line). ``values`` maps dotted keys to lists of values, or to a "start:stop:count" range,
    like ``--set``; the deck's own [sweep] table applies too. ``mode`` is "product" or "zip".

    The cases are recorded in ``output_dir`` (a temporary folder when None; a folder with records of
    the same sweep resumes them). Returns the table of sweep.csv."""
    d = case if isinstance(case, Deck) else load(case)
    options = []
    for key, v in (values or {}).items():
        listed = v if isinstance(v, str) else ",".join(_value_text(x) for x in v)
        options.append(f"{key}={listed}")
    if mode not in ("", "product", "zip"):
        raise ValueError(f"sweep mode {mode!r}: expected 'product' or 'zip'")

    def run(folder: str) -> SweepTable:
        text, factorizations, missing, failed = _core.run_sweep(d._core, options, mode, folder, jobs, overwrite)
        if missing:
            raise RuntimeError(f"sweep: {missing} cases have no record (interrupted?); run again to resume")
        return SweepTable(text, factorizations)

    if output_dir is not None:
        return run(os.fspath(output_dir))
    with tempfile.TemporaryDirectory(prefix="plyimpact-sweep-") as folder:
        return run(folder)
