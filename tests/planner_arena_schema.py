#!/usr/bin/python3
"""Checks that a gridcar bench database loads in OMPL's Planner Arena schema: the tables
experiments, plannerConfigs, runs and progress with the columns Planner Arena reads, every run
pointing at an experiment and a planner configuration, progress rows pointing at runs, and the
run properties gridcar adds; then what Planner Arena shows: an OMPL version number, path
attributes only on runs with an exact solution, no progress column without a value, one
experiment name per query (its time limits told apart by the time_limit parameter), and a set-up
text that names no planner that did not run.
Usage: planner_arena_schema.py DB MIN_EXPERIMENTS [TIME_LIMITS_PER_QUERY]"""
import re
import sqlite3
import sys

# run properties that describe a path: NULL unless the run found an exact solution
PATH_ATTRIBUTES = ["solution_length", "driving_time", "drivable", "cusps", "time_to_first_solution", "min_clearance",
                   "max_curvature", "sim_reached", "path_length"]

REQUIRED = {
    "experiments": {"id", "name", "totaltime", "timelimit", "memorylimit", "runcount", "version", "hostname",
                    "cpuinfo", "date", "seed", "setup"},
    "plannerConfigs": {"id", "name", "settings"},
    "runs": {"id", "experimentid", "plannerid", "time", "memory", "solved", "approximate_solution",
             "solution_length", "status",
             # gridcar's own run properties
             "driving_time", "drivable", "cusps", "time_to_first_solution", "min_clearance", "max_curvature"},
    "progress": {"runid", "time"},
}


def main():
    db, min_exp = sys.argv[1], int(sys.argv[2])
    limits_per_query = int(sys.argv[3]) if len(sys.argv) > 3 else 1
    con = sqlite3.connect(db)
    tables = {r[0] for r in con.execute("SELECT name FROM sqlite_master WHERE type = 'table'")}
    for t, cols in REQUIRED.items():
        if t not in tables:
            sys.exit("{}: no table {}".format(db, t))
        have = {r[1] for r in con.execute("PRAGMA table_info({})".format(t))}
        if not cols <= have:
            sys.exit("{}: table {} lacks {}".format(db, t, sorted(cols - have)))
    n_exp = con.execute("SELECT COUNT(*) FROM experiments").fetchone()[0]
    if n_exp < min_exp:
        sys.exit("{}: {} experiments, expected at least {}".format(db, n_exp, min_exp))
    orphans = con.execute("SELECT COUNT(*) FROM runs WHERE experimentid NOT IN (SELECT id FROM experiments) "
                          "OR plannerid NOT IN (SELECT id FROM plannerConfigs)").fetchone()[0]
    if orphans:
        sys.exit("{}: {} runs point at no experiment or planner".format(db, orphans))
    n_prog = con.execute("SELECT COUNT(*) FROM progress").fetchone()[0]
    bad_prog = con.execute("SELECT COUNT(*) FROM progress WHERE runid NOT IN (SELECT id FROM runs)").fetchone()[0]
    if bad_prog:
        sys.exit("{}: {} progress rows, {} of them pointing at no run".format(db, n_prog, bad_prog))
    # on OMPL's car spaces (space dubins / reeds-shepp) every exact path must be drivable; on se2
    # the grid baselines' corners are not
    undrivable = con.execute("SELECT COUNT(*) FROM runs WHERE solved = 1 AND approximate_solution = 0 "
                             "AND drivable = 0 AND experimentid IN (SELECT id FROM experiments "
                             "WHERE space != 'se2')").fetchone()[0]
    print("{}: {} experiments, {} runs, {} progress rows; exact but not drivable: {}".format(
        db, n_exp, con.execute("SELECT COUNT(*) FROM runs").fetchone()[0], n_prog, undrivable))
    if undrivable:
        sys.exit("{}: {} exact solutions on a car space are not drivable".format(db, undrivable))
    check_arena_view(con, db, limits_per_query)


def check_arena_view(con, db, limits_per_query):
    # ompl_benchmark_statistics stores the log's "OMPL version 1.5.2" as "OMPL 1.5.2"
    for (version,) in con.execute("SELECT version FROM experiments"):
        if not re.fullmatch(r"(OMPL )?\d+\.\d+\.\d+", str(version)):
            sys.exit("{}: OMPL version '{}' is not a version number".format(db, version))
    run_cols = {r[1] for r in con.execute("PRAGMA table_info(runs)")}
    for c in PATH_ATTRIBUTES:
        if c not in run_cols:
            continue
        n = con.execute("SELECT COUNT(*) FROM runs WHERE NOT (solved = 1 AND approximate_solution = 0) "
                        "AND {} IS NOT NULL".format(c)).fetchone()[0]
        if c == "solution_length":  # OMPL's own column: 0 or the approximate path's length
            continue
        if n:
            sys.exit("{}: {} runs without an exact solution carry the path attribute {}".format(db, n, c))
    has_progress = con.execute("SELECT COUNT(*) FROM progress").fetchone()[0] > 0
    for c in [r[1] for r in con.execute("PRAGMA table_info(progress)")] if has_progress else []:
        if con.execute("SELECT COUNT(*) FROM progress WHERE {} IS NOT NULL".format('"' + c + '"')).fetchone()[0] == 0:
            sys.exit("{}: progress column {} has no value (Planner Arena would plot nothing)".format(db, c))
    names = {}
    for name, in con.execute("SELECT name FROM experiments"):
        names[name] = names.get(name, 0) + 1
    exp_cols = {r[1] for r in con.execute("PRAGMA table_info(experiments)")}
    if "time_limit" not in exp_cols:
        sys.exit("{}: experiments lack the time_limit parameter".format(db))
    for name, n in names.items():
        limits = con.execute("SELECT COUNT(DISTINCT time_limit) FROM experiments WHERE name = ?", (name,)).fetchone()[0]
        if limits != limits_per_query or n != limits_per_query:
            sys.exit("{}: experiment {} has {} entries at {} time limits, expected one per limit ({})".format(
                db, name, n, limits, limits_per_query))
    ran = {r[0].replace("geometric_", "") for r in con.execute(
        "SELECT DISTINCT p.name FROM runs r JOIN plannerConfigs p ON r.plannerid = p.id")}
    for (setup,) in con.execute("SELECT setup FROM experiments"):
        for named in re.findall(r"Planner (\S+) specs:", setup or ""):
            if named not in ran:
                sys.exit("{}: the set-up text describes planner {}, which did not run".format(db, named))


if __name__ == "__main__":
    main()
