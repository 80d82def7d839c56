"""The Python module against the command line: the same engine must give the same numbers.

Run by ctest (Python.pytest) with PYTHONPATH pointing at the build tree's python/ folder,
PLYIMPACT_EXE at the plyimpact executable and PLYIMPACT_SOURCE_DIR at the repository.
"""
import json
import os
import shutil
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np
import pytest

import plyimpact

SOURCE = Path(os.environ.get("PLYIMPACT_SOURCE_DIR", Path(__file__).resolve().parents[2]))
EXE = str(Path(os.environ.get("PLYIMPACT_EXE", SOURCE / "build/release/plyimpact")).resolve())

# The thesis §3.6 material (examples/thesis-3.6-v268.toml).
THESIS_3_6 = {"E1": 129.0e9, "E2": 7.5e9, "G12": 3.5e9, "G13": 3.5e9, "G23": 3.5e9, "nu12": 0.33, "rho": 1540.0}


def cli(*args, cwd):
    """Runs the plyimpact command; returns its completed process (output checked by the caller)."""
    return subprocess.run([EXE, *args], cwd=cwd, capture_output=True, text=True, check=False)


@pytest.fixture()
def examples(tmp_path, monkeypatch):
    """A working folder where the decks are reached as examples/NAME.toml, as the CLI is run."""
    (tmp_path / "examples").symlink_to(SOURCE / "examples")
    monkeypatch.chdir(tmp_path)
    return tmp_path


@pytest.mark.parametrize("name", ["thesis-3.6-v268", "thesis-3.6-v268-nonlinear", "impact-adaptive-steps"])
def test_impact_summary_and_history_equal_the_command_line_bit_for_bit(examples, name):
    """One engine: the §3.6 impact (linear and geometrically non-linear) and an impact with
    error-controlled steps run from Python give the CLI's summary.json and history.csv exactly (every
    double equal, not close)."""
    deck_path = f"examples/{name}.toml"
    done = cli("impact", deck_path, "-o", "cli", "--quiet", cwd=examples)
    assert done.returncode == 0, done.stderr
    run = plyimpact.impact(deck_path)
    expected = json.loads((examples / "cli/summary.json").read_text())
    assert run.summary.pop("wall_time") > 0 and expected.pop("wall_time") > 0  # the one key that may differ
    assert run.summary == expected
    with open(examples / "cli/history.csv") as f:
        header = f.readline().strip().split(",")
    rows = np.loadtxt(examples / "cli/history.csv", delimiter=",", skiprows=1, ndmin=2)
    assert list(run.history) == header
    for j, column in enumerate(header):
        assert np.array_equal(run.history[column], rows[:, j]), column
    assert run.history["force_N"].max() == run.summary["peak_force"]


def test_a_stacked_plates_history_follows_its_interfaces_as_the_command_line_does(examples):
    """The delamination columns (issue 19) come out of Python as out of history.csv, double for double:
    the example on 5 x 5 elements to 0.25 ms, where both interfaces delaminate."""
    text = (SOURCE / "examples/impact-delamination.toml").read_text()
    for old, new in (("nx = 11", "nx = 5"), ("ny = 11", "ny = 5"), ("end = 0.35e-3", "end = 0.25e-3")):
        assert f"\n{old}\n" in text
        text = text.replace(f"\n{old}\n", f"\n{new}\n")
    (examples / "small.toml").write_text(text)
    done = cli("impact", "small.toml", "-o", "cli", "--quiet", cwd=examples)
    assert done.returncode == 0, done.stderr
    run = plyimpact.impact("small.toml")
    with open(examples / "cli/history.csv") as f:
        header = f.readline().strip().split(",")
    rows = np.loadtxt(examples / "cli/history.csv", delimiter=",", skiprows=1, ndmin=2)
    assert list(run.history) == header
    assert header[-4:] == ["delamination_dissipation_J", "delamination_area_m2",
                           "delamination_area_after_ply2_m2", "delamination_area_after_ply6_m2"]
    for j, column in enumerate(header):
        assert np.array_equal(run.history[column], rows[:, j]), column
    projected = run.summary["delamination"]["projected_delaminated_area_m2"]
    assert run.history["delamination_area_m2"][-1] == projected > 0


