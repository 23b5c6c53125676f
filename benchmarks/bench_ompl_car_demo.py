#!/usr/bin/env python3
"""OMPL's own car demo (GeometricCarPlanning, from ompl-demos) with a gridcar planner and no
parameter set: the build's ompl_car_demo is that demo's source with one line added before
ss.setup() (ss.setPlanner(gridcar::makePlanner(...)), the name from GRIDCAR_PLANNER).

Runs --reedsshepp --easyplan and --hardplan for each planner, several times, and prints the
solve() times OMPL reports ("Solution found in X seconds"). Every path the demo prints (after
OMPL's simplifySolution() and interpolate(1000)) is checked independently of the planner: it
starts at the demo's start, ends at its goal, and every printed state satisfies the demo's
own validity function (bounds, and the easy problem's walls) within OMPL's own checking
resolution (the demo's 0.5 % of the space's extent: OMPL certifies a motion only at states
that far apart, so the states interpolate(1000) puts between them may cut a corner by that
much, whichever planner made the path; RRTConnect's do). With --check the program exits 1 when
any run is approximate or any path fails those checks (the ompl_car_demo test). A run in which
OMPL's own simplifySolution() aborts after the planner answered (an assertion in OMPL 1.5.2's
PathGeometric::checkAndRepair(), met by RRTConnect's paths too) is run again, up to 8 times,
and counted in its own column.
"""
import argparse
import math
import os
import statistics
import subprocess
import sys

PROBLEMS = {
    # the demo's start, goal and isStateValid*, as its source states them
    "easyplan": {"start": (1.0, 1.0, 0.0), "goal": (17.0, 17.0, -0.99 * math.pi),
                 "valid": lambda x, y, t: -t <= x <= 18 + t and -t <= y <= 18 + t and
                 (x < 5 + t or x > 13 - t or 8.5 - t < y < 9.5 + t)},
    "hardplan": {"start": (0.5, 0.5, 0.5 * math.pi), "goal": (5.5, 0.5, 0.5 * math.pi),
                 "valid": lambda x, y, t: -t <= x <= 6 + t and -t <= y <= 0.6 + t},
}


def angle_diff(a, b):
    return abs(math.atan2(math.sin(a - b), math.cos(a - b)))


def run_once(demo, planner, problem, space, timeout):
    env = dict(os.environ, GRIDCAR_PLANNER=planner)
    try:
        out = subprocess.run([demo, "--" + space, "--" + problem], env=env, capture_output=True, text=True,
                             timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"ok": False, "why": f"no answer in {timeout} s", "seconds": float("nan"), "length": float("nan")}
    text = out.stdout + out.stderr
    res = {"ok": True, "why": "", "seconds": float("nan"), "length": float("nan")}
    tol = None
    for line in text.splitlines():
        if line.strip().startswith("- extent:") and tol is None:
            tol = 0.005 * float(line.split(":")[1])  # the demo's setStateValidityCheckingResolution(0.005)
        if "Solution found in" in line:
            res["seconds"] = float(line.split("Solution found in")[1].split()[0])
    if out.returncode != 0:
        # OMPL 1.5.2's simplifySolution() (after the planner's answer) sometimes aborts in
        # PathGeometric::checkAndRepair() -> sampleUniformNear() on a state it interpolated just
        # outside the bounds; RRTConnect's paths meet it too (about 1 run in 40 of --hardplan)
        if "lower_bound <= upper_bound" in text and "Solution found in" in text:
            return dict(res, ok=False, why="OMPL's simplifier aborted after the planner's answer", ompl_abort=True)
        return dict(res, ok=False, why=f"exit status {out.returncode}")
    if "Adding approximate solution" in text or "No solution found" in text:
        return dict(res, ok=False, why="no exact solution")
    # the path: the rows of three numbers after "Found solution:"
    rows = []
    seen = False
    for line in text.splitlines():
        if line.startswith("Found solution"):
            seen = True
            continue
        parts = line.split()
        if seen and len(parts) == 3:
            try:
                rows.append(tuple(float(p) for p in parts))
            except ValueError:
                pass
    if len(rows) < 2:
        return dict(res, ok=False, why="no path printed")
    p = PROBLEMS[problem]
    for name, end, pose in (("start", p["start"], rows[0]), ("goal", p["goal"], rows[-1])):
        if math.hypot(pose[0] - end[0], pose[1] - end[1]) > 1e-3 or angle_diff(pose[2], end[2]) > 1e-3:
            return dict(res, ok=False, why=f"path ends {pose}, not at the {name} {end}")
    if tol is None:
        return dict(res, ok=False, why="the demo printed no extent of its space")
    for x, y, _ in rows:
        if not p["valid"](x, y, tol):
            return dict(res, ok=False, why=f"state ({x}, {y}) is invalid (by more than {tol:.3f} m)")
    res["length"] = sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(rows, rows[1:]))
    return res


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("demo", help="the build's benchmarks/ompl_car_demo")
    ap.add_argument("--planners", nargs="+", default=["corner-astar", "improved-astar"])
    ap.add_argument("--runs", type=int, default=5, help="runs of each planner and problem (default 5)")
    ap.add_argument("--space", default="reedsshepp", choices=["reedsshepp", "dubins", "dubinssym"])
    ap.add_argument("--timeout", type=float, default=60.0, help="seconds before a run counts as failed")
    ap.add_argument("--check", action="store_true", help="exit 1 if any run is not exact and valid")
    a = ap.parse_args()
    if not os.access(a.demo, os.X_OK):
        sys.exit(f"bench_ompl_car_demo: {a.demo} is not an executable (build the target ompl_car_demo; "
                 "it needs ompl-demos installed)")
    print(f"OMPL's GeometricCarPlanning demo, --{a.space}, gridcar planners with no parameters, {a.runs} runs each\n")
    print("| planner | problem | exact and valid | solve() median / max (ms) | path length (m) | OMPL simplifier aborts, run again |")
    print("|---|---|---|---|---|---|")
    failed = []
    for planner in a.planners:
        for problem in PROBLEMS:
            results, aborts = [], 0
            for _ in range(a.runs):
                r = run_once(a.demo, planner, problem, a.space, a.timeout)
                for _retry in range(8):  # OMPL's own abort, not the planner's answer: run again
                    if not r.get("ompl_abort"):
                        break
                    aborts += 1
                    r = run_once(a.demo, planner, problem, a.space, a.timeout)
                results.append(r)
            good = [r for r in results if r["ok"]]
            failed += [f"{planner} --{problem}: {r['why']}" for r in results if not r["ok"]]
            secs = [r["seconds"] * 1000 for r in results if not math.isnan(r["seconds"])]
            times = f"{statistics.median(secs):.1f} / {max(secs):.1f}" if secs else "-"
            length = f"{statistics.median(r['length'] for r in good):.2f}" if good else "-"
            print(f"| {planner} | {problem} | {len(good)} / {len(results)} | {times} | {length} | {aborts} |", flush=True)
    for f in failed:
        print("FAILED:", f, file=sys.stderr)
    if a.check and failed:
        sys.exit(1)


if __name__ == "__main__":
    main()
