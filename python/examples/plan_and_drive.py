#!/usr/bin/python3
"""Plan on a ROS map with gridcar's defaults, draw the plan, then drive it with paper C's
potential-field follower in the simulation.

    PYTHONPATH=build/python python3 python/examples/plan_and_drive.py \
        --map ../shared/maps/ros/willow_garage/willow-2010-02-18-0.10.yaml --out willow.png
"""
import argparse
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import gridcar  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--map", required=True, help="a ROS map_server .yaml (or any map gridcar reads)")
    ap.add_argument("--start", default="36.45,51.45", help="x,y[,yaw_deg] in metres (default: Willow Garage's)")
    ap.add_argument("--goal", default="31.25,10.45,0", help="x,y[,yaw_deg]")
    ap.add_argument("--vehicle", default="paper-c-robot", help="a preset (%s) or a YAML file"
                    % ", ".join(gridcar.vehicle_presets()))
    ap.add_argument("--planner", default="corner-astar")
    ap.add_argument("--out", default="plan_and_drive.png", help="the picture")
    a = ap.parse_args()

    def pose(text):
        v = [float(t) for t in text.split(",")]
        return tuple(v[:2]) + ((math.radians(v[2]),) if len(v) > 2 else ())

    m = gridcar.Map.load(a.map)
    print(m)
    scene = gridcar.Scene(m, vehicle=a.vehicle)  # distance field and footprint checker, once
    r = scene.plan(pose(a.start), pose(a.goal), planner=a.planner)
    print("%s: %s in %.3f s, %.1f m, %d cusp(s), %s" % (r.planner, r.status, r.time, r.length, r.cusps,
                                                      "drivable" if r.drivable else "NOT drivable: " + r.not_drivable_because))
    if not r.exact:
        return 3
    d = scene.drive(r)
    print("drive: %s after %.1f s (%s)" % (d.outcome, d.driving_time, d.reason))
    ax = gridcar.plot(m, plan=r, drive=d, vehicle=scene.vehicle)
    ax.figure.tight_layout()
    ax.figure.savefig(a.out, dpi=120)
    plt.close(ax.figure)
    print("picture:", a.out)
    return 0 if d.reached else 3


if __name__ == "__main__":
    raise SystemExit(main())
