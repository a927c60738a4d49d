"""The Python module against the CLI it stands beside (ctest runs this with pytest; PYTHONPATH=build/python,
GRIT_EXECUTABLE=build/grit, GRIT_SOURCE_DIR=the repository)."""
import json
import os
import pathlib
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

import grit

ROOT = pathlib.Path(os.environ.get("GRIT_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
CLI = os.environ.get("GRIT_EXECUTABLE", str(ROOT / "build" / "grit"))
TANK = ROOT / "cases" / "hydrostatic_2d" / "case.toml"
DAM = ROOT / "cases" / "dambreak_2d" / "case.toml"
# The dam break coarse and short: 1,250 water particles, 4 outputs.
DAM_SETS = {"numerics.particle_spacing": 0.008, "time.end": 0.02, "output.interval": 0.005}


def coarse_dam() -> grit.Case:
    case = grit.Case.load(DAM)
    for k, v in DAM_SETS.items():
        case.set(k, v)
    return case


def cli(*args, cwd=None) -> subprocess.CompletedProcess:
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, cwd=cwd, timeout=600)


def test_load_set_and_overrides():
    case = grit.Case.load(TANK)
    assert case.name == "hydrostatic_2d" and case.dimension == 2 and case.end_time == 1.0
    assert case.set("time.end", 0.25) is case
    case.set("output.snapshots", False).set("physics.gravity", [0.0, -9.81])
    assert case.end_time == 0.25
    assert case.overrides == ["time.end=0.25", "output.snapshots=false", "physics.gravity=[0.0, -9.81]"]
    copy = case.copy().set("time.end", 0.5)
    assert copy.end_time == 0.5 and case.end_time == 0.25
    checked = case.check()
    assert checked["name"] == "hydrostatic_2d" and checked["estimate"].startswith("~")
    steps_and_particles = checked["estimate"].split(" outputs")[0]  # "~2e+03 steps, ~1.58e+03 particles, 6"
    assert steps_and_particles in cli("check", TANK, *[a for o in case.overrides for a in ("--set", o)]).stdout


def test_bad_key_raises_the_cli_message_with_its_suggestion():
    case = grit.Case.load(TANK)
    with pytest.raises(grit.CaseError) as e:
        case.set("time.ned", 1.0)
    assert str(e.value) == "key 'time.ned' = 1: unknown key (did you mean 'end'?)"
    # The same words as the command line's --set.
    r = cli("check", TANK, "--set", "time.ned=1.0")
    assert r.returncode == 2 and str(e.value) in r.stderr
    # A refused value leaves the case as it was.
    with pytest.raises(grit.CaseError, match="numerics.particle_spacing.*must be positive"):
        case.set("numerics.particle_spacing", -0.01)
    assert case.overrides == []
    assert isinstance(e.value, ValueError)


def test_a_value_python_cannot_write_as_toml_is_a_type_error():
    with pytest.raises(TypeError, match="not object"):
        grit.Case.load(TANK).set("time.end", object())


def test_from_string_runs_like_the_file():
    text = TANK.read_text()
    case = grit.Case.from_string(text, name="tank", folder=TANK.parent).set("time.end", 0.05)
    assert case.name == "tank"
    a = grit.run(case)
    b = grit.run(grit.Case.load(TANK).set("time.end", 0.05))
    assert a["status"] == "completed" and a["steps"] == b["steps"] > 0
    assert a["values"] == b["values"]
    with pytest.raises(grit.CaseError, match="line 1: malformed TOML"):
        grit.Case.from_string("[time\nend = 1")


def test_dam_break_files_equal_the_cli_bit_for_bit(tmp_path):
    run = grit.run(coarse_dam(), out=tmp_path / "py", threads=2)
    sets = [a for k, v in DAM_SETS.items() for a in ("--set", f"{k}={v!r}")]
    r = cli("run", DAM, "--out", tmp_path / "cli", "--quiet", *sets)
    assert r.returncode == 0, r.stderr
    for name in ["series.csv", "snapshots/dambreak_2d_000004.vtu", "dambreak_2d.pvd"]:
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name
    assert isinstance(run, grit.Run) and run.summary["status"] == "completed"
    series = run.series
    times = np.asarray(series["time"])
    assert np.allclose(times, [0.0, 0.005, 0.01, 0.015, 0.02])
    # The snapshot read back: every particle, with its arrays.
    last = run.snapshot(-1)
    assert last["Points"].shape == (run.summary["particles"], 3)
    assert last["id"].dtype == np.int64 and len(np.unique(last["id"])) == len(last["id"])
    assert run.snapshot_times() == pytest.approx(list(times))
    assert run.crater() is None and run.impacts is None


def test_a_run_extended_from_its_checkpoint_equals_one_that_never_stopped(tmp_path):
    straight = grit.run(coarse_dam(), out=tmp_path / "straight")
    extended = grit.run(coarse_dam().set("time.end", 0.01), out=tmp_path / "extended")
    assert extended.checkpoints, "a finished run leaves its checkpoint"
    assert extended.restart(end_time=0.02) is extended  # the case the checkpoint holds
    for name in ["series.csv", "snapshots/dambreak_2d_000004.vtu"]:
        assert (tmp_path / "straight" / name).read_bytes() == (tmp_path / "extended" / name).read_bytes(), name
    assert extended.summary["segments"] == 2 and straight.summary["steps"] == extended.summary["steps"]
    # Given the case again, as the command line's restart takes it: already at its end, nothing runs.
    before = (tmp_path / "extended" / "series.csv").read_bytes()
    extended.restart(case=coarse_dam())
    assert (tmp_path / "extended" / "series.csv").read_bytes() == before


def test_an_earlier_run_is_not_replaced_unless_asked(tmp_path):
    case = grit.Case.load(TANK).set("time.end", 0.05)
    grit.run(case, out=tmp_path)
    with pytest.raises(grit.CaseError, match="holds a completed run.*overwrite=True"):
        grit.run(case, out=tmp_path)
    grit.run(case, out=tmp_path, overwrite=True)


def test_progress_is_called_after_every_output_and_can_stop_the_run(tmp_path):
    seen = []
    grit.run(coarse_dam(), progress=lambda t, step: seen.append((t, step)))
    assert [t for t, _ in seen] == pytest.approx([0.0, 0.005, 0.01, 0.015, 0.02])
    assert seen[0][1] == 0 and all(a[1] < b[1] for a, b in zip(seen, seen[1:]))

    def stop_at_10ms(t, step):
        if t >= 0.01:
            raise ValueError("enough")

    with pytest.raises(ValueError, match="enough"):
        grit.run(coarse_dam(), out=tmp_path, progress=stop_at_10ms)
    assert len((tmp_path / "series.csv").read_text().splitlines()) == 1 + 3  # header, 0, 5 ms, 10 ms


def test_ctrl_c_stops_an_advance_after_its_step():
    script = (f"import grit, time\nsim = grit.Simulation(grit.Case.load({str(DAM)!r}), threads=1)\n"
              "print('ready', flush=True)\n"
              "try:\n    sim.advance(5.0)\nexcept KeyboardInterrupt:\n"
              "    print('stopped at step', sim.step, 't =', sim.time, flush=True)\n")
    child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True, env=dict(os.environ))
    assert child.stdout.readline().strip() == "ready"
    time.sleep(2.0)
    start = time.time()
    child.send_signal(signal.SIGINT)
    out, err = child.communicate(timeout=120)
    assert child.returncode == 0, err
    assert out.startswith("stopped at step ") and int(out.split()[3]) > 0
    assert time.time() - start < 10.0


