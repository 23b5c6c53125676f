#!/usr/bin/python3
"""Report of a gridcar benchmark: report.md with one table per problem query and PNG plots
(every planner's path on the map; box plots), read from the SQLite database that
ompl_benchmark_statistics built from the OMPL .log files. Run by `gridcar bench`."""
import argparse
import json
import math
import re
import sys
import os
import sqlite3
import statistics

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plot_figure  # noqa: E402

METRICS = [  # (column, header, format)
    ("time", "time s", "{:.3f}"),
    ("time_to_first_solution", "first solution s", "{:.3f}"),
    ("path_length", "length m", "{:.1f}"),
    ("driving_time", "driving time s", "{:.1f}"),
    ("sim_driving_time", "simulated s", "{:.1f}"),
    ("min_clearance", "clearance m", "{:.2f}"),
    ("turns", "turns", "{:.0f}"),
    ("max_curvature", "max curvature 1/m", "{:.2f}"),
    ("cusps", "cusps", "{:.0f}"),
]
LOG_AXIS = ("time", "time_to_first_solution")  # answers take 5 ms, timeouts 5 s


def query_of(ename):
    """The query an experiment belongs to: its name without the time-limit suffix -tTs."""
    m = re.match(r"^(.*-q\d+)(-t[0-9.e+]+s)?$", ename)
    return m.group(1) if m else ename


def outline(ax, x, y, yaw, veh, color):
    """The vehicle's outline at a pose: plot_figure.py's drawing (installed beside this script)."""
    plot_figure.outline(ax, x, y, yaw, veh, color, lw=0.6)


def summary(cur, exps, cols):
    """One table: per planner and query, the best driving time of a drivable exact run, the
    solve time of that run and the time limit it ran under; then the runs that succeeded."""
    if "driving_time" not in cols:
        return []
    drv = "drivable" if "drivable" in cols else "1"
    best, ok, queries = {}, {}, []
    for eid, ename, tlimit, _ in exps:
        q = query_of(ename)
        if q not in queries:
            queries.append(q)
        for pname, dt, t, solved, approx, dr in cur.execute(
                "SELECT p.name, r.driving_time, r.time, r.solved, r.approximate_solution, {} FROM runs r "
                "JOIN plannerConfigs p ON r.plannerid = p.id WHERE r.experimentid = ?".format(
                    "r." + drv if drv != "1" else "1"), (eid,)):
            label = pname.replace("geometric_", "")
            good = solved and not approx and dr and dt is not None
            n = ok.setdefault(label, [0, 0])
            n[1] += 1
            if good:
                n[0] += 1
                key = (label, q)
                if key not in best or dt < best[key][0]:
                    best[key] = (dt, t, tlimit)
    lines = ["## Summary: best driving time per planner and query", "",
             "Best simulated-profile driving time (s) of a drivable exact path over all runs and time limits, "
             "with the solve time of that run and its time limit; drivable = exact solutions that pass the "
             "independent drivable check / runs.", ""]
    hdr = ["planner"] + queries + ["drivable"]
    lines.append("| " + " | ".join(hdr) + " |")
    lines.append("|" + "---|" * len(hdr))
    for label in ok:
        row = [label]
        for q in queries:
            b = best.get((label, q))
            row.append("-" if b is None else "{:.1f} s in {:.3f} s (limit {:g} s)".format(*b))
        row.append("{}/{}".format(*ok[label]))
        lines.append("| " + " | ".join(row) + " |")
    lines.append("")
    return lines


def quartiles(values):
    v = sorted(values)
    if not v:
        return None
    med = statistics.median(v)
    if len(v) < 2:
        return med, med, med
    q = statistics.quantiles(v, n=4, method="inclusive")
    return q[0], med, q[2]


