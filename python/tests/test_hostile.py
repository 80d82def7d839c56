"""Hostile calls of the Python module (docs/robustness.md, "Python"): arguments of the wrong type are refused
where they are given, naming the function and the argument or key; out-of-range values as the command line
refuses them; Ctrl-C stops a run within a step and raises KeyboardInterrupt carrying what was computed.

Before these checks a wrong type surfaced deep inside (``AttributeError: 'int' object has no attribute
'split'``) and Ctrl-C took effect only when the run returned, its results lost.
"""
import os
import signal
import threading
import time
from pathlib import Path

import pytest

import plyimpact

SOURCE = Path(os.environ.get("PLYIMPACT_SOURCE_DIR", Path(__file__).resolve().parents[2]))
DECK = SOURCE / "examples" / "thesis-3.6-v268.toml"


@pytest.fixture(scope="module")
def deck():
    return plyimpact.load(DECK)


# (what is called, the fragment its TypeError must hold: the function and the argument or key)
WRONG_TYPES = [
    (lambda d: plyimpact.load(5), "load: path must be the path of a deck file"),
    (lambda d: plyimpact.load(None), "load: path"),
    (lambda d: plyimpact.parse(5), "parse: text must be the deck's TOML text"),
    (lambda d: plyimpact.parse("a = 1", source=3), "parse: source"),
    (lambda d: plyimpact.deck([1, 2]), "deck: values must be a mapping of tables"),
    (lambda d: d[5], "Deck[key]: key must be a dotted deck key"),
    (lambda d: d.get(("impactor", "mass")), "Deck.get: key"),
    (lambda d: d.replace(5), "Deck.replace: values must be a mapping"),
    (lambda d: d.replace({3: 1.0}), "Deck.replace: values: key 3"),
    (lambda d: d.replace(impactor=3), "Deck.replace: impactor must be a mapping of the [impactor] keys"),
    (lambda d: plyimpact.impact(5), "impact: case must be a plyimpact.Deck or the path of a deck file"),
    (lambda d: plyimpact.impact(d, 5), "impact: output_dir must be a folder path or None"),
    (lambda d: plyimpact.impact(d, nonlinear="yes"), "impact: nonlinear must be True or False"),
    (lambda d: plyimpact.impact(d, history=1), "impact: history must be True or False"),
    (lambda d: plyimpact.impact(d, threads="2"), "impact: threads must be a thread count"),
    (lambda d: plyimpact.impact(d, threads=2.0), "impact: threads must be a thread count"),
    (lambda d: plyimpact.static(3.0), "static: case"),
    (lambda d: plyimpact.modal(d, output_dir=[1]), "modal: output_dir"),
    (lambda d: plyimpact.buckling(d, overwrite="no"), "buckling: overwrite"),
    (lambda d: plyimpact.threshold(d, criterion=7), "threshold: criterion must be a criterion name"),
    (lambda d: plyimpact.threshold(d, tolerance="0.1"), "threshold: tolerance must be a number in m/s"),
    (lambda d: plyimpact.sweep(d, 3), "sweep: values must be a mapping of dotted deck keys"),
    (lambda d: plyimpact.sweep(d, {"impactor.velocity": 3}), "sweep: values['impactor.velocity'] must be a list"),
    (lambda d: plyimpact.sweep(d, {1: [1, 2]}), "sweep: values: key 1"),
    (lambda d: plyimpact.sweep(d, {"impactor.velocity": [1, 2]}, jobs="2"), "sweep: jobs must be a thread count"),
    (lambda d: plyimpact.sweep(d, {"impactor.velocity": [1, 2]}, jobs=2.5), "sweep: jobs"),
    (lambda d: plyimpact.sweep(d, {"impactor.velocity": [1, 2]}, mode=1), "sweep: mode"),
    (lambda d: plyimpact.Laminate(5), "Laminate: layup must be a stacking sequence"),
    (lambda d: plyimpact.Laminate("[0/90]s", [1, 2], 1e-4), "Laminate: material must be a mapping"),
    (lambda d: plyimpact.Laminate("[0/90]s", {"E1": 1e11}, "thin"), "Laminate: ply_thickness must be a number"),
    (lambda d: plyimpact.laminate(1), "laminate: case"),
    (lambda d: plyimpact.ImpactStudy(d, nonlinear=None), "ImpactStudy: nonlinear"),
]


