"""The Python module against the command-line tool: the same library, so the same numbers, bit
for bit; bad input raises with the key named, as the tool reports it."""

import _thread
import json
import math
import os
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import tbridge

SOURCE = os.environ["TBRIDGE_SOURCE_DIR"]
BINARY = os.environ["TBRIDGE_BINARY"]
DEFAULT = os.path.join(SOURCE, "configs", "default.json")


def cli(*args):
    """Runs tbridge with `args`; returns (exit code, stderr)."""
    r = subprocess.run([BINARY, *args], capture_output=True, text=True)
    return r.returncode, r.stderr


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    """The default design as tbridge design writes it, and its path."""
    path = tmp_path_factory.mktemp("cli") / "design.json"
    code, err = cli("design", DEFAULT, "-q", "-o", str(path))
    assert code in (0, 1), err
    return path


@pytest.fixture(scope="module")
def design():
    return tbridge.design(DEFAULT)


def test_design_is_the_cli_design_bit_for_bit(design, written):
    text = written.read_text()
    assert design.to_json() == text
    cli_json = json.loads(text)
    assert np.array_equal(design.nodes, np.array(cli_json["nodes"]))
    members = cli_json["members"]
    assert design.member_names == [m["name"] for m in members]
    for key, array in [("area", design.areas), ("force", design.forces), ("rest_length", design.rest_lengths),
                       ("utilisation", design.utilisation)]:
        column = np.array([m[key] if m[key] is not None else m["length"] for m in members])
        assert np.array_equal(array, column), key
    names = ["%d-%d" % (i + 1, j + 1) for i, j in design.member_ends]
    assert names == design.member_names
    assert design.verdict == cli_json["verdict"]["outcome"]
    assert design.cases == [c["name"] for c in cli_json["cases"]]


def test_a_dict_config_is_the_file_config(design):
    with open(DEFAULT) as f:
        config = json.load(f)
    assert tbridge.design(config).to_json() == design.to_json()


def test_arrays_are_owned_copies(design):
    areas = design.areas
    areas[:] = 0
    assert np.all(design.areas > 0)


def test_bad_config_raises_with_the_key_named_as_the_cli_says(tmp_path):
    with open(DEFAULT) as f:
        config = json.load(f)
    config["bridge"]["n"] = -3
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(config))
    code, err = cli("design", str(path), "-q", "-o", str(tmp_path / "out.json"))
    assert code == 2
    with pytest.raises(tbridge.ConfigError) as raised:
        tbridge.design(config)
    assert "bridge.n" in str(raised.value)
    assert str(raised.value) in err


@pytest.mark.parametrize("value, shown", [(math.nan, "nan"), (math.inf, "inf"), (-math.inf, "-inf")])
def test_a_non_finite_float_raises_with_the_key_named(value, shown):
    # json.dumps writes NaN and Infinity bare, which is no JSON: the error names the key instead.
    with open(DEFAULT) as f:
        config = json.load(f)
    config["bridge"]["payload"] = value
    with pytest.raises(tbridge.ConfigError, match=rf"config key 'bridge\.payload' = {shown}: must be a finite number"):
        tbridge.design(config)
    # In a list too, and in a sweep's config.
    config["bridge"]["payload"] = 12000.0
    config["loads"]["cases"] = ["permanent", value]
    with pytest.raises(tbridge.ConfigError, match=rf"'loads\.cases\[1\]' = {shown}"):
        tbridge.modes(config)
    with pytest.raises(tbridge.ConfigError, match=rf"'sweep\.beta_deg\[0\]' = {shown}"):
        tbridge.sweep({"bridge": {"n": 1}, "sweep": {"beta_deg": [value]}}, threads=1)


def test_bad_export_format_raises_with_the_key_named(design):
    with pytest.raises(tbridge.ConfigError, match="'format' = 'abaqus': expected calculix or opensees"):
        tbridge.export(design, "abaqus")


def test_load_design_then_check_is_tbridge_check(written, tmp_path):
    out = tmp_path / "checked.json"
    code, err = cli("check", str(written), "-q", "-o", str(out))
    assert code in (0, 1), err
    assert tbridge.check(tbridge.load_design(str(written))).to_json() == out.read_text()


def test_export_is_tbridge_export(design, written, tmp_path):
    for fmt in ("calculix", "opensees"):
        out = tmp_path / ("bridge." + fmt)
        code, err = cli("export", str(written), "--format", fmt, "--rigid-bars", "-o", str(out))
        assert code == 0, err
        assert tbridge.export(design, fmt, rigid_bars=True) == out.read_text()


