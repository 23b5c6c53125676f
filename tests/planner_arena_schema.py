#!/usr/bin/python3
"""Checks that a gridcar bench database loads in OMPL's Planner Arena schema: the tables
experiments, plannerConfigs, runs and progress with the columns Planner Arena reads, every run
pointing at an experiment and a planner configuration, progress rows pointing at runs, and the
run properties gridcar adds. Usage: planner_arena_schema.py DB MIN_EXPERIMENTS"""
import sqlite3
import sys

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
    if n_prog == 0 or bad_prog:
        sys.exit("{}: {} progress rows, {} of them pointing at no run".format(db, n_prog, bad_prog))
    undrivable = con.execute("SELECT COUNT(*) FROM runs WHERE solved = 1 AND approximate_solution = 0 "
                             "AND drivable = 0").fetchone()[0]
    print("{}: {} experiments, {} runs, {} progress rows; exact but not drivable: {}".format(
        db, n_exp, con.execute("SELECT COUNT(*) FROM runs").fetchone()[0], n_prog, undrivable))
    if undrivable:
        sys.exit("{}: {} exact solutions on a car space are not drivable".format(db, undrivable))


if __name__ == "__main__":
    main()