@pytest.mark.parametrize("call, says", WRONG_TYPES, ids=[s.split(" must")[0] for _, s in WRONG_TYPES])
def test_a_wrong_type_names_the_function_and_the_argument(deck, call, says):
    with pytest.raises(TypeError) as refused:
        call(deck)
    assert says in str(refused.value)
    assert "got " in str(refused.value)  # and what was given


def test_a_wrong_type_of_a_deck_value_names_the_key(deck):
    with pytest.raises(plyimpact.DeckError) as refused:
        deck.replace({"impactor.velocity": "fast"})
    assert "impactor.velocity must be a number in m/s, got a string" in str(refused.value)


@pytest.mark.parametrize("tolerance", [-1.0, float("nan"), float("inf")])
def test_a_threshold_tolerance_out_of_range_is_refused_as_on_the_command_line(deck, tolerance):
    with pytest.raises(ValueError, match="tolerance must be a positive number of m/s"):
        plyimpact.threshold(deck, tolerance=tolerance)


@pytest.mark.parametrize("jobs", [0, -3, 100000])
def test_a_sweep_thread_count_out_of_range_is_refused(deck, jobs):
    with pytest.raises(ValueError, match="jobs must lie between 1 and 1024"):
        plyimpact.sweep(deck, {"impactor.velocity": [1.0, 2.0]}, jobs=jobs)


@pytest.mark.parametrize("threads", [0, -1, 1025])
def test_an_impact_thread_count_out_of_range_is_refused(deck, threads):
    with pytest.raises(ValueError, match="impact: threads must lie between 1 and 1024"):
        plyimpact.impact(deck, threads=threads)


def test_ctrl_c_stops_an_impact_within_a_step_and_raises_with_the_results_so_far(deck, tmp_path):
    # The §3.6 plate struck for 2 s of 1 µs steps: two million steps, minutes of work. SIGINT after 1 s.
    long_run = deck.replace({"time.dt": 1e-6, "time.end": 2.0, "time.max_steps": 10_000_000})
    timer = threading.Timer(1.0, os.kill, (os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt) as stopped:
            plyimpact.impact(long_run, tmp_path / "out")
    finally:
        timer.cancel()
    elapsed = time.monotonic() - start
    assert elapsed < 30.0, f"the run went on {elapsed:.1f} s after Ctrl-C"
    run = stopped.value.run
    assert run.summary["complete"] is False
    assert 0 < run.summary["steps"] < 2_000_000
    assert len(run.history["t_s"]) >= 2
    # what was computed is written too, as the command line writes it
    written = (tmp_path / "out" / "summary.json").read_text()
    assert '"complete": false' in written
    assert "interrupted" in str(stopped.value)


def test_ctrl_c_stops_a_sweep_and_keeps_the_records_for_a_resume(deck, tmp_path):
    # 16 cases of the §3.6 plate, each stepped in full (not through the plate's impulse response), one at a
    # time: about 0.45 s a case, 7 s in all. SIGINT after 1.5 s.
    values = {"impactor.velocity": "1.0:3.0:16"}
    deck = deck.replace({"time.dt": 1e-6, "time.end": 0.005, "sweep.plate_response": "full"})
    timer = threading.Timer(1.5, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt, match="to resume"):
            plyimpact.sweep(deck, values, jobs=1, output_dir=tmp_path / "sweep")
    finally:
        timer.cancel()
    recorded = list((tmp_path / "sweep" / "cases").glob("*"))
    assert 0 < len(recorded) < 16
    table = plyimpact.sweep(deck, values, jobs=1, output_dir=tmp_path / "sweep")  # the resume
    assert len(table) == 16


def test_ctrl_c_stops_a_threshold_search_within_a_step():
    # The §4.3 search in 1e-8 s steps: a hundred times its 0.5 s. SIGINT after 1 s.
    search = plyimpact.load(SOURCE / "examples" / "thesis-4.3-threshold-0_2-90_2-0_2.toml").replace({"time.dt": 1e-8})
    timer = threading.Timer(1.0, os.kill, (os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt, match="interrupted"):
            plyimpact.threshold(search)
    finally:
        timer.cancel()
    assert time.monotonic() - start < 20.0
