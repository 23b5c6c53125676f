"""gridcar: vehicle-aware grid planners for OMPL on occupancy-grid maps, from Python.

Corner-weighted A* (paper C: heading changes cost the time lost braking for them) and improved
A* (paper I), on gridcar's car lattice, next to OMPL's own planners, with FCL footprint
collision checking; and paper C's potential-field follower driving the paths in a kinematic
simulation.

    import gridcar
    m = gridcar.Map.load("willow-2010-02-18-0.10.yaml")
    r = gridcar.plan(m, start=(36.45, 51.45), goal=(31.25, 10.45, 0.0), vehicle="paper-c-robot")
    d = gridcar.drive(m, r, vehicle="paper-c-robot")
    gridcar.plot(m, plan=r, drive=d, vehicle="paper-c-robot")

Units: metres, seconds, radians (yaw). Maps follow ROS's conventions (origin: lower-left
corner; arrays with the first row at the origin unless row_order="top"). Planning and driving
release the GIL. Errors: MapLoadError (a file or dict that cannot be read) and InputError (a
bad argument), both ValueErrors, with the message the gridcar program prints.
"""
from ._gridcar import (  # noqa: F401
    DriveResult,
    InputError,
    Map,
    MapLoadError,
    PlanResult,
    Scene,
    Vehicle,
    __version__,
    planners,
    vehicle_presets,
)

__all__ = ["Map", "Vehicle", "Scene", "PlanResult", "DriveResult", "MapLoadError", "InputError", "plan", "drive",
           "plot", "planners", "vehicle_presets", "__version__"]


def _map(m, unknown_free=False):
    if isinstance(m, Map):
        return m
    if isinstance(m, (str, bytes)) or hasattr(m, "__fspath__"):
        import os
        return Map.load(os.fsdecode(m), unknown_free)
    raise InputError("map must be a gridcar.Map or a map file's path, not %s" % type(m).__name__)


def plan(map, start, goal, planner="corner-astar", settings=None, vehicle=None, time_limit=10.0, space="se2",
         smooth=False, goal_tolerance=None):
    """Plans start -> goal on a map and measures the path.

    map: a gridcar.Map or a map file's path. start, goal: (x, y) or (x, y, yaw) in metres and
    radians; without a yaw the start heading is the planner's choice and the goal is a position
    at any heading. planner: any name of gridcar.planners() (ours: 'corner-astar',
    'improved-astar', ...; OMPL's: 'rrtconnect', 'rrtstar', ...). settings: the planner's
    parameters as a dict ({'reverse': 'on', 'clearance': 0.2}; `gridcar planners` lists them
    with their defaults). vehicle: a preset name (gridcar.vehicle_presets(), default 'paper-i'),
    a YAML file, a dict of vehicle fields or a gridcar.Vehicle. space: 'se2', 'dubins' or
    'reeds-shepp'. smooth: paper I's post-processing for any planner. goal_tolerance: None
    (exact), metres from the goal position, or (metres, radians) with the heading's tolerance
    for a goal with a yaw (Nav2's goal checker: (0.25, 0.25)); the path then ends within it.

    Returns a gridcar.PlanResult: status, exact, path (N x 3 numpy array), length, time,
    drivable (the independent check) and more. Raises InputError for a start or goal off the
    map or in collision, an unknown planner or a bad setting. Builds a Scene for the query:
    to plan many queries on one map, make a gridcar.Scene once and call its plan().
    """
    return Scene(_map(map), vehicle, space).plan(start, goal, planner, settings or {}, time_limit, smooth, goal_tolerance)


def drive(map, path, vehicle=None, scenario=None, space="se2", dt=0.05, xi=1.0, eta=0.6, rho0=1.5, time_limit=0.0,
          goal_tolerance=None):
    """Drives a path with paper C's potential-field follower in the kinematic bicycle simulation.

    path: a PlanResult or an N x 3 array (x, y, yaw). scenario: a YAML file of moving obstacles
    (as `gridcar drive --scenario`). dt: simulation step (s); xi, eta, rho0: the attractive
    gain, the repulsive gain and the obstacles' influence distance (m). time_limit: 0 = from
    the path's length. A path with cusps is driven piece by piece, each in its gear.
    goal_tolerance: None (the follower's own: 0.3 m or a cell), metres from the path's end, or (metres,
    radians) with a heading tolerance at the end.

    Returns a gridcar.DriveResult: outcome ('reached', 'collided', 'stuck', 'timeout'), reason,
    driving_time, trajectory (N x 6: t, x, y, yaw, v, steer) and more.
    """
    return Scene(_map(map), vehicle, space).drive(path, scenario, dt, xi, eta, rho0, time_limit, goal_tolerance)


def plot(map, plan=None, drive=None, vehicle=None, ax=None, margin=5.0, title=None, distance=False):
    """Draws a map with a plan and / or a drive, as the gridcar program's pictures do (see
    gridcar.plotting.plot). Needs matplotlib; returns the matplotlib Axes."""
    from .plotting import plot as _plot
    return _plot(_map(map), plan=plan, drive=drive, vehicle=vehicle, ax=ax, margin=margin, title=title,
                 distance=distance)
