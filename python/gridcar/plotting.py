"""gridcar.plot(): a map with a plan and / or a drive, drawn as the gridcar program's pictures
(`gridcar plan --png`, `gridcar drive --png`): axes in metres, a scale bar, a legend, the
vehicle's outline along the path, reverse segments in their own colour, start (black circle) and
goal (magenta star), the map's cost layer tinted where it has one."""
import math

import numpy as np

PATH_COLOUR = "tab:blue"
REVERSE_COLOUR = "tab:purple"
DRIVE_COLOUR = "tab:red"


def _vehicle(vehicle):
    from . import Vehicle
    if vehicle is None:
        return Vehicle("paper-i")
    if isinstance(vehicle, Vehicle):
        return vehicle
    if isinstance(vehicle, dict):
        return Vehicle.from_dict(vehicle)
    return Vehicle(str(vehicle))


def _outline(ax, pose, outline, colour):
    c, s = math.cos(pose[2]), math.sin(pose[2])
    pts = np.vstack([outline, outline[:1]])
    ax.plot(pose[0] + c * pts[:, 0] - s * pts[:, 1], pose[1] + s * pts[:, 0] + c * pts[:, 1], color=colour, lw=0.7,
            alpha=0.85)


def _reversing(path):
    """Per segment: True where the motion runs against the heading."""
    d = np.diff(path[:, :2], axis=0)
    return d[:, 0] * np.cos(path[:-1, 2]) + d[:, 1] * np.sin(path[:-1, 2]) < -1e-9


def _draw_path(ax, path, colour, label, outline, spacing):
    if len(path) < 2:
        return
    rev = _reversing(path)
    labelled = set()
    i = 0
    while i < len(rev):  # runs of one gear, each in one call
        j = i
        while j + 1 < len(rev) and rev[j + 1] == rev[i]:
            j += 1
        col = REVERSE_COLOUR if rev[i] else colour
        lab = (label + " (reverse)" if rev[i] else label)
        ax.plot(path[i:j + 2, 0], path[i:j + 2, 1], color=col, lw=1.8, label=None if lab in labelled else lab)
        labelled.add(lab)
        i = j + 1
    if outline is not None:
        travelled, last = 0.0, -math.inf
        for k in range(len(path)):
            if k:
                travelled += float(np.hypot(*(path[k, :2] - path[k - 1, :2])))
            if travelled - last >= spacing or k == len(path) - 1:
                _outline(ax, path[k], outline, REVERSE_COLOUR if k and rev[min(k, len(rev)) - 1] else colour)
                last = travelled


