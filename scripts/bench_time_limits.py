#!/usr/bin/python3
"""Compare one problem benchmarked at several time limits (one database per limit, from
`gridcar bench PROBLEM --time-limit S --out DIR`): per query, each planner's success rate and
median driving time / simulated driving time / clearance / turns at every limit, as markdown.

usage: bench_time_limits.py DB [DB ...] [--planners a,b,c]
"""
import argparse
import sqlite3
import statistics


def load(db):
    con = sqlite3.connect(db)
    cols = {r[1] for r in con.execute("PRAGMA table_info(runs)")}
    out = {}
    for eid, name, limit in con.execute("SELECT id, name, timelimit FROM experiments"):
        for pname, solved, approx, dt, sim, clr, turns in con.execute(
                "SELECT p.name, r.solved, r.approximate_solution, r.driving_time, {}, r.min_clearance, r.turns "
                "FROM runs r JOIN plannerConfigs p ON r.plannerid = p.id WHERE r.experimentid = ?".format(
                    "r.sim_driving_time" if "sim_driving_time" in cols else "NULL"), (eid,)):
            key = (name, pname.replace("geometric_", ""))
            e = out.setdefault(key, {"limit": limit, "runs": 0, "dt": [], "sim": [], "clr": [], "turns": []})
            e["runs"] += 1
            if solved and not approx:
                for k, v in (("dt", dt), ("sim", sim), ("clr", clr), ("turns", turns)):
                    if v is not None:
                        e[k].append(v)
    return out


def med(v, fmt):
    return fmt.format(statistics.median(v)) if v else "-"


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("db", nargs="+")
    ap.add_argument("--planners", default="")
    a = ap.parse_args()
    data = [load(db) for db in a.db]
    limits = [next(iter(d.values()))["limit"] for d in data]
    wanted = [p for p in a.planners.split(",") if p]
    queries = sorted({k[0] for d in data for k in d})
    for q in queries:
        planners = wanted or sorted({k[1] for d in data for k in d if k[0] == q})
        print("#### {}\n".format(q))
        hdr = ["planner"] + ["{:g} s: success, driving / simulated s, clearance m, turns".format(l) for l in limits]
        print("| " + " | ".join(hdr) + " |")
        print("|" + "---|" * len(hdr))
        for p in planners:
            row = [p]
            for d in data:
                e = d.get((q, p))
                if not e:
                    row.append("-")
                    continue
                row.append("{}/{}, {} / {}, {}, {}".format(len(e["dt"]), e["runs"], med(e["dt"], "{:.1f}"),
                                                          med(e["sim"], "{:.1f}"), med(e["clr"], "{:.2f}"),
                                                          med(e["turns"], "{:.0f}")))
            print("| " + " | ".join(row) + " |")
        print()


if __name__ == "__main__":
    main()
