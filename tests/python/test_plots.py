"""The figure scripts on real outputs: tools/plot_sweep.py bridge on design files (planar and 3D)
and tools/plot_dynamics.py on a run that starts from the loaded equilibrium. Each figure must be
written and carry what an engineer reads off it; the SVG keeps its text as text, so its labels
can be checked."""

import html
import importlib.util
import json
import os
import re
import subprocess
import sys

import pytest

pytest.importorskip("matplotlib")

SOURCE = os.environ["TBRIDGE_SOURCE_DIR"]
BINARY = os.environ["TBRIDGE_BINARY"]
DEFAULT = os.path.join(SOURCE, "configs", "default.json")
PLOT_SWEEP = os.path.join(SOURCE, "tools", "plot_sweep.py")
PLOT_DYNAMICS = os.path.join(SOURCE, "tools", "plot_dynamics.py")


def run(*args):
    """Runs a command; returns (exit code, stderr)."""
    r = subprocess.run([*args], capture_output=True, text=True)
    return r.returncode, r.stderr


def design_file(path, config):
    """`tbridge design` of `config` (a path) written to `path`: a design that fails its checks
    (exit 1) is still a design to draw."""
    code, err = run(BINARY, "design", config, "-q", "-o", str(path))
    assert code in (0, 1), err
    with open(path) as f:
        return json.load(f)


def svg_texts(path):
    """The text elements of an SVG, unescaped."""
    with open(path) as f:
        return [html.unescape(t) for t in re.findall(r"<text[^>]*>([^<]*)</text>", f.read())]


def labelled(path, kind):
    """The nodes or members (kind "node", "member") a drawing labels, from its labels' SVG ids:
    "elevation-node-1-4" is the label of nodes 1 and 4, which that view puts on one point."""
    with open(path) as f:
        ids = re.findall(r'id="(?:elevation|plan)-%s-([0-9-]+)"' % kind, f.read())
    return {int(v) for i in ids for v in i.split("-")}


@pytest.fixture(scope="module")
def planar(tmp_path_factory):
    path = tmp_path_factory.mktemp("planar") / "design.json"
    return path, design_file(path, DEFAULT)


@pytest.fixture(scope="module")
def spatial(tmp_path_factory):
    path = tmp_path_factory.mktemp("spatial") / "design.json"
    return path, design_file(path, os.path.join(SOURCE, "configs", "paper_3d.json"))


def test_planar_drawing_labels_every_node_and_member_with_the_verdict(planar, tmp_path):
    path, design = planar
    png = tmp_path / "bridge.png"
    code, err = run(sys.executable, PLOT_SWEEP, "bridge", str(path), "-o", str(png),
                    "--case", "sls_travelling at station 4")
    assert code == 0, err
    svg = tmp_path / "bridge.svg"
    assert png.stat().st_size > 50_000
    assert svg.stat().st_size > 20_000
    texts = svg_texts(svg)
    assert labelled(svg, "node") == set(range(1, len(design["nodes"]) + 1))
    assert labelled(svg, "member") == set(range(1, len(design["members"]) + 1))
    assert {str(k) for k in range(1, len(design["nodes"]) + 1)} <= set(texts)
    assert {"m%d" % k for k in range(1, len(design["members"]) + 1)} <= set(texts)
    # The table names every member as the design file does.
    assert {m["name"] for m in design["members"]} <= set(texts)
    joined = "\n".join(texts)
    assert "verdict " + design["verdict"]["outcome"] in joined
    # The governing member: the largest utilisation, its mode and case.
    top = max(design["members"], key=lambda m: m["utilisation"])
    assert top["name"] in joined and top["governing_case"] in joined
    # Station 4 of the travelling family is the 4th such entry of deflection_max, along x.
    family = [e for e in design["deflection_max"] if e["case"].startswith("sls_travelling at node ")]
    assert "%.2f mm" % (1e3 * family[3]["deflection"]) in texts