def test_modes_are_tbridge_modes(design, tmp_path):
    out = tmp_path / "modes.json"
    code, err = cli("modes", DEFAULT, "-q", "-o", str(out))
    assert code == 0, err
    cli_modes = json.loads(out.read_text())
    omega = np.array([m["omega_rad_s"] for m in cli_modes["modes"]])
    for modes in (tbridge.modes(DEFAULT), tbridge.modes(design)):
        assert np.array_equal(modes.omega_rad_s, omega)
        shapes = np.array([s["displacements"] for s in cli_modes["mode_shapes"]])
        assert np.array_equal(modes.shapes[: len(shapes)], shapes)


def test_the_gil_is_released_while_designing():
    # A design takes about a second; a thread holding the GIL throughout would let this loop
    # run only between the design's own Python calls, a handful of times.
    worker = threading.Thread(target=tbridge.design, args=(DEFAULT,))
    worker.start()
    turns = 0
    while worker.is_alive():
        turns += 1
    worker.join()
    assert turns > 10000


def test_importing_loads_no_solver_until_a_design_needs_one():
    script = (
        "import tbridge\n"
        "def solvers():\n"
        "    maps = open('/proc/self/maps').read()\n"
        "    return [s for s in ('tbridge_ipopt', 'tbridge_nlopt') if s in maps]\n"
        "print(solvers())\n"
        "tbridge.design(%r)\n"
        "print(solvers())\n" % os.path.join(SOURCE, "configs", "paper_3d.json")
    )
    r = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    before, after = r.stdout.splitlines()
    assert before == "[]"
    # The 3D bridge's equilibrium design needs an iterative solver (design.solver "auto": Ipopt,
    # else NLopt); the default's verified sizing needs none (its SQP is built in).
    assert after != "[]"


def test_simulate_is_tbridge_simulate(tmp_path):
    config = os.path.join(SOURCE, "configs", "motes_dbar.json")
    code, err = cli("simulate", config, "-q", "-o", str(tmp_path))
    assert code == 0, err
    run = tbridge.simulate(config)
    summary = json.loads((tmp_path / "summary.json").read_text())
    # Every number but the wall-clock time of the run.
    del summary["run"]["wall_s"], run.summary["run"]["wall_s"]
    assert run.summary == summary
    # history.csv holds 12 digits; the run's own numbers are what it rounds.
    csv = np.loadtxt(tmp_path / "history.csv", delimiter=",", skiprows=1)
    assert run.positions.shape == (len(csv), 4, 2)
    assert np.allclose(run.time, csv[:, 0], rtol=1e-11, atol=0)
    assert np.allclose(run.positions.reshape(len(csv), -1), csv[:, 1:], rtol=1e-11, atol=1e-12)
    assert list(run.recorded_nodes) == [0, 1, 2, 3]


def test_ctrl_c_stops_a_long_run():
    with open(os.path.join(SOURCE, "configs", "paper_t5_n1.json")) as f:
        config = json.load(f)
    config["dynamics"]["duration"] = 1000.0  # 1e8 steps: hours, were it not stopped
    config["dynamics"]["record"]["every"] = 1000
    config["dynamics"]["frequency"]["enabled"] = False
    assert seconds_to_interrupt(tbridge.simulate, config) < 30


def seconds_to_interrupt(work, *args):
    """Runs work(*args) with Ctrl-C after 1 s (as a terminal sends it); returns how long it ran."""
    timer = threading.Timer(1.0, _thread.interrupt_main)
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        work(*args)
    timer.join()
    return time.monotonic() - start


def test_ctrl_c_stops_a_design():
    # The default at n = 7 takes over a quarter of an hour here (BENCHMARKS.md; n = 5 takes about
    # 20 s); the design polls Python's signals at every progress report (each iteration of a
    # sizing, each static solve, every 1024 steps of a run), so it stops within a second of
    # Ctrl-C (1.01 s measured, the Ctrl-C included). 5 s: far above a poll's interval on a loaded
    # machine, and far below the design's own time, so a design that did not poll (and raised
    # only on its return) fails here.
    with open(DEFAULT) as f:
        config = json.load(f)
    config["bridge"]["n"] = 7
    assert seconds_to_interrupt(tbridge.design, config) < 5