def test_a_run_under_an_mpi_launcher_with_more_than_one_process_is_refused():
    script = (f"import grit\ntry:\n    grit.run(grit.Case.load({str(TANK)!r}))\n"
              "except RuntimeError as e:\n    print(e)\n")
    r = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                       env=dict(os.environ, OMPI_COMM_WORLD_SIZE="2"))
    assert r.returncode == 0 and "runs a case in one process" in r.stdout and "OMPI_COMM_WORLD_SIZE = 2" in r.stdout


def test_run_without_out_writes_nothing(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    summary = grit.run(grit.Case.load(TANK).set("time.end", 0.05))
    assert summary["status"] == "completed" and summary["values"]["particles"] > 0
    assert list(tmp_path.iterdir()) == []


def test_advancing_in_pieces_equals_one_run_to_the_same_time(tmp_path):
    whole = grit.Simulation(coarse_dam()).advance(0.02)
    pieces = grit.Simulation(coarse_dam())
    pieces.advance(0.01)  # an output time
    assert pieces.time == 0.01
    pieces.advance(0.02)
    assert (pieces.step, pieces.time) == (whole.step, whole.time)
    a, b = whole.fields("fluid"), pieces.fields("fluid")
    for name in a:
        assert np.array_equal(a[name], b[name], equal_nan=True), name
    assert whole.outputs() == pieces.outputs()
    # And a run of the CLI to that time ends with the same values (summary.json keeps every digit).
    r = cli("run", DAM, "--out", tmp_path, "--quiet",
            *[a for k, v in DAM_SETS.items() for a in ("--set", f"{k}={v!r}")])
    assert r.returncode == 0, r.stderr
    summary = json.loads((tmp_path / "summary.json").read_text())
    values = whole.outputs()
    for name in ["kinetic_energy", "mass_total", "max_velocity", "particles"]:
        assert values[name] == summary[name], name


def test_fields_by_phase():
    sim = grit.Simulation(coarse_dam())
    water, walls = sim.fields("fluid"), sim.fields("wall")
    n = len(water["id"])
    assert n > 1000 and water["position"].shape == (n, 2) and water["velocity"].shape == (n, 2)
    assert water["id"].dtype == np.int64 and water["phase"].dtype == np.int32
    assert set(np.unique(water["phase"])) == {0} and set(np.unique(walls["phase"])) == {2}
    assert sim.fields("grains")["position"].shape == (0, 2)
    sim.advance(0.005)
    moved = sim.fields("fluid")
    assert np.max(np.abs(moved["velocity"])) > 0.0
    with pytest.raises(ValueError, match="phases are 'fluid', 'solid', 'wall' and 'grains'"):
        sim.fields("water")


def test_a_checkpoint_continues_bit_for_bit(tmp_path):
    grit.Simulation(coarse_dam()).advance(0.01).checkpoint(tmp_path / "mid.h5")
    restarted = grit.Simulation(coarse_dam(), checkpoint=tmp_path / "mid.h5")
    assert (restarted.time, restarted.step) == (0.01, grit.Simulation(coarse_dam()).advance(0.01).step)
    restarted.advance(0.02)
    straight = grit.Simulation(coarse_dam()).advance(0.02)
    assert restarted.outputs() == straight.outputs()
    a, b = restarted.fields("fluid"), straight.fields("fluid")
    for name in a:
        assert np.array_equal(a[name], b[name], equal_nan=True), name
    # A checkpoint of another case is refused, naming it.
    with pytest.raises(grit.CaseError, match="checkpoint"):
        grit.Simulation(grit.Case.load(TANK), checkpoint=tmp_path / "mid.h5")


def test_a_sweep_of_two_points_runs_each_as_the_cli(tmp_path):
    case = grit.Case.load(TANK).set("output.snapshots", False)
    table = grit.sweep(case, {"time.end": [0.01, 0.02]}, out=tmp_path, jobs=2, threads=2)
    assert list(np.asarray(table["time.end"])) == [0.01, 0.02]
    assert list(np.asarray(table["status"])) == ["completed", "completed"]
    for end, folder in zip([0.01, 0.02], np.asarray(table["folder"])):
        kept = json.loads((tmp_path / folder / "summary.json").read_text())
        alone = grit.run(grit.Case.load(TANK).set("output.snapshots", False).set("time.end", end))
        assert kept["steps"] == alone["steps"] and kept["kinetic_energy"] == alone["values"]["kinetic_energy"]
    assert np.isnan(np.asarray(table["crater_depth"], dtype=float)).all()  # no crater: empty cells
    # Without out: a temporary folder, gone afterwards; a bad key is the CLI's refusal.
    assert len(grit.sweep(case, {"time.end": [0.01]})["status"]) == 1
    with pytest.raises(grit.CaseError, match="time.ned"):
        grit.sweep(case, {"time.ned": [0.01]})
    with pytest.raises(TypeError, match="has a comma"):
        grit.sweep(case, {"physics.gravity": [[0.0, -9.81]]})


def test_threads_must_be_positive_and_last_for_the_run():
    with pytest.raises(grit.CaseError, match="threads=0: must be a positive whole number"):
        grit.run(grit.Case.load(TANK), threads=0)
    before = grit._grit.max_threads()
    grit.run(grit.Case.load(TANK).set("time.end", 0.01), threads=1)
    grit.Simulation(grit.Case.load(TANK), threads=1).advance(0.01)
    assert grit._grit.max_threads() == before


def test_python_m_grit_is_the_cli():
    env = dict(os.environ, GRIT_EXECUTABLE=CLI)
    r = subprocess.run([sys.executable, "-m", "grit", "--version"], capture_output=True, text=True, env=env)
    assert r.returncode == 0 and r.stdout.startswith(f"grit {grit.version} (git ")
    r = subprocess.run([sys.executable, "-m", "grit", "check", TANK, "--set", "time.ned=1"], capture_output=True,
                       text=True, env=env)
    assert r.returncode == 2 and "did you mean 'end'" in r.stderr


def test_ctrl_c_stops_the_run_with_a_checkpoint_and_raises_keyboard_interrupt(tmp_path):
    script = (f"import grit\ncase = grit.Case.load({str(DAM)!r}).set('time.end', 5.0)\n"
              f"grit.run(case, out={str(tmp_path)!r}, threads=1)\n")
    child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True, env=dict(os.environ))
    deadline = time.time() + 120
    while not (tmp_path / "run.log").exists() and time.time() < deadline:
        time.sleep(0.2)
    time.sleep(2.0)  # stepping by now
    child.send_signal(signal.SIGINT)
    _, err = child.communicate(timeout=300)
    assert child.returncode != 0 and "KeyboardInterrupt" in err and "interrupted by signal 2" in err
    assert list((tmp_path / "checkpoints").glob("*.h5")), "no checkpoint written"
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert summary["status"] == "interrupted"
