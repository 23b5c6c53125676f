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
much, whichever planner made the path; RRTConnect's do).

The build's ompl_car_demo_unsimplified (found beside the demo) is the same program without
simplifySolution(): it prints the planner's own path, checked the same way. OMPL 1.5.2's
simplifier can make a valid path invalid on a Reeds-Shepp space: its motion check
(ReedsSheppMotionValidator) takes as many samples as the straight line between two states
needs (CompoundStateSpace::validSegmentCount), not as many as the curve between them, so a
shortcut with a cusp or a loop is certified at samples metres apart. Such runs are counted
in their own column; the planner is judged by its own path. With --check the program exits 1
when any run is approximate, any path (the planner's, or the simplified one when the
unsimplified program is absent) fails those checks, or the simplified path does not end at
the start and goal (the ompl_car_demo test). A run in which OMPL's own simplifySolution()
aborts after the planner answered (an assertion in OMPL 1.5.2's
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


def run_retrying(demo, planner, problem, space, timeout):
    """One run, run again (up to 8 times) while OMPL's simplifier aborts; (result, aborts)."""
    r, aborts = run_once(demo, planner, problem, space, timeout), 0
    while r.get("ompl_abort") and aborts < 8:  # OMPL's own abort, not the planner's answer
        aborts += 1
        r = run_once(demo, planner, problem, space, timeout)
    return r, aborts


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
    raw_demo = os.path.join(os.path.dirname(os.path.abspath(a.demo)), "ompl_car_demo_unsimplified")
    if not os.access(raw_demo, os.X_OK):
        print(f"({raw_demo} absent: only the simplified paths are checked)\n")
        raw_demo = None
    print(f"OMPL's GeometricCarPlanning demo, --{a.space}, gridcar planners with no parameters, {a.runs} runs each\n")
    print("| planner | problem | exact and valid (planner's path) | valid after OMPL's simplifier "
          "| solve() median / max (ms) | path length (m) | OMPL simplifier aborts, run again |")
    print("|---|---|---|---|---|---|---|")
    failed = []
    for planner in a.planners:
        for problem in PROBLEMS:
            own, simplified, aborts = [], [], 0
            for _ in range(a.runs):
                r, n = run_retrying(a.demo, planner, problem, a.space, a.timeout)
                simplified.append(r)
                aborts += n
                own.append(run_once(raw_demo, planner, problem, a.space, a.timeout) if raw_demo else r)
            failed += [f"{planner} --{problem}: {r['why']}" for r in own if not r["ok"]]
            # the simplified path: exact and from start to goal is the planner's doing; a state
            # off the bounds after a valid own path is OMPL's simplifier's (see above)
            failed += [f"{planner} --{problem} after OMPL's simplifier: {r['why']}" for r in simplified
                       if not r["ok"] and (raw_demo is None or "is invalid" not in r["why"])]
            for r in simplified:
                if not r["ok"] and raw_demo and "is invalid" in r["why"]:
                    print(f"note: {planner} --{problem}: OMPL's simplifier left an invalid path: {r['why']}",
                          file=sys.stderr)
            secs = [r["seconds"] * 1000 for r in simplified if not math.isnan(r["seconds"])]
            times = f"{statistics.median(secs):.1f} / {max(secs):.1f}" if secs else "-"
            good = [r for r in simplified if r["ok"]]
            length = f"{statistics.median(r['length'] for r in good):.2f}" if good else "-"
            print(f"| {planner} | {problem} | {sum(r['ok'] for r in own)} / {len(own)} | {len(good)} / {len(simplified)} "
                  f"| {times} | {length} | {aborts} |", flush=True)
    for f in failed:
        print("FAILED:", f, file=sys.stderr)
    if a.check and failed:
        sys.exit(1)


if __name__ == "__main__":
    main()