SWEEP = {
    "bridge": {"beta_deg": 10},
    "design": {"yield_safety_factor": 10, "buckling_safety_factor": 1, "self_weight": False, "bar_resistance": "euler"},
    "loads": {"cases": ["paper"]},
    "sweep": {"n": [1, 2], "beta_deg": [10, 20], "verified": False, "joint_mass": {"per_node_kg": 2.0},
              "report": {"first_frequency": True},
              # No travelling-load run: the constraints read from it are off.
              "constraints": {"min_first_frequency_rad_s": 10, "no_slack_under_service": False,
                              "bar_capacity_during_motion": False}},
}


def test_sweep_is_tbridge_sweep_and_shards_partition_it(tmp_path):
    path = tmp_path / "sweep.json"
    path.write_text(json.dumps(SWEEP))
    code, err = cli("sweep", str(path), "-q", "-j", "2", "-o", str(tmp_path / "out"))
    assert code == 0, err
    whole = tbridge.sweep(SWEEP, threads=2)
    assert whole.to_json() == (tmp_path / "out" / "sweep.json").read_text()
    assert whole.to_csv() == (tmp_path / "out" / "sweep.csv").read_text()
    cli_json = json.loads(whole.to_json())
    assert whole.rows == cli_json["rows"] and whole.choice == cli_json["choice"]
    assert whole.choice["found"]
    # --shard semantics: shard i of N holds the candidates with index % N == i - 1, no choice.
    first, second = tbridge.sweep(str(path), threads=1, shard="1/2"), tbridge.sweep(SWEEP, shard="2/2")
    assert first.choice is None and second.choice is None
    assert [r["index"] for r in first.rows] == [0, 2] and [r["index"] for r in second.rows] == [1, 3]
    merged = sorted(first.rows + second.rows, key=lambda r: r["index"])
    assert merged == whole.rows


def test_bad_sweep_input_raises_with_the_key_named():
    with pytest.raises(tbridge.ConfigError, match="shard"):
        tbridge.sweep(SWEEP, shard="3/2")
    bad = json.loads(json.dumps(SWEEP))
    bad["sweep"]["n"] = []
    with pytest.raises(tbridge.ConfigError, match="sweep.n"):
        tbridge.sweep(bad)


def test_edited_areas_are_checked_as_tbridge_check_of_the_edited_file(written, tmp_path):
    # A bar 20 % thinner, edited in Python and in the file (area, radius and mass together, as
    # the reader derives them): the same as-built design and the same check, bit for bit.
    d = tbridge.load_design(str(written))
    areas = d.areas
    areas[0] *= 0.8
    edited = d.with_areas(areas)
    file = json.loads(written.read_text())
    m = file["members"][0]
    m["area"] = areas[0]
    m["radius"] = math.sqrt(areas[0] / math.pi)
    m["mass"] = file["config"]["material"]["density"] * areas[0] * m["length"]
    path, out = tmp_path / "thinner.json", tmp_path / "checked.json"
    path.write_text(json.dumps(file))
    code, err = cli("check", str(path), "-q", "-o", str(out))
    assert code in (0, 1), err
    checked = tbridge.check(edited)
    assert checked.to_json() == out.read_text()
    assert json.loads(checked.to_json())["as_built"]["re_derived"]
    d.areas = areas  # assigning is with_areas in place
    assert d.to_json() == edited.to_json()
    with pytest.raises(tbridge.ConfigError, match="areas"):
        d.with_areas(areas[:-1])


def test_case_nodes_give_the_design_file_deflections(design):
    # Each statically solved case's nodes, as the static check solves it: the largest vertical
    # deck deflection from the drawn geometry is the file's, at its node (1e-9 of it: the same
    # Newton solve, whose last iterate the file's shortest exact doubles and the module's own
    # reading of the design round apart by 1e-10 of the deflection on the default bridge).
    # A case with the rest lengths off by their tolerance deflects from that state's own reference
    # state, as built (the permanent case's nodes in it), not from the drawn geometry.
    file = json.loads(design.to_json())
    deck = sorted({n - 1 for m in file["members"] if m["type"] == "deck_string" for n in m["nodes"]})
    for entry in file["deflection_max"]:
        nodes = tbridge.case_nodes(design, entry["case"])
        suffix = next((s for s in (" with the rest lengths short", " with the rest lengths long",
                                   " after the prestress loss, the rest lengths long") if entry["case"].endswith(s)), None)
        reference = design.nodes if suffix is None else tbridge.case_nodes(design, "sls_permanent" + suffix)
        dy = np.abs(nodes[deck, 1] - reference[deck, 1])
        assert abs(dy.max() - entry["deflection"]) <= 1e-9 * max(entry["deflection"], 1e-3), entry["case"]
    with pytest.raises(tbridge.ConfigError, match="'case' = 'sls_travelling at node 99'"):
        tbridge.case_nodes(design, "sls_travelling at node 99")


