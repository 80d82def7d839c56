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
import math
import numbers
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


# ---------------------------------------------------------------------------------------------------------
# Arguments of the wrong type are refused where they are given, naming the function, the argument (or the
# deck key) and what it must be (docs/robustness.md, "Python"), not deep inside with a raw AttributeError.

_PathLike = (str, bytes, os.PathLike)


def _type_name(value: Any) -> str:
    return type(value).__name__


def _require(value: Any, types: Any, where: str, expected: str) -> None:
    """Raises TypeError "where must be expected, got TYPE VALUE" unless value is one of types (bool is
    not a number here)."""
    if isinstance(value, bool) and bool not in (types if isinstance(types, tuple) else (types,)):
        ok = False
    else:
        ok = isinstance(value, types)
    if not ok:
        raise TypeError(f"{where} must be {expected}, got {_type_name(value)} {value!r}")


def _as_deck(case: Any, where: str) -> "Deck":
    """A Deck, or the deck file a path names."""
    if isinstance(case, Deck):
        return case
    _require(case, _PathLike, f"{where}: case", "a plyimpact.Deck or the path of a deck file")
    return load(case)


def _output_dir(output_dir: Any, where: str) -> str | None:
    if output_dir is None:
        return None
    _require(output_dir, _PathLike, f"{where}: output_dir", "a folder path or None")
    return os.fsdecode(os.fspath(output_dir))


def _flag(value: Any, where: str) -> bool:
    _require(value, bool, where, "True or False")
    return value


def _require_values(values: Any, where: str) -> None:
    """A mapping of dotted deck keys (strings) to values."""
    _require(values, Mapping, where, 'a mapping of dotted deck keys to values, e.g. {"impactor.velocity": 3.0}')
    for key in values:
        _require(key, str, f"{where}: key {key!r}", 'a dotted deck key (a string such as "impactor.velocity")')


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
        _require(key, str, "Deck[key]: key", 'a dotted deck key (a string such as "impactor.velocity")')
        node: Any = self._values()
        for part in key.split("."):
            if not isinstance(node, dict) or part not in node:
                raise KeyError(f"{self.source}: the deck has no key '{key}'")
            node = node[part]
        return node

    def get(self, key: str, default: Any = None) -> Any:
        _require(key, str, "Deck.get: key", 'a dotted deck key (a string such as "impactor.velocity")')
        try:
            return self[key]
        except KeyError:
            return default

    def __contains__(self, key: object) -> bool:
        return isinstance(key, str) and self.get(key, _missing) is not _missing

    def keys(self) -> list[str]:
        """Every value's dotted key, in the order written."""
        return [k for k, _ in _flatten(self._values())]

    def replace(self, values: Mapping[str, Any] | None = None, /, **tables: Mapping[str, Any]) -> "Deck":
        """A new deck with values replaced: by dotted key (``{"impactor.velocity": 3.0}``) and/or by
        table (``impactor={"velocity": 3.0}``). Tables and keys that do not exist are added."""
        tree = self.to_dict()
        if values is not None:
            _require_values(values, "Deck.replace: values")
        for table, entries in tables.items():
            _require(entries, Mapping, f"Deck.replace: {table}", f'a mapping of the [{table}] keys to values, e.g. {table}={{"key": 1.0}}')
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
    _require(path, _PathLike, "load: path", "the path of a deck file (str or os.PathLike)")
    return Deck(_core.load_deck(os.fsdecode(os.fspath(path))))


def parse(text: str, source: str = "<string>") -> Deck:
    """Validates deck text; ``source`` names it in messages."""
    _require(text, str, "parse: text", "the deck's TOML text (a str)")
    _require(source, str, "parse: source", "a name for messages (a str)")
    return Deck(_core.parse_deck(text, source))


def deck(values: Mapping[str, Any], source: str = "<dict>") -> Deck:
    """A deck built from Python values, table by table as a deck file writes them::

        plyimpact.deck({"materials": {"cfrp": {...}}, "laminate": {...}, "plate": {...}, ...})
    """
    _require(values, Mapping, "deck: values", 'a mapping of tables, e.g. {"impactor": {"mass": 0.314}}')
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
    threads: int | None = None,
) -> ImpactRun:
    """Runs the impact of a deck (or a deck file) as ``plyimpact impact DECK [-o output_dir]`` does.

    With ``output_dir`` the results folder is written too (summary.json, history.csv, ...);
    ``nonlinear`` is the command's ``--nonlinear``; ``history=False`` keeps no history in memory;
    ``threads`` is the command's ``--threads`` (the element loops of the run; by default the deck's
    ``[run] threads``, else one, since the module runs with ``OMP_NUM_THREADS=1`` unless you set it).
    The results are the same bits for any number of threads.
    """
    d = _as_deck(case, "impact")
    out = _output_dir(output_dir, "impact")
    flags = [_flag(v, f"impact: {k}") for k, v in (("overwrite", overwrite), ("nonlinear", nonlinear), ("history", history))]
    if threads is not None:
        _require(threads, numbers.Integral, "impact: threads", "a thread count (an int from 1 to 1024)")
        if not 1 <= threads <= 1024:
            raise ValueError(f"impact: threads must lie between 1 and 1024, got {threads}")
    summary, notes, columns, rows, interrupted = _core.run_impact(d._core, out, *flags, int(threads or 0))
    run = ImpactRun(json.loads(summary), list(notes), list(columns), rows)
    if interrupted:  # Ctrl-C: the run finished its step and wrote what it had (docs/python.md)
        stopped = KeyboardInterrupt(
            f"plyimpact.impact: interrupted at t = {run.summary.get('end_time', float('nan')):g} s after "
            f"{run.summary.get('steps')} steps; the results so far are in this exception's .run"
            + (f" and in {out}" if out else "")
        )
        stopped.run = run  # type: ignore[attr-defined]
        raise stopped
    return run