def test_impact_writes_the_same_results_folder(examples):
    """plyimpact.impact(deck, DIR) writes the folder the command writes (summary.json equal)."""
    run = plyimpact.impact("examples/thesis-3.6-v268.toml", examples / "py")
    written = json.loads((examples / "py/summary.json").read_text())
    assert written == run.summary
    assert (examples / "py/history.csv").is_file()
    with pytest.raises(plyimpact.FolderHoldsResults):
        plyimpact.impact("examples/thesis-3.6-v268.toml", examples / "py")
    plyimpact.impact("examples/thesis-3.6-v268.toml", examples / "py", overwrite=True, history=False)


def test_laminate_matrices_equal_the_command_line_json(examples):
    """ABD and F from Python are those of `plyimpact laminate DECK --json`."""
    done = cli("laminate", "examples/annex2.toml", "--json", cwd=examples)
    assert done.returncode == 0, done.stderr
    expected = json.loads(done.stdout)
    lam = plyimpact.laminate("examples/annex2.toml")
    for name in ("A", "B", "D", "F"):
        assert np.array_equal(getattr(lam, name), np.array(expected[name])), name
    assert lam.thickness == expected["thickness"]


def test_a_unidirectional_laminate_has_the_closed_form_stiffness():
    """[0]4 of one material: A11 = Q11 h with Q11 = E1/(1 − ν12 ν21), D11 = Q11 h³/12, B = 0,
    A66 = G12 h, F = κ diag(G13, G23) h with κ = 5/6 (hand calculation, Jones ch. 4)."""
    t = 0.125e-3
    lam = plyimpact.Laminate("[0]4", THESIS_3_6, ply_thickness=t)
    h = 4 * t
    m = THESIS_3_6
    nu21 = m["nu12"] * m["E2"] / m["E1"]
    q11 = m["E1"] / (1.0 - m["nu12"] * nu21)
    assert lam.A[0, 0] == pytest.approx(q11 * h, rel=1e-12)
    assert lam.D[0, 0] == pytest.approx(q11 * h**3 / 12.0, rel=1e-12)
    assert lam.A[2, 2] == pytest.approx(m["G12"] * h, rel=1e-12)
    assert np.abs(lam.B).max() == pytest.approx(0.0, abs=1e-9 * q11 * h * h)
    assert lam.F[0, 0] == pytest.approx(5.0 / 6.0 * m["G13"] * h, rel=1e-12)
    assert lam.ABD.shape == (6, 6)


def test_a_laminate_from_python_values_equals_the_decks(examples):
    """Laminate(layup, material dict, t) builds the deck's laminate: the §3.6 plate's D exactly."""
    from_deck = plyimpact.laminate("examples/thesis-3.6-v268.toml")
    built = plyimpact.Laminate("[45/90/-45/0]3s", THESIS_3_6, ply_thickness=0.19375e-3)
    assert np.array_equal(built.D, from_deck.D)
    assert np.array_equal(built.A, from_deck.A)


def test_a_bad_deck_raises_deck_error_with_file_and_line(tmp_path):
    """The CLI's message, as a Python exception: file, line, key and what was expected."""
    bad = tmp_path / "bad.toml"
    text = (SOURCE / "examples/thesis-3.6-v268.toml").read_text().replace("mass = 6.14", "mass = -6.14")
    bad.write_text(text)
    line = next(i for i, s in enumerate(text.splitlines(), 1) if s.startswith("mass = -6.14"))
    with pytest.raises(plyimpact.DeckError) as error:
        plyimpact.load(bad)
    assert f"bad.toml:{line}:" in str(error.value)
    assert "mass" in str(error.value)
    with pytest.raises(plyimpact.DeckError, match="no such file|cannot"):
        plyimpact.load(tmp_path / "missing.toml")


def test_replace_makes_a_new_validated_deck(examples):
    """Dotted keys read the deck; replace() changes a copy and validates it like a file."""
    base = plyimpact.load("examples/thesis-3.6-v268.toml")
    assert base["impactor.velocity"] == 2.68
    faster = base.replace({"impactor.velocity": 3.0})
    assert faster["impactor.velocity"] == 3.0 and base["impactor.velocity"] == 2.68
    assert faster.replace(impactor={"velocity": 2.68})["impactor.velocity"] == 2.68
    with pytest.raises(plyimpact.DeckError, match="velocity"):
        base.replace({"impactor.velocity": "fast"})
    with pytest.raises(KeyError):
        base["impactor.colour"]


def test_a_deck_built_from_dicts_runs_like_the_file(examples):
    """A case built from Python values alone (no file) gives the file's peak force exactly."""
    tree = plyimpact.load("examples/thesis-3.6-v268.toml").to_dict()
    from_dict = plyimpact.deck(tree, source="from-dict")
    a = plyimpact.impact(from_dict, history=False)
    b = plyimpact.impact("examples/thesis-3.6-v268.toml", history=False)
    assert a.summary["peak_force"] == b.summary["peak_force"]
    assert a.summary["deck"] == "from-dict"