def test_simulate_of_a_design_is_tbridge_simulate_of_its_file(tmp_path):
    """A Design, its file's path and its file's dict run as `tbridge simulate DESIGN.json` does:
    the same bridge from the file's 17 digits, so the same run, bit for bit; edited, as built."""
    config = json.loads(open(DEFAULT).read())
    config["bridge"]["n"] = 2
    # A short run of the verified bridge standing under its loads: 2000 RK4 steps.
    config["dynamics"] = {"duration": 0.2, "dt": 1e-4, "integrator": "rk4",
                          "record": {"nodes": [3], "every": 100}, "frequency": {"enabled": False}}
    (tmp_path / "config.json").write_text(json.dumps(config))
    path = tmp_path / "design.json"
    code, err = cli("design", str(tmp_path / "config.json"), "-q", "-o", str(path))
    assert code == 0, err
    code, err = cli("simulate", str(path), "-q", "-o", str(tmp_path / "run"))
    assert code == 0, err
    summary = json.loads((tmp_path / "run" / "summary.json").read_text())
    del summary["run"]["wall_s"]
    file = json.loads(path.read_text())
    for given in (tbridge.load_design(str(path)), str(path), file):
        run = tbridge.simulate(given)
        del run.summary["run"]["wall_s"]
        assert run.summary == summary
    # The heaviest string 20 % thinner (area, radius, mass and stiffness together): run as built,
    # another bridge, as the command line runs the edited file.
    nb = file["topology"]["bars"]
    k = max(range(nb, len(file["members"])), key=lambda i: file["members"][i]["mass"])
    m = file["members"][k]
    mat = file["config"]["material"]
    m["area"] *= 0.8
    m["radius"] = math.sqrt(m["area"] / math.pi)
    m["mass"] = mat["density"] * m["area"] * m["length"]
    m["stiffness"] = mat["youngs_modulus"] * m["area"] / m["rest_length"]
    (tmp_path / "edited.json").write_text(json.dumps(file))
    code, err = cli("simulate", str(tmp_path / "edited.json"), "-q", "-o", str(tmp_path / "edited"))
    assert code == 0, err
    edited = json.loads((tmp_path / "edited" / "summary.json").read_text())
    del edited["run"]["wall_s"]
    run = tbridge.simulate(file)
    del run.summary["run"]["wall_s"]
    assert run.summary == edited
    assert edited["max_string_stress"] != summary["max_string_stress"]


def test_a_structure_is_designed_as_tbridge_design_designs_it(tmp_path):
    # The 10-bar stress problem: the module's design file is the command line's, byte for byte
    # (the same library), and its properties read that file's numbers.
    config = os.path.join(SOURCE, "configs", "truss_10bar_stress.json")
    d = tbridge.design(config)
    assert isinstance(d, tbridge.StructureDesign)
    path = tmp_path / "d.json"
    code, err = cli("design", config, "-q", "-o", str(path))
    assert code == 0, err
    assert d.to_json() == path.read_text()
    written = json.loads(path.read_text())
    assert list(d.areas) == [m["area"] for m in written["members"]]
    assert d.structure_mass == written["mass"]["structure"]
    assert d.verdict == "PASS" and d.proved_local_optimum
    assert d.group_names == [g["name"] for g in written["groups"]]
    assert list(d.prestress) == [0.0] * len(written["members"])  # no prestress asked


def test_a_prestressed_structure_gives_its_prestress():
    # The prism designed with its prestress: the module's forces are the file's, its prestress a
    # self-stress with the bars in compression and the strings in tension.
    d = tbridge.design(os.path.join(SOURCE, "configs", "motes_prism_design.json"))
    written = json.loads(d.to_json())
    assert list(d.prestress) == [m["prestress_n"] for m in written["members"]]
    assert all(n < 0 for n in d.prestress[:3]) and all(n > 0 for n in d.prestress[3:])
    assert d.verdict == "PASS" and d.proved_local_optimum