class ImpactStudy:
    """A plate built once and hit by many impactors: the matrices, the factorization and, for a linear
    plate under a point load with the trapezoidal rule, the plate's impulse response at the impact point
    (one run's worth of work) are kept, so each further impactor on a linear plate costs a convolution
    (docs/sweep.md, "Reusing the plate's response"). ``run`` takes the keys of ``[impactor]`` and
    ``contact_k`` and returns summary.json's dict with ``plate_response`` ("contact point" or "full").
    The time step must not change between runs: give ``[time] dt`` a number, not "auto"."""

    def __init__(self, case: Deck | str | os.PathLike[str], *, nonlinear: bool = False):
        self.deck = _as_deck(case, "ImpactStudy")
        self._core = _core.ImpactStudy(self.deck._core, _flag(nonlinear, "ImpactStudy: nonlinear"))

    def run(self, *, contact_k: float | None = None, **impactor: Any) -> dict[str, Any]:
        """The impact of the study's plate by the deck's impactor with ``impactor`` keys replaced
        (``velocity=3.0``, ``mass=0.5``, ...) and ``contact_k`` as ``[contact] k``."""
        values: dict[str, Any] = {f"impactor.{k}": v for k, v in impactor.items()}
        if contact_k is not None:
            _require(contact_k, numbers.Real, "ImpactStudy.run: contact_k", "a number (the contact stiffness k)")
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
            _require(layup, str, "Laminate: layup", 'a stacking sequence (a str such as "[0/90]s") or a plyimpact.Deck')
            if material is None or ply_thickness is None:
                raise TypeError("Laminate(layup, material, ply_thickness): give the material and the ply thickness")
            _require(material, Mapping, "Laminate: material", 'a mapping of the material keys, e.g. {"E1": 129e9, ...}')
            _require(ply_thickness, numbers.Real, "Laminate: ply_thickness", "a number in m")
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
    return Laminate(_as_deck(case, "laminate"))


def _plate_analysis(kind: str, case: Any, output_dir: Any, overwrite: bool, nonlinear: bool = False) -> dict[str, Any]:
    d = _as_deck(case, kind)
    out = _output_dir(output_dir, kind)
    _text, summary = _core.run_plate_analysis(
        d._core, kind, out, _flag(overwrite, f"{kind}: overwrite"), _flag(nonlinear, f"{kind}: nonlinear")
    )
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
    d = _as_deck(case, "threshold")
    _require(criterion, str, "threshold: criterion", 'a criterion name (a str such as "hashin"), or "" for the deck\'s')
    _require(tolerance, numbers.Real, "threshold: tolerance", "a number in m/s (0 for the deck's)")
    if tolerance != 0 and not (math.isfinite(tolerance) and tolerance > 0):
        raise ValueError(f"threshold: tolerance must be a positive number of m/s (or 0 for the deck's), got {tolerance!r}")
    return json.loads(_core.run_threshold(d._core, criterion, float(tolerance), _flag(nonlinear, "threshold: nonlinear")))


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
    d = _as_deck(case, "sweep")
    if values is not None:
        _require_values(values, "sweep: values")
    _require(mode, str, "sweep: mode", "'product', 'zip' or '' (the deck's)")
    _require(jobs, numbers.Integral, "sweep: jobs", "a thread count (an int from 1 to 1024)")
    _flag(overwrite, "sweep: overwrite")
    options = []
    for key, v in (values or {}).items():
        if not isinstance(v, (str, list, tuple, range)) and not hasattr(v, "tolist"):
            raise TypeError(
                f"sweep: values[{key!r}] must be a list of values or a \"start:stop:count\" range, got {_type_name(v)} {v!r}"
            )
        listed = v if isinstance(v, str) else ",".join(_value_text(x) for x in (v.tolist() if hasattr(v, "tolist") else v))
        options.append(f"{key}={listed}")
    if mode not in ("", "product", "zip"):
        raise ValueError(f"sweep mode {mode!r}: expected 'product' or 'zip'")

    def run(folder: str) -> SweepTable:
        text, factorizations, missing, failed, interrupted = _core.run_sweep(
            d._core, options, mode, folder, int(jobs), overwrite
        )
        if interrupted:  # Ctrl-C: the cases under way finish; their records stay for a resume
            raise KeyboardInterrupt(
                f"plyimpact.sweep: interrupted with {missing} cases left; "
                + (f"run it again with output_dir={output_dir!r} to resume" if output_dir is not None else
                   "give output_dir to keep the records of an interrupted sweep")
            )
        if missing:
            raise RuntimeError(f"sweep: {missing} cases have no record (interrupted?); run again to resume")
        return SweepTable(text, factorizations)

    if output_dir is not None:
        return run(_output_dir(output_dir, "sweep") or "")
    with tempfile.TemporaryDirectory(prefix="plyimpact-sweep-") as folder:
        return run(folder)