def test_cases_on_threads_equal_the_same_cases_in_series(examples):
    """The engine releases the GIL and shares nothing between runs: four velocities on two threads
    give the serial peak forces exactly."""
    base = plyimpact.load("examples/thesis-3.6-v268.toml")
    decks = [base.replace({"impactor.velocity": v}) for v in (1.0, 1.5, 2.0, 2.5)]
    serial = [plyimpact.impact(d, history=False).summary["peak_force"] for d in decks]
    with ThreadPoolExecutor(max_workers=2) as pool:
        threaded = [r.summary["peak_force"] for r in pool.map(lambda d: plyimpact.impact(d, history=False), decks)]
    assert threaded == serial
    assert serial == sorted(serial)  # a faster impactor strikes harder


def test_ply_damage_on_one_and_two_threads_is_the_same_bits(examples):
    """threads= is the command's --threads: the element loops of a progressive-damage run on one and two
    threads give the same summary (wall time aside) and history, value for value."""
    d = plyimpact.load("examples/damage-progressive-explicit.toml").replace({"time.end": 4e-4})
    one, two = (plyimpact.impact(d, threads=n) for n in (1, 2))
    for run in (one, two):
        run.summary.pop("wall_time")
    assert one.summary["damage"]["dissipated_energy"] > 0.0
    assert one.summary == two.summary
    assert one.history.keys() == two.history.keys()
    assert all(np.array_equal(one.history[k], two.history[k]) for k in one.history)


def test_threshold_search_equals_the_command_line(examples):
    """`plyimpact threshold` and plyimpact.threshold run the same bisection: same trials, same velocity."""
    deck_path = "examples/thesis-4.3-threshold-0_2-90_2-0_2.toml"
    done = cli("threshold", deck_path, "-o", "cli", "--quiet", cwd=examples)
    assert done.returncode == 0, done.stderr
    expected = json.loads((examples / "cli/summary.json").read_text())
    expected.pop("wall_time")
    found = plyimpact.threshold(deck_path)
    assert found == expected
    assert found["threshold_velocity"] is not None


def test_a_threaded_sweep_gives_the_command_lines_table(examples):
    """Eight velocities on two Python-side threads give `plyimpact sweep`'s sweep.csv byte for byte, and
    the folder gets the sweep's report.html (peak force and absorbed energy against the velocity)."""
    deck_path = "examples/thesis-4.2-velocity-2.92.toml"
    done = cli("sweep", deck_path, "--set", "impactor.velocity=0.5:3.0:8", "--jobs", "1", "-o", "cli", "--quiet",
               cwd=examples)
    assert done.returncode == 0, done.stderr
    table = plyimpact.sweep(deck_path, {"impactor.velocity": "0.5:3.0:8"}, jobs=2, output_dir=examples / "py")
    assert table.text == (examples / "cli/sweep.csv").read_text()
    assert len(table) == 8
    report = (examples / "py/report.html").read_text()  # the sweep's report, as the command writes it
    assert report.count("<td>ok</td>") == 8 and report.count('class="plot"') == 2
    listed = plyimpact.sweep(deck_path, {"impactor.velocity": [0.5, 3.0]}, jobs=1)
    assert list(listed["impactor.velocity"]) == [0.5, 3.0]


def test_an_unbuilt_module_says_how_to_build_it(tmp_path):
    """The package's files without the compiled _core beside them (what the README's first command, which
    builds the command alone, leaves in the build tree): `import plyimpact` names the target to build
    instead of failing later with AttributeError."""
    shutil.copytree(SOURCE / "python/plyimpact", tmp_path / "plyimpact")
    done = subprocess.run([sys.executable, "-c", "import plyimpact"], cwd=tmp_path, capture_output=True,
                          text=True, env=dict(os.environ, PYTHONPATH=str(tmp_path)), check=False)
    assert done.returncode != 0
    assert "ImportError: plyimpact's compiled module (_core) is not built" in done.stderr, done.stderr
    assert "--target plyimpact_python" in done.stderr


def test_a_sweep_refuses_a_thread_count_it_cannot_run(examples):
    """jobs=0, a negative count or one past the limit is refused before anything is written, naming jobs
    and its range (0 and -3 were accepted, 100000 aborted the interpreter)."""
    deck_path = "examples/thesis-4.2-velocity-2.92.toml"
    for jobs in (0, -3, 100000):
        with pytest.raises(ValueError, match="jobs must lie between 1 and 1024 threads"):
            plyimpact.sweep(deck_path, {"impactor.velocity": [0.5, 3.0]}, jobs=jobs, output_dir=examples / "bad")
        assert not (examples / "bad" / "sweep.csv").exists()


