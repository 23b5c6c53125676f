"""pytest suite of gridcar's Python package (run by CTest: test `python_pytest`)."""
import math
import os
import pathlib
import re
import subprocess
import sys
import threading

import numpy as np
import pytest

import gridcar

SOURCE = pathlib.Path(os.environ.get("GRIDCAR_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
SHARED = pathlib.Path(os.environ.get("GRIDCAR_SHARED_DIR", SOURCE.parent / "shared"))
WILLOW = SHARED / "maps/ros/willow_garage/willow-2010-02-18-0.10.yaml"
needs_shared = pytest.mark.skipif(not WILLOW.exists(), reason="real maps not available: %s does not exist "
                                  "(a fresh clone has no ../shared; CI provides it)" % WILLOW)


def walled(rows=60, cols=100, wall=True):
    """A walled rectangle at 0.5 m, with an inner wall from the top down to y = 10 m at x = 25 m."""
    occ = np.zeros((rows, cols), bool)
    occ[0, :] = occ[-1, :] = occ[:, 0] = occ[:, -1] = True
    if wall:
        occ[20:, 50] = True  # rows counted from the bottom (ROS order): y 10 .. 30 m
    return occ


def free_at(occ, res, x, y):
    return not occ[int(y / res), int(x / res)]


def check_body_free(occ, res, path, vehicle):
    """Independent of gridcar's checker: the outline's corners and edge points of every pose at
    most 5 cm apart lie on free cells."""
    outline = vehicle.outline
    dense = [path[0]]
    for a, b in zip(path, path[1:]):
        n = max(1, int(math.ceil(np.hypot(*(b[:2] - a[:2])) / 0.05)))
        for k in range(1, n + 1):
            t = k / n
            yaw = a[2] + t * math.remainder(b[2] - a[2], 2 * math.pi)
            dense.append(np.array([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), yaw]))
    edge = []
    for p, q in zip(outline, np.vstack([outline[1:], outline[:1]])):
        n = max(1, int(math.ceil(np.hypot(*(q - p)) / 0.1)))
        edge += [p + (q - p) * k / n for k in range(n)]
    edge = np.array(edge)
    for x, y, yaw in dense:
        c, s = math.cos(yaw), math.sin(yaw)
        for u, v in edge:
            assert free_at(occ, res, x + c * u - s * v, y + s * u + c * v), "body hits a wall at (%.2f, %.2f)" % (x, y)


def test_version_presets_and_planners():
    assert re.match(r"\d+\.\d+\.\d+", gridcar.__version__)
    assert "paper-c-robot" in gridcar.vehicle_presets()
    names = gridcar.planners()
    assert "corner-astar" in names and "improved-astar" in names and "rrtconnect" in names


def test_map_from_array_round_trip_and_row_order():
    occ = walled()
    m = gridcar.Map.from_array(occ, resolution=0.5, origin=(-3.0, 2.0))
    assert (m.width, m.height, m.resolution) == (100, 60, 0.5)
    assert m.origin == (-3.0, 2.0, 0.0)
    assert m.extent == (-3.0, 47.0, 2.0, 32.0)
    back = m.to_array()
    assert back.dtype == np.int8
    assert np.array_equal(back == 100, occ)
    assert np.array_equal(m.to_array(row_order="top"), back[::-1])
    top = gridcar.Map.from_array(occ[::-1], resolution=0.5, origin=(-3.0, 2.0), row_order="top")
    assert np.array_equal(top.to_array(), back)
    # ROS values: negative unknown, >= 65 occupied
    ros = np.array([[0, -1, 64, 65, 100]], dtype=np.int16)
    assert list(gridcar.Map.from_array(ros, 1.0).to_array()[0]) == [0, -1, 0, 100, 100]
    assert m.costs() is None


def test_distance_field_matches_brute_force():
    rng = np.random.default_rng(7)
    occ = rng.random((30, 40)) < 0.08
    m = gridcar.Map.from_array(occ, resolution=0.2)
    d = m.distance_field()
    assert d.shape == (30, 40) and d.dtype == np.float32
    # the cells beyond the edge count as blocked too
    padded = np.pad(occ, 1, constant_values=True)
    blocked = np.argwhere(padded) - 1
    for r, c in [(0, 0), (5, 7), (29, 39), (14, 20), (22, 3), (10, 30)]:
        expect = 0.0 if occ[r, c] else 0.2 * np.min(np.hypot(blocked[:, 0] - r, blocked[:, 1] - c))
        assert d[r, c] == pytest.approx(expect, abs=1e-4)


def test_plan_is_exact_drivable_and_ends_at_the_goal():
    occ = walled()
    m = gridcar.Map.from_array(occ, resolution=0.5)
    veh = gridcar.Vehicle("paper-i")
    for planner in ("corner-astar", "improved-astar"):
        r = gridcar.plan(m, start=(5, 5, 0), goal=(45, 20, math.pi / 2), planner=planner, vehicle=veh)
        assert r.exact and r.status == "Exact solution", r
        assert r.drivable, r.not_drivable_because
        assert r.path.shape[1] == 3 and len(r.path) > 10
        assert np.allclose(r.path[0], [5, 5, 0], atol=1e-6)
        assert np.hypot(*(r.path[-1, :2] - [45, 20])) < 1e-6
        assert abs(math.remainder(r.path[-1, 2] - math.pi / 2, 2 * math.pi)) < 1e-6
        # it goes round the inner wall (below y = 10 m where it crosses x = 25 m)
        crossing = r.path[np.argmin(np.abs(r.path[:, 0] - 25.25))]
        assert crossing[1] < 10.0
        seg = np.hypot(*np.diff(r.path[:, :2], axis=0).T).sum()
        assert r.length == pytest.approx(seg, rel=1e-6)
        check_body_free(occ, 0.5, r.path, veh)
        assert r.driving_time_profile > r.length / veh.max_speed


def test_free_headings_and_goal_errors():
    m = gridcar.Map.from_array(walled(), resolution=0.5)
    r = gridcar.plan(m, start=(5, 5), goal=(45, 20), vehicle="paper-i")
    assert r.exact
    assert r.goal_distance == pytest.approx(0.0, abs=1e-6)
    assert math.isnan(r.goal_heading_error_deg)  # no goal yaw asked for


def test_errors_are_python_exceptions_with_the_messages():
    m = gridcar.Map.from_array(walled(), resolution=0.5)
    with pytest.raises(gridcar.InputError, match="in collision for vehicle paper-i"):
        gridcar.plan(m, (25.2, 25), (45, 20))
    with pytest.raises(gridcar.InputError, match="outside the map, which spans x 0.000..50.000"):
        gridcar.plan(m, (5, 5), (60, 20))
    with pytest.raises(ValueError, match="unknown planner 'nope'"):
        gridcar.plan(m, (5, 5), (45, 20), planner="nope")
    with pytest.raises(gridcar.InputError, match="heuristic_weight"):
        gridcar.plan(m, (5, 5), (45, 20), settings={"heuristic_weight": "abc"})
    with pytest.raises(gridcar.InputError, match="time_limit"):
        gridcar.plan(m, (5, 5), (45, 20), time_limit=-1)
    with pytest.raises(gridcar.InputError, match=r"\(x, y\) or \(x, y, yaw_rad\)"):
        gridcar.plan(m, (5, 5, 0, 1), (45, 20))
    with pytest.raises(gridcar.MapLoadError, match="/no/such/map.yaml"):
        gridcar.Map.load("/no/such/map.yaml")
    with pytest.raises(gridcar.MapLoadError, match="unknown vehicle field 'lenght'"):
        gridcar.Vehicle.from_dict({"lenght": 3.0})
    with pytest.raises(ValueError, match="unknown vehicle preset"):
        gridcar.Vehicle("no-such-car")
    with pytest.raises(gridcar.InputError, match="2D"):
        gridcar.Map.from_array(np.zeros(5), 1.0)
    assert issubclass(gridcar.InputError, ValueError) and issubclass(gridcar.MapLoadError, ValueError)


def test_a_pose_on_unknown_cells_names_the_python_switch():
    grid = np.zeros((20, 40), np.int8)
    grid[:, :10] = -1  # unknown (ROS's OccupancyGrid value)
    m = gridcar.Map.from_array(grid, resolution=0.5)
    with pytest.raises(gridcar.InputError, match=r"unknown.*unknown_free=True of Map.load\(\) or Map.from_array\(\)"):
        gridcar.plan(m, (2, 5), (15, 5), vehicle="paper-c-robot")
    free = gridcar.Map.from_array(grid, resolution=0.5, unknown_free=True)
    assert gridcar.plan(free, (2, 5), (15, 5), vehicle="paper-c-robot").exact


def test_log_lines_carry_no_source_location(capfd):
    occ = walled(wall=False)
    occ[10:20, 70:80] = True
    occ[12:18, 72:78] = False  # a closed room, 3 m across: the goal inside is cut off
    m = gridcar.Map.from_array(occ, resolution=0.5)
    r = gridcar.plan(m, (5, 5, 0), (37.5, 7.5, 0), vehicle="paper-c-robot", time_limit=2)
    assert not r.exact
    err = capfd.readouterr().err
    assert "Warning: corner-astar:" in err and " at line " not in err, err


def test_every_public_name_has_a_docstring():
    missing = []
    for cname in ["Map", "Vehicle", "Scene", "PlanResult", "DriveResult"]:
        for name, member in vars(getattr(gridcar, cname)).items():
            if not name.startswith("_") and not (getattr(member, "__doc__", None) or "").strip():
                missing.append("%s.%s" % (cname, name))
    for name in ["plan", "drive", "plot", "planners", "vehicle_presets"]:
        if not (getattr(gridcar, name).__doc__ or "").strip():
            missing.append(name)
    assert not missing, "no docstring: " + ", ".join(missing)


def test_vehicle_from_dict_and_settings_of_every_kind():
    veh = gridcar.Vehicle.from_dict({"preset": "paper-i", "scale": 0.5})
    base = gridcar.Vehicle("paper-i")
    assert veh.length == pytest.approx(base.length / 2)
    assert veh.min_turning_radius == pytest.approx(base.min_turning_radius / 2)
    m = gridcar.Map.from_array(walled(), resolution=0.5)
    scene = gridcar.Scene(m, vehicle=veh, space="reeds-shepp")
    r = scene.plan((5, 5, 0), (10, 5, math.pi), settings={"reverse": "on", "heuristic_weight": 1.5}, time_limit=5.0)
    assert r.exact and r.drivable
    assert scene.why_invalid((5, 5, 0)) == ""
    assert "in collision" in scene.why_invalid((25.2, 25.0))


def test_vehicle_from_a_yaml_file(tmp_path):
    f = tmp_path / "small-car.yaml"
    f.write_text("preset: paper-i\nscale: 0.5\n")
    veh = gridcar.Vehicle(str(f))
    base = gridcar.Vehicle("paper-i")
    assert veh.length == pytest.approx(base.length / 2) and veh.width == pytest.approx(base.width / 2)
    # plan() takes the file's name as it takes a preset's
    m = gridcar.Map.from_array(walled(), resolution=0.5)
    r = gridcar.plan(m, (5, 5, 0), (45, 20, math.pi / 2), vehicle=str(f))
    assert r.exact and r.drivable
    bad = tmp_path / "bad.yaml"
    bad.write_text("lenght: 3.0\n")
    with pytest.raises(gridcar.MapLoadError, match="lenght"):
        gridcar.Vehicle(str(bad))


def test_plot_tints_the_cost_layer(tmp_path):
    import matplotlib
    matplotlib.use("Agg")
    # a grey-level map read in ROS map_server's 'scale' mode: the grey band is free with a cost
    rows, cols = 40, 60
    img = np.full((rows, cols), 254, np.uint8)
    img[0, :] = img[-1, :] = img[:, 0] = img[:, -1] = 0
    img[:, 28:32] = 160  # a costly band across the middle
    (tmp_path / "band.pgm").write_bytes(b"P5\n%d %d\n255\n" % (cols, rows) + img.tobytes())
    (tmp_path / "band.yaml").write_text("image: band.pgm\nresolution: 0.5\norigin: [0.0, 0.0, 0.0]\n"
                                        "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\nmode: scale\n")
    m = gridcar.Map.load(str(tmp_path / "band.yaml"))
    costs = m.costs()
    assert costs is not None and costs[:, 29].max() > 0 and costs[:, 10].max() == 0
    r = gridcar.Scene(m).plan((5, 10, 0), (25, 10, 0))
    ax = gridcar.plot(m, plan=r)
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert "cost layer" in labels
    plain = gridcar.Map.from_array(walled(), resolution=0.5)
    assert plain.costs() is None
    assert "cost layer" not in [t.get_text() for t in gridcar.plot(plain).get_legend().get_texts()]


def test_drive_reaches_the_goal():
    m = gridcar.Map.from_array(walled(), resolution=0.5)
    scene = gridcar.Scene(m, vehicle="paper-i")
    r = scene.plan((5, 5, 0), (45, 20, math.pi / 2))
    d = scene.drive(r)
    assert d.outcome == "reached" and d.reached, d.reason
    t = d.trajectory
    assert t.shape[1] == 6 and len(t) > 10
    assert np.all(np.diff(t[:, 0]) > 0)
    assert np.hypot(t[-1, 1] - 45, t[-1, 2] - 20) < 0.6
    assert d.driving_time == pytest.approx(t[-1, 0], abs=0.06)
    # the same from an array, and bad paths
    assert gridcar.drive(m, r.path).outcome == "reached"
    with pytest.raises(gridcar.InputError, match="N x 3"):
        scene.drive(np.zeros((4, 2)))
    with pytest.raises(gridcar.InputError, match="off the map or in collision"):
        scene.drive(np.array([[25.2, 25.0, 0.0], [30.0, 25.0, 0.0]]))


def test_goal_tolerance_in_plan_and_drive():
    m = gridcar.Map.from_array(walled(), resolution=0.5)
    scene = gridcar.Scene(m, vehicle="paper-i")
    exact = scene.plan((5, 5, 0), (45, 20, math.pi / 2))
    r = gridcar.plan(m, (5, 5, 0), (45, 20, math.pi / 2), goal_tolerance=(1.0, 0.3))
    assert r.exact and r.drivable
    x, y, yaw = r.path[-1]
    assert math.hypot(x - 45, y - 20) <= 1.0 + 1e-6
    assert abs(math.remainder(yaw - math.pi / 2, 2 * math.pi)) <= 0.3 + 1e-6
    assert r.length <= exact.length + 1e-6
    d = scene.drive(r, goal_tolerance=(0.5, 0.3))
    assert d.reached, d.reason
    for bad in [(-1.0, 0.0), (0.5, 4.0), "abc", (1.0, 2.0, 3.0), float("nan")]:
        with pytest.raises(gridcar.InputError, match="goal_tolerance"):
            scene.plan((5, 5, 0), (45, 20), goal_tolerance=bad)


def test_threads_drive_side_by_side_with_the_same_answers():
    """Drives in four threads (a scene each, the GIL released while they run) give the one
    thread's trajectory, sample for sample."""
    m = gridcar.Map.from_array(walled(), resolution=0.5)
    path = gridcar.Scene(m, vehicle="paper-i").plan((5, 5, 0), (45, 20, math.pi / 2)).path
    alone = gridcar.Scene(m, vehicle="paper-i").drive(path)
    assert alone.reached, alone.reason
    outs = [None] * 4

    def work(k):
        outs[k] = gridcar.Scene(m, vehicle="paper-i").drive(path)

    threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
    for d in outs:
        assert d.outcome == alone.outcome and np.array_equal(d.trajectory, alone.trajectory)


def test_planning_releases_the_gil():
    """While one thread plans (RRT* uses its whole time limit), Python code runs in another."""
    m = gridcar.Map.from_array(walled(), resolution=0.5)
    scene = gridcar.Scene(m, vehicle="paper-i", space="reeds-shepp")
    done = threading.Event()
    out = {}

    def work():
        out["r"] = scene.plan((5, 5, 0), (45, 20, 0), planner="rrtstar", time_limit=1.0)
        done.set()

    th = threading.Thread(target=work)
    th.start()
    ticks = 0
    while not done.is_set():
        ticks += 1
    th.join()
    assert out["r"].time >= 0.9
    assert ticks > 10000  # with the GIL held for the whole second this loop could not run


def test_threads_plan_side_by_side_with_the_same_answers():
    m = gridcar.Map.from_array(walled(), resolution=0.5)
    queries = [((5, 5, 0), (45, 20, math.pi / 2)), ((5, 25, 0), (45, 5, 0)), ((45, 25, math.pi), (5, 5, math.pi))]
    alone = [gridcar.plan(m, s, g).path for s, g in queries]
    results = [None] * len(queries)

    def work(i):
        results[i] = gridcar.plan(m, *queries[i]).path

    threads = [threading.Thread(target=work, args=(i,)) for i in range(len(queries))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for a, b in zip(alone, results):
        assert np.array_equal(a, b)


def test_plot_draws_axes_in_metres_and_a_legend(tmp_path):
    import matplotlib
    matplotlib.use("Agg")
    m = gridcar.Map.from_array(walled(), resolution=0.5)
    scene = gridcar.Scene(m)
    r = scene.plan((5, 5, 0), (45, 20, 0))
    ax = gridcar.plot(m, plan=r, drive=scene.drive(r))
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert "planned path" in labels and "start" in labels and "goal" in labels and "driven (simulation)" in labels
    assert ax.get_xlabel() == "x (m)" and ax.get_ylabel() == "y (m)"
    assert "unknown" not in labels  # the map has no unknown cell
    out = tmp_path / "plot.png"
    ax.figure.savefig(out)
    assert out.stat().st_size > 5000
    # a smoothed grid path: the path before smoothing is drawn too, as the program's pictures do
    g = scene.plan((5, 5), (45, 20), planner="improved-astar-grid")
    assert len(g.raw_path) and not np.array_equal(g.raw_path, g.path)
    labels = [t.get_text() for t in gridcar.plot(m, plan=g).get_legend().get_texts()]
    assert "path before smoothing" in labels


@needs_shared
def test_real_map_with_the_defaults():
    m = gridcar.Map.load(str(WILLOW))
    veh = gridcar.Vehicle("paper-c-robot")
    scene = gridcar.Scene(m, vehicle=veh)
    r = scene.plan((36.45, 51.45), (31.25, 10.45))
    assert r.exact and r.drivable, (r.status, r.not_drivable_because)
    occ = m.to_array() != 0  # unknown cells are blocked too
    check_body_free(occ, m.resolution, r.path - [m.origin[0], m.origin[1], 0.0], veh)
    assert scene.drive(r).reached


def child_env():
    """The environment for a child python: this gridcar package first on its path."""
    here = str(pathlib.Path(gridcar.__file__).resolve().parents[1])
    return dict(os.environ, MPLBACKEND="Agg", PYTHONPATH=os.pathsep.join([here, os.environ.get("PYTHONPATH", "")]))


def readme_python_block():
    text = (SOURCE / "README.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert blocks, "README.md has no ```python example"
    return blocks[0]


@needs_shared
def test_the_readme_example_runs(tmp_path):
    code = readme_python_block()
    assert len([ln for ln in code.splitlines() if ln.strip() and not ln.startswith("#")]) <= 6
    env = child_env()
    p = subprocess.run([sys.executable, "-c", code], cwd=SOURCE, env=env, capture_output=True, text=True, timeout=600)
    assert p.returncode == 0, p.stderr
    assert "Exact solution" in p.stdout and "reached" in p.stdout, p.stdout


@needs_shared
def test_the_example_script_plans_plots_and_drives(tmp_path):
    out = tmp_path / "example.png"
    env = child_env()
    p = subprocess.run([sys.executable, str(SOURCE / "python/examples/plan_and_drive.py"), "--map", str(WILLOW),
                        "--out", str(out)], env=env, capture_output=True, text=True, timeout=600)
    assert p.returncode == 0, p.stderr
    assert "reached" in p.stdout
    assert out.stat().st_size > 20000
