#!/usr/bin/python3
"""A picture of a plan or a drive for `gridcar plan --png` and `gridcar drive --png`: the map crop
(written by gridcar as a PNG) with axes in metres, a scale bar, a legend, the vehicle's outline
along each path, and the colours of `gridcar bench`'s path pictures (start: black circle, goal:
magenta star). Reverse segments of a path are drawn in their own colour.

Usage: plot_figure.py FIGURE.json OUT.png

FIGURE.json: {"title", "image", "extent": [x0, x1, y0, y1], "vehicle": {length, width,
rear_overhang} or null, "start": [x, y, yaw], "goal": [x, y, yaw] (yaw null: free; both absent
in a picture of a map alone),
"paths": [{"label", "colour", "points": [[x, y, yaw], ...], "outline": bool, "width"}],
"markers": [{"label", "colour", "marker", "points": [[x, y], ...]}],
"tint": {"label", "colour"} (a legend entry for cells tinted in the image),
"costs": {"label", "colour"} (a legend entry for the map's cost layer, shaded in the image)}."""
import json
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.patches as mpatches  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from mpl_toolkits.axes_grid1.anchored_artists import AnchoredSizeBar  # noqa: E402

REVERSE_COLOUR = "tab:purple"


def outline(ax, x, y, yaw, veh, colour, lw=0.7):
    """The vehicle's outline at a pose (reference point: rear axle): its polygon footprint, or
    the rectangle."""
    if veh.get("footprint"):
        pts = [tuple(p) for p in veh["footprint"]] + [tuple(veh["footprint"][0])]
    else:
        length, width, rear = veh["length"], veh["width"], veh["rear_overhang"]
        pts = [(-rear, -width / 2), (length - rear, -width / 2), (length - rear, width / 2), (-rear, width / 2),
               (-rear, -width / 2)]
    c, s = math.cos(yaw), math.sin(yaw)
    ax.plot([x + c * u - s * v for u, v in pts], [y + s * u + c * v for u, v in pts], color=colour, lw=lw, alpha=0.85)


def reversed_steps(pts):
    """Per segment: True when the motion runs against the heading (driven in reverse)."""
    out = []
    for a, b in zip(pts, pts[1:]):
        dx, dy = b[0] - a[0], b[1] - a[1]
        yaw = a[2] if len(a) > 2 and a[2] is not None else math.atan2(dy, dx)
        out.append(dx * math.cos(yaw) + dy * math.sin(yaw) < -1e-9)
    return out


def draw_path(ax, p, veh, span):
    pts = p["points"]
    if len(pts) < 2:
        return False
    rev = reversed_steps(pts) if len(pts[0]) > 2 else [False] * (len(pts) - 1)
    lw = p.get("width", 1.6)
    # runs of the same gear, each drawn in one call
    start = 0
    for i in range(1, len(rev) + 1):
        if i == len(rev) or rev[i] != rev[start]:
            seg = pts[start:i + 1]
            ax.plot([q[0] for q in seg], [q[1] for q in seg], color=REVERSE_COLOUR if rev[start] else p["colour"],
                    lw=lw, solid_capstyle="round")
            start = i
    if veh and p.get("outline") and len(pts[0]) > 2:
        length = sum(math.hypot(b[0] - a[0], b[1] - a[1]) for a, b in zip(pts, pts[1:]))
        every = max(length / 12.0, span / 25.0, 1e-6)
        along, last = 0.0, None
        for k, q in enumerate(pts):
            if k:
                along += math.hypot(q[0] - pts[k - 1][0], q[1] - pts[k - 1][1])
            if last is None or along - last >= every or k == len(pts) - 1:
                outline(ax, q[0], q[1], q[2], veh, p["colour"])
                last = along
    return any(rev)


def nice_length(span):
    """1, 2 or 5 times a power of ten, about a fifth of the span."""
    target = max(span / 5.0, 1e-9)
    k = 10 ** math.floor(math.log10(target))
    for m in (5, 2, 1):
        if m * k <= target:
            return m * k
    return k


def has_unknown_cells(img):
    """True if the map picture has a cell drawn as unknown (grey 190, as gridcar draws them)."""
    rgb = img[..., :3].astype(float) * (255.0 if img.dtype.kind == "f" else 1.0)
    return bool((abs(rgb - 190.0) < 0.5).all(axis=-1).any())


def main():
    fig_spec, out = sys.argv[1], sys.argv[2]
    with open(fig_spec) as f:
        spec = json.load(f)
    x0, x1, y0, y1 = spec["extent"]
    w, h = max(x1 - x0, 1e-9), max(y1 - y0, 1e-9)
    fig, ax = plt.subplots(figsize=(12.5, min(14, max(4, 9 * h / w)) + 0.8))
    img = mpimg.imread(spec["image"])
    ax.imshow(img, extent=[x0, x1, y0, y1], interpolation="nearest")
    veh = spec.get("vehicle")
    handles = []
    any_reverse = False
    for p in spec.get("paths", []):
        any_reverse = draw_path(ax, p, veh, max(w, h)) or any_reverse
        handles.append(Line2D([], [], color=p["colour"], lw=p.get("width", 1.6), label=p["label"]))
    if any_reverse:
        handles.append(Line2D([], [], color=REVERSE_COLOUR, lw=1.6, label="driven in reverse"))
    for m in spec.get("markers", []):
        pts = m["points"]
        if pts:
            ax.plot([q[0] for q in pts], [q[1] for q in pts], m.get("marker", "o"), color=m["colour"], ms=5,
                    linestyle=m.get("linestyle", "none"), lw=1)
            handles.append(Line2D([], [], color=m["colour"], marker=m.get("marker", "o"),
                                  linestyle=m.get("linestyle", "none"), label=m["label"]))
    if spec.get("start") is not None and spec.get("goal") is not None:
        sx, sy, syaw = spec["start"]
        gx, gy, gyaw = spec["goal"]
        if veh:
            outline(ax, sx, sy, syaw, veh, "black", 1.0)
            if gyaw is not None:
                outline(ax, gx, gy, gyaw, veh, "m", 1.0)
        ax.plot(sx, sy, "ko", ms=7)
        ax.plot(gx, gy, "m*", ms=13)
        handles.append(Line2D([], [], color="k", marker="o", linestyle="none", label="start"))
        handles.append(Line2D([], [], color="m", marker="*", ms=11, linestyle="none",
                              label="goal" + ("" if gyaw is not None else " (any heading)")))
    if veh and (spec.get("paths") or spec.get("start") is not None):
        handles.append(Line2D([], [], color="grey", lw=0.8, label="vehicle {} ({:g} m x {:g} m)".format(
            "footprint" if veh.get("footprint") else "outline", veh["length"], veh["width"])))
    if spec.get("tint"):
        handles.append(mpatches.Patch(color=spec["tint"]["colour"], label=spec["tint"]["label"]))
    if spec.get("costs"):
        handles.append(mpatches.Patch(color=spec["costs"]["colour"], label=spec["costs"]["label"]))
    handles.append(mpatches.Patch(facecolor="black", label="occupied"))
    if has_unknown_cells(img):
        handles.append(mpatches.Patch(facecolor=(190 / 255,) * 3, label="unknown"))
    bar = nice_length(w)
    ax.add_artist(AnchoredSizeBar(ax.transData, bar, "{:g} m".format(bar), "lower right", pad=0.4, sep=4,
                                  frameon=True, size_vertical=h / 200.0))
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_aspect("equal")
    ax.set_title(spec.get("title", ""))
    ax.legend(handles=handles, fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0)
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    plt.close(fig)


if __name__ == "__main__":
    main()