def test_an_svg_output_is_written_alone(planar, tmp_path):
    path, _ = planar
    code, err = run(sys.executable, PLOT_SWEEP, "bridge", str(path), "-o", str(tmp_path / "only.svg"))
    assert code == 0, err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["only.svg"]


def test_an_unknown_case_is_refused_with_the_cases_named(planar, tmp_path):
    path, _ = planar
    code, err = run(sys.executable, PLOT_SWEEP, "bridge", str(path), "-o", str(tmp_path / "x.png"),
                    "--case", "no_such_case")
    assert code != 0
    assert "sls_travelling" in err and "no_such_case" in err
    assert not (tmp_path / "x.png").exists()


def test_3d_drawing_has_elevation_and_plan_and_flags_members_over_1(spatial, tmp_path):
    path, design = spatial
    png = tmp_path / "bridge3d.png"
    code, err = run(sys.executable, PLOT_SWEEP, "bridge", str(path), "-o", str(png))
    assert code == 0, err
    assert png.stat().st_size > 50_000
    svg = tmp_path / "bridge3d.svg"
    texts = svg_texts(svg)
    joined = "\n".join(texts)
    assert "elevation (x-y)" in joined and "plan (x-z)" in joined
    assert labelled(svg, "node") == set(range(1, len(design["nodes"]) + 1))
    # A member along one view's line of sight is drawn in the other: every member in some view.
    assert labelled(svg, "member") == set(range(1, len(design["members"]) + 1))
    over = [m for m in design["members"] if m["utilisation"] > 1 + 1e-9]
    assert over, "the paper's 3D design is expected to fail its dynamic check"
    assert any(t.endswith(" !") for t in texts)
    assert "verdict " + design["verdict"]["outcome"] in joined


def load_plot_dynamics():
    spec = importlib.util.spec_from_file_location("plot_dynamics", PLOT_DYNAMICS)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def loaded_run(tmp_path_factory):
    """A short run of an engineering config: it starts from the static equilibrium under the
    design loads, where the deck has sagged below y = 0; a timed load on the middle deck node."""
    folder = tmp_path_factory.mktemp("run")
    with open(DEFAULT) as f:
        config = json.load(f)
    config["bridge"]["n"] = 2
    config["dynamics"] = {"duration": 0.3, "dt": 1e-4,
                          "loads": [{"t_start": 0.05, "t_end": 0.2, "node": 2, "force": [0, -5000, 0]}],
                          "record": {"nodes": [1, 2, 3, 4, 5, 6], "every": 10}}
    path = folder / "config.json"
    path.write_text(json.dumps(config))
    code, err = run(BINARY, "simulate", str(path), "-o", str(folder / "out"))
    assert code == 0, err
    design = design_file(folder / "design.json", str(path))
    return folder / "out", design


def test_deck_nodes_of_a_loaded_start_are_the_drawn_deck(loaded_run):
    out, design = loaded_run
    with open(out / "summary.json") as f:
        summary = json.load(f)
    fixed = set(design["topology"]["fixed_nodes"])
    drawn_deck = sorted(k + 1 for k, p in enumerate(design["nodes"]) if p[1] == 0 and k + 1 not in fixed)
    start = summary["model"]["members"]["positions"]
    assert all(start[v - 1][1] < 0 for v in drawn_deck), "the run should start from the sagged deck"
    assert load_plot_dynamics().deck_nodes(summary) == drawn_deck


def test_deck_and_snapshot_figures_of_a_loaded_start(loaded_run, tmp_path):
    out, _ = loaded_run
    deck = tmp_path / "deck.png"
    code, err = run(sys.executable, PLOT_DYNAMICS, "deck", str(out), "-o", str(deck))
    assert code == 0, err
    assert deck.stat().st_size > 20_000
    snaps = tmp_path / "snapshots.png"
    code, err = run(sys.executable, PLOT_DYNAMICS, "snapshots", str(out), "-o", str(snaps), "--times", "0.1,0.2",
                    "--scale", "50")
    assert code == 0, err
    assert snaps.stat().st_size > 20_000