@pytest.mark.parametrize("script", ["layup_study.py", "energy_sweep.py", "threshold_search.py"])
def test_the_notebook_style_examples_run(tmp_path, script):
    """Every example of examples/python runs from the repository root and prints its table."""
    env = dict(os.environ, MPLBACKEND="Agg")
    done = subprocess.run([sys.executable, str(SOURCE / "examples/python" / script), str(tmp_path)], cwd=SOURCE,
                          env=env, capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stderr
    assert len(done.stdout.splitlines()) >= 4, done.stdout
    if script == "energy_sweep.py":
        assert (tmp_path / "energy_sweep.png").stat().st_size > 10_000


@pytest.mark.parametrize(
    "kind, name",
    [("static", "static-annex2-loads"), ("modal", "modal-annex2"), ("buckling", "buckling-annex2")],
)
def test_static_modal_and_buckling_equal_the_command_line(examples, kind, name):
    """The plate analyses from Python give the command's summary.json exactly."""
    deck_path = f"examples/{name}.toml"
    done = cli(kind, deck_path, "-o", "cli", cwd=examples)
    assert done.returncode == 0, done.stderr
    expected = json.loads((examples / "cli/summary.json").read_text())
    assert getattr(plyimpact, kind)(deck_path) == expected
    assert getattr(plyimpact, kind)(deck_path, examples / "py") == expected
    assert json.loads((examples / "py/summary.json").read_text()) == expected


def test_an_edited_deck_keeps_its_gmsh_mesh_file(examples):
    """[mesh] file is relative to the deck's folder, also after replace() (whose deck is named after the
    edit, here with a '/' in it): doubling the laminate (8 to 16 plies) stiffens the clamped circular plate,
    the deflection under the same loads falling by about 2^3 (bending) to 0.2 or less of the thin plate's."""
    base = plyimpact.load("examples/static-circular-clamped.toml")
    thick = base.replace({"laminate.layup": "[0/45/-45/90]2s"})
    thin_w = plyimpact.static(base)["center_deflection"]
    thick_w = plyimpact.static(thick)["center_deflection"]
    assert 0.1 < thick_w / thin_w < 0.2


def test_impact_study_runs_many_impactors_on_one_plate(examples):
    """ImpactStudy keeps the plate: on the thesis's linear plate under a point force every impactor
    after the first goes through the plate's impulse response at the impact point (a convolution,
    docs/sweep.md), which must give each impactor's own full run to rounding; a deck with the Hertz
    pressure (not a convolution) runs in full and gives the full run's numbers bit for bit."""
    deck = plyimpact.load("examples/thesis-4.2-velocity-2.92.toml")
    study = plyimpact.ImpactStudy(deck)
    for velocity, mass in [(2.92, None), (1.0, None), (2.0, 1.0)]:
        impactor = {"velocity": velocity} if mass is None else {"velocity": velocity, "mass": mass}
        r = study.run(**impactor)
        full = plyimpact.impact(deck.replace(impactor=impactor), history=False)
        assert r["plate_response"] == "contact point"
        assert r["steps"] == full["steps"]
        assert r["time_of_peak_force"] == full["time_of_peak_force"]
        for key in ["peak_force", "peak_contact_deflection", "max_indentation", "rebound_velocity"]:
            assert r[key] == pytest.approx(full[key], rel=1e-10), key
    pressure = deck.replace({"contact.load": "hertz-pressure"})
    r = plyimpact.ImpactStudy(pressure).run(velocity=1.5)
    full = plyimpact.impact(pressure.replace({"impactor.velocity": 1.5}), history=False)
    assert r["plate_response"] == "full"
    assert r["peak_force"] == full["peak_force"]
    assert r["rebound_velocity"] == full["rebound_velocity"]


def test_impact_study_refuses_another_time_step(examples):
    """A study's plate is factored for one Δt: an impactor whose dt = "auto" resolves to another step is
    refused with the engine's message, not run on the wrong factor."""
    deck = plyimpact.load("examples/thesis-4.2-velocity-2.92.toml").replace({"time.dt": "auto"})
    study = plyimpact.ImpactStudy(deck)
    with pytest.raises(ValueError, match="same time step"):
        study.run(velocity=0.5, mass=5.0)