def cell(values, fmt):
    q = quartiles(values)
    if q is None:
        return "-"
    lo, med, hi = q
    if len(values) < 2 or hi - lo < 1e-12:
        return fmt.format(med)
    return "{} ({}-{})".format(fmt.format(med), fmt.format(lo), fmt.format(hi))


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--db", required=True)
    ap.add_argument("--paths", required=True, nargs="+",
                    help="paths JSON written by gridcar bench (several: the shards' files, merged)")
    ap.add_argument("--out", required=True)
    ap.add_argument("--title", default="benchmark")
    ap.add_argument("--note", default="", help="a paragraph put under the title (e.g. a link to another report)")
    a = ap.parse_args()

    con = sqlite3.connect(a.db)
    cur = con.cursor()
    cols = {r[1] for r in cur.execute("PRAGMA table_info(runs)")}
    paths, maps, vehicle = {}, {}, None
    for name in a.paths:
        try:
            with open(name) as f:
                part = json.load(f)
        except (OSError, ValueError) as e:
            sys.exit("bench_report.py: {}: {}".format(name, e))
        maps.update(part.pop("_maps", {}))
        v = part.pop("_vehicle", None)
        if v:
            vehicle = v
        paths.update(part)

    exps = cur.execute("SELECT id, name, timelimit, runcount FROM experiments ORDER BY id").fetchall()
    lines = ["# Benchmark report: {}".format(a.title), ""]
    if a.note:
        lines += [a.note, ""]
    lines += summary(cur, exps, cols)
    lines.append("Built from `{}` (OMPL benchmark database; open it with `ompl_benchmark_statistics` "
                 "or Planner Arena). Cells: median (lower quartile - upper quartile) over the runs "
                 "that found an exact solution; success = exact solutions / runs. Length: x-y length of the "
                 "path (OMPL's solution length also counts yaw distance). Driving time: "
                 "`gridcar::drivingTime` of the path (forward-backward velocity profile); simulated: the time "
                 "paper C's potential-field follower needs to drive it in the kinematic simulation (runs it "
                 "did not finish are left out; see sim_reached in the database); clearance: "
                 "footprint clearance (m); turns: heading changes above 15 deg over 3 m chords.".format(
                     os.path.basename(a.db)))
    lines.append("")
    names = [e[1] for e in exps]
    for eid, ename, tlimit, runcount in exps:
        # one experiment per query; a query run at several time limits has one experiment per
        # limit under the same name (Planner Arena groups them by the time_limit parameter)
        tag = "-t{:g}s".format(tlimit) if names.count(ename) > 1 else ""
        if sum(1 for e in exps if e[1] == ename and e[2] == tlimit) > 1:  # shards merged: one per log
            tag += "-e{}".format(eid)
        planners = cur.execute(
            "SELECT DISTINCT p.id, p.name FROM runs r JOIN plannerConfigs p ON r.plannerid = p.id "
            "WHERE r.experimentid = ? ORDER BY p.id", (eid,)).fetchall()
        lines.append("## {} (time limit {:g} s, {} runs per planner)".format(ename + tag, tlimit, runcount))
        lines.append("")
        hdr = ["planner", "success"] + [h for _, h, _ in METRICS]
        lines.append("| " + " | ".join(hdr) + " |")
        lines.append("|" + "---|" * len(hdr))
        series = {}
        for pid, pname in planners:
            label = pname.replace("geometric_", "")
            sel = ["solved", "approximate_solution"] + [c for c, _, _ in METRICS if c in cols]
            rows = cur.execute("SELECT {} FROM runs WHERE experimentid = ? AND plannerid = ?".format(
                ", ".join(sel)), (eid, pid)).fetchall()
            exact = [r for r in rows if r[0] and not r[1]]
            vals = {}
            for i, c in enumerate(sel[2:], start=2):
                vals[c] = [r[i] for r in exact if r[i] is not None]
            series[label] = vals
            row = [label, "{}/{}".format(len(exact), len(rows))]
            for c, _, fmt in METRICS:
                row.append(cell(vals.get(c, []), fmt))
            lines.append("| " + " | ".join(row) + " |")
        lines.append("")

        # box plots
        labels = list(series.keys())
        boxed = [m for m in METRICS if m[0] in ("time", "time_to_first_solution", "driving_time", "min_clearance")
                 and m[0] in cols]
        fig, axes = plt.subplots(1, len(boxed), figsize=(4.5 * len(boxed), 0.35 * len(labels) + 2.5))
        for ax, (c, h, _) in zip(axes, boxed):
            data = [series[l].get(c, []) or [float("nan")] for l in labels]
            ax.boxplot(data, vert=False, labels=labels if ax is axes[0] else [""] * len(labels))
            ax.set_title(h + (" (log)" if c in LOG_AXIS else ""))
            if c in LOG_AXIS:
                ax.set_xscale("log")
            ax.grid(True, axis="x", alpha=0.3, which="both")
        fig.suptitle("{} (time limit {:g} s)".format(ename, tlimit))
        fig.tight_layout()
        box = "{}{}-box.png".format(ename, tag)
        fig.savefig(os.path.join(a.out, box), dpi=90)
        plt.close(fig)

        # paths on the map
        m = maps.get(ename)
        if m and names.index(ename) == exps.index((eid, ename, tlimit, runcount)):  # once per query
            img = mpimg.imread(os.path.join(a.out, m["image"]))
            x0, x1, y0, y1 = m["extent"]
            fig, ax = plt.subplots(figsize=(10, 10 * (y1 - y0) / max(x1 - x0, 1e-9) + 0.5))
            ax.imshow(img, extent=[x0, x1, y0, y1])
            cmap = plt.get_cmap("tab20")
            for i, l in enumerate(labels):
                pts = paths.get("{}|{}".format(ename, l))
                if not pts:
                    continue
                ax.plot([p[0] for p in pts], [p[1] for p in pts], color=cmap(i % 20), lw=1.4, label=l)
                if vehicle and len(pts[0]) > 2:  # the car's outline every few metres
                    along, last = 0.0, None
                    for k, p in enumerate(pts):
                        if k:
                            along += math.hypot(p[0] - pts[k - 1][0], p[1] - pts[k - 1][1])
                        if last is None or along - last >= 8.0 or k == len(pts) - 1:
                            outline(ax, p[0], p[1], p[2], vehicle, cmap(i % 20))
                            last = along
            ax.plot(*m["start"], "ko", ms=7)
            ax.plot(*m["goal"], "m*", ms=12)
            ax.set_xlim(x0, x1)
            ax.set_ylim(y0, y1)
            ax.set_xlabel("x (m)")
            ax.set_ylabel("y (m)")
            ax.legend(fontsize=7, loc="best")
            ax.set_title("{}: first exact path of each planner{}".format(
                ename, " (car outline every 8 m)" if vehicle else ""))
            fig.tight_layout()
            pp = "{}-paths.png".format(ename)
            fig.savefig(os.path.join(a.out, pp), dpi=90)
            plt.close(fig)
            lines.append("![paths]({})".format(pp))
            lines.append("")
        lines.append("![box plots]({})".format(box))
        lines.append("")
    with open(os.path.join(a.out, "report.md"), "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