def plot(map, plan=None, drive=None, vehicle=None, ax=None, margin=5.0, title=None, distance=False):
    """Draws @p map (a gridcar.Map) around @p plan (a PlanResult or an N x 3 path) and @p drive (a
    DriveResult), with @p vehicle's outline along them (a preset name, dict or Vehicle; default
    'paper-i'). margin: metres around the paths (the whole map without paths). distance: shade
    free cells by their distance to obstacles. Returns the Axes (a new figure when ax is None)."""
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    from mpl_toolkits.axes_grid1.anchored_artists import AnchoredSizeBar

    veh = _vehicle(vehicle)
    if ax is None:
        _, ax = plt.subplots(figsize=(8, 8))
    path = None
    if plan is not None:
        path = np.asarray(plan.path if hasattr(plan, "path") else plan, dtype=float)
    traj = np.asarray(drive.trajectory, dtype=float) if drive is not None else None

    x0, x1, y0, y1 = map.extent
    pts = [p[:, :2] for p in (path, traj[:, 1:3] if traj is not None else None) if p is not None and len(p)]
    if pts:
        allp = np.vstack(pts)
        x0, x1 = max(x0, allp[:, 0].min() - margin), min(x1, allp[:, 0].max() + margin)
        y0, y1 = max(y0, allp[:, 1].min() - margin), min(y1, allp[:, 1].max() + margin)
    res = map.resolution
    ox, oy, _ = map.origin
    c0, c1 = max(0, int((x0 - ox) / res)), min(map.width, int(math.ceil((x1 - ox) / res)))
    r0, r1 = max(0, int((y0 - oy) / res)), min(map.height, int(math.ceil((y1 - oy) / res)))
    cells = map.to_array()[r0:r1, c0:c1]
    extent = (ox + c0 * res, ox + c1 * res, oy + r0 * res, oy + r1 * res)
    grey = np.where(cells == 100, 0.0, np.where(cells < 0, 0.75, 1.0))
    if distance:
        d = map.distance_field()[r0:r1, c0:c1]
        dmax = max(float(d.max()), 1e-9)
        grey = np.where(cells == 0, 0.55 + 0.45 * np.minimum(d / dmax, 1.0), grey)
    ax.imshow(grey, cmap="gray", vmin=0, vmax=1, origin="lower", extent=extent, interpolation="nearest")
    handles = [Line2D([], [], color="black", lw=6, label="occupied")]
    if (cells < 0).any():  # (as the program's pictures: only where the map has unknown cells)
        handles.append(Line2D([], [], color="0.75", lw=6, label="unknown"))
    costs = map.costs()
    if costs is not None:
        cst = costs[r0:r1, c0:c1].astype(float)
        masked = np.ma.masked_where((cst <= 0) | (cells != 0), cst)
        ax.imshow(masked, cmap="Oranges", alpha=0.5, origin="lower", extent=extent, interpolation="nearest")
        handles.append(Line2D([], [], color="tab:orange", lw=6, alpha=0.5, label="cost layer"))

    outline = veh.outline if len(veh.outline) else None
    spacing = max(3.0 * veh.length, (x1 - x0 + y1 - y0) / 30.0)
    raw = np.asarray(plan.raw_path, dtype=float) if plan is not None and hasattr(plan, "raw_path") else None
    if raw is not None and len(raw) and (raw.shape != path.shape or not np.allclose(raw, path)):
        ax.plot(raw[:, 0], raw[:, 1], color="tab:orange", lw=1.0, ls="--", label="path before smoothing")
    if path is not None and len(path):
        _draw_path(ax, path, PATH_COLOUR, "planned path", outline, spacing)
    if traj is not None and len(traj) > 1:
        drv = traj[:, 1:4]
        ax.plot(drv[:, 0], drv[:, 1], color=DRIVE_COLOUR, lw=1.0, label="driven (simulation)")
        back = traj[:, 4] < 0  # speed column: negative in reverse
        if back.any():
            ax.plot(np.where(back, drv[:, 0], np.nan), np.where(back, drv[:, 1], np.nan), color=REVERSE_COLOUR, lw=1.5,
                    label="driven in reverse")
        if outline is not None:
            _outline(ax, drv[-1], outline, DRIVE_COLOUR)
        ax.plot(drv[-1, 0], drv[-1, 1], "X", color=DRIVE_COLOUR, ms=8, label="end of the drive (%s)" % drive.outcome)
    if path is not None and len(path):
        ax.plot(path[0, 0], path[0, 1], "o", color="black", ms=8, label="start")
        ax.plot(path[-1, 0], path[-1, 1], "*", color="magenta", ms=14, label="goal")
    h, _ = ax.get_legend_handles_labels()
    ax.legend(handles=h + handles, loc="best", fontsize=8, framealpha=0.85)
    ax.set_xlim(extent[0], extent[1])
    ax.set_ylim(extent[2], extent[3])
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    span = extent[1] - extent[0]
    step = 10 ** math.floor(math.log10(max(span / 5, 1e-3)))
    bar = max(k * step for k in (1, 2, 5) if k * step <= max(span / 5, 1e-3))
    ax.add_artist(AnchoredSizeBar(ax.transData, bar, "%g m" % bar, "lower right", frameon=True, size_vertical=0))
    if title is None and plan is not None and hasattr(plan, "status"):
        title = "%s: %s (%.1f m)" % (plan.planner, plan.status, plan.length)
    if title:
        ax.set_title(title)
    return ax
