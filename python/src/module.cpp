// gridcar's Python module (gridcar._gridcar): maps, vehicles, planning and driving from Python.
// The package gridcar (python/gridcar/__init__.py) re-exports it and adds the plotting helper.
// Planning and driving release the GIL: queries on different scenes run side by side in threads.
#include "gridcar/core/Errors.h"
#include "gridcar/distance/DistanceField.h"
#include "gridcar/map/MapIO.h"
#include "gridcar/map/OccupancyGrid.h"
#include "gridcar/path/PathIO.h"
#include "gridcar/planners/PlannerFactory.h"
#include "gridcar/query/PlainLog.h"
#include "gridcar/query/PlanQuery.h"
#include "gridcar/sim/Simulation.h"
#include "gridcar/spaces/CarSpaces.h"
#include "gridcar/spaces/Setup.h"
#include "gridcar/vehicle/Dynamics.h"
#include "gridcar/vehicle/VehicleParams.h"
#include "gridcar/version.h"

#include <ompl/util/Console.h>
#include <ompl/util/Exception.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

namespace py = pybind11;

namespace gridcar::python
{
namespace
{
/// A map as Python sees it: the grid (never changed once made) and its distance field, computed
/// on first use and shared by every scene on the map.
struct Map
{
    std::shared_ptr<const OccupancyGrid> grid;
    std::string source;
    mutable std::once_flag fieldOnce;
    mutable std::shared_ptr<const DistanceField> field;

    std::shared_ptr<const DistanceField> distanceField() const
    {
        std::call_once(fieldOnce, [this] { field = std::make_shared<const DistanceField>(*grid); });
        return field;
    }
};

std::shared_ptr<Map> makeMap(OccupancyGrid g, std::string source)
{
    auto m = std::make_shared<Map>();
    m->grid = std::make_shared<const OccupancyGrid>(std::move(g));
    m->source = std::move(source);
    return m;
}

std::shared_ptr<Map> loadMapFile(const std::string &path, bool unknownFree)
{
    OccupancyGrid g = loadMap(path);
    g.setUnknownIsFree(unknownFree);
    return makeMap(std::move(g), path);
}

bool rowsFromBottom(const std::string &rowOrder)
{
    if (rowOrder == "bottom") return true;
    if (rowOrder == "top") return false;
    throw InputError("row_order '" + rowOrder + "': expected 'bottom' (ROS: the first row at the origin) or 'top' (image rows)");
}

/// A map from a 2D array: bool (True: occupied) or numbers in ROS's OccupancyGrid convention
/// (negative: unknown, >= occupied_threshold: occupied, else free).
std::shared_ptr<Map> mapFromArray(const py::array &a, double resolution, const std::vector<double> &origin,
                                  const std::string &rowOrder, double occupiedThreshold, bool unknownFree)
{
    if (a.ndim() != 2) throw InputError("the occupancy array must be 2D (rows, columns); it has " + std::to_string(a.ndim()) + " dimension(s)");
    if (!(resolution > 0) || !std::isfinite(resolution)) throw InputError("resolution must be a positive number of metres per cell");
    if (origin.size() != 2 && origin.size() != 3) throw InputError("origin must be (x, y) or (x, y, yaw)");
    for (double v : origin)
        if (!std::isfinite(v)) throw InputError("origin must be finite");
    const bool bottom = rowsFromBottom(rowOrder);
    const py::ssize_t rows = a.shape(0), cols = a.shape(1);
    if (rows < 1 || cols < 1) throw InputError("the occupancy array is empty");
    if (double(rows) * double(cols) > double(1u << 30)) throw InputError("the occupancy array has more than 2^30 cells");
    const bool isBool = a.dtype().kind() == 'b';
    const py::array_t<double, py::array::c_style | py::array::forcecast> d(a);
    const auto v = d.unchecked<2>();
    OccupancyGrid g(int(cols), int(rows), resolution);
    g.setOrigin(origin[0], origin[1], origin.size() == 3 ? origin[2] : 0.0);
    for (py::ssize_t i = 0; i < rows; ++i)
        for (py::ssize_t k = 0; k < cols; ++k)
        {
            const double x = v(i, k);
            if (std::isnan(x)) throw InputError("the occupancy array has a NaN at row " + std::to_string(i) + ", column " + std::to_string(k));
            const CellState s = isBool ? (x != 0 ? CellState::Occupied : CellState::Free)
                                       : x < 0 ? CellState::Unknown : x >= occupiedThreshold ? CellState::Occupied : CellState::Free;
            g.set(int(k), int(bottom ? rows - 1 - i : i), s);
        }
    g.setUnknownIsFree(unknownFree);
    return makeMap(std::move(g), "array");
}

VehicleParams vehicleOf(const py::object &o)
{
    if (o.is_none()) return VehicleParams::preset("paper-i");
    if (py::isinstance<VehicleParams>(o)) return o.cast<VehicleParams>();
    if (py::isinstance<py::str>(o)) return VehicleParams::fromNameOrFile(o.cast<std::string>());
    if (py::isinstance<py::dict>(o))
    {
        // the same fields as a vehicle file: JSON is YAML
        const std::string text = py::module_::import("json").attr("dumps")(o).cast<std::string>();
        return VehicleParams::fromYaml(text, "vehicle dict");
    }
    throw InputError("vehicle must be a preset name, a YAML file, a dict of vehicle fields or a gridcar.Vehicle");
}

SpaceKind spaceOf(const std::string &s)
{
    if (s == "se2") return SpaceKind::SE2;
    if (s == "dubins") return SpaceKind::Dubins;
    if (s == "reeds-shepp" || s == "reeds_shepp") return SpaceKind::ReedsShepp;
    throw InputError("space '" + s + "': expected 'se2', 'dubins' or 'reeds-shepp'");
}

/// A pose from (x, y) or (x, y, yaw in radians); @p hasYaw says which.
Pose2 poseOf(const py::object &o, const char *what, bool &hasYaw)
{
    std::vector<double> v;
    try
    {
        v = o.cast<std::vector<double>>();
    }
    catch (const py::cast_error &)
    {
        throw InputError(std::string(what) + " must be (x, y) or (x, y, yaw_rad)");
    }
    if (v.size() != 2 && v.size() != 3) throw InputError(std::string(what) + " must be (x, y) or (x, y, yaw_rad); it has " + std::to_string(v.size()) + " numbers");
    for (double x : v)
        if (!std::isfinite(x)) throw InputError(std::string(what) + " must be finite");
    hasYaw = v.size() == 3;
    return {v[0], v[1], hasYaw ? v[2] : 0.0};
}

std::string describe(const Pose2 &p, bool yaw)
{
    std::ostringstream s;
    s.precision(3);
    s << std::fixed << "(" << p.x << ", " << p.y;
    if (yaw) s << ", " << p.yaw << " rad";
    s << ")";
    return s.str();
}

py::array_t<double> posesArray(const std::vector<Pose2> &path)
{
    py::array_t<double> a({py::ssize_t(path.size()), py::ssize_t(3)});
    auto w = a.mutable_unchecked<2>();
    for (std::size_t i = 0; i < path.size(); ++i)
    {
        w(i, 0) = path[i].x;
        w(i, 1) = path[i].y;
        w(i, 2) = path[i].yaw;
    }
    return a;
}

std::vector<Pose2> posesOf(const py::object &o)
{
    if (py::hasattr(o, "path") && !py::isinstance<py::array>(o)) return posesOf(o.attr("path"));
    const py::array_t<double, py::array::c_style | py::array::forcecast> a(o);
    if (a.ndim() != 2 || a.shape(1) != 3) throw InputError("a path must be an N x 3 array of x, y, yaw_rad (or a PlanResult)");
    const auto v = a.unchecked<2>();
    std::vector<Pose2> path;
    for (py::ssize_t i = 0; i < a.shape(0); ++i)
    {
        if (!std::isfinite(v(i, 0)) || !std::isfinite(v(i, 1)) || !std::isfinite(v(i, 2)))
            throw InputError("path pose " + std::to_string(i) + " is not finite");
        path.push_back({v(i, 0), v(i, 1), v(i, 2)});
    }
    if (path.size() < 2) throw InputError("a path needs at least 2 poses");
    return path;
}

/// What plan() returns.
struct PlanResult
{
    std::string status;
    bool exact{false};
    std::string planner;
    std::vector<Pose2> path, rawPath;
    double seconds{0}, length{0}, cost{0}, maxCurvature{0}, minClearance{0}, minPathDistance{0}, maxTurnDeg{0};
    double maxTurnAngleDeg{0};
    double drivingTimeProfile{0}, goalDistance{NAN}, goalHeadingErrorDeg{NAN};
    int turns{0}, cusps{0};
    std::uint64_t expanded{0};
    bool drivable{false};
    std::string notDrivableBecause, notExactBecause;
};

/// goal_tolerance: None (exact), a position tolerance in metres, or (metres, radians).
GoalTolerance toleranceOf(const py::object &o)
{
    GoalTolerance t;
    if (o.is_none()) return t;
    try
    {
        if (py::isinstance<py::sequence>(o))
        {
            const auto seq = o.cast<std::vector<double>>();
            if (seq.size() != 2) throw InputError("");
            t.position = seq[0];
            t.yaw = seq[1];
        }
        else
            t.position = o.cast<double>();
    }
    catch (const std::exception &)
    {
        throw InputError("goal_tolerance must be None, metres, or (metres, radians)");
    }
    if (!(t.position >= 0) || !(t.yaw >= 0) || !std::isfinite(t.position) || t.yaw > M_PI)
        throw InputError("goal_tolerance must be finite and >= 0 (the yaw part at most pi)");
    return t;
}

/// A map, a vehicle and an OMPL set-up on them (distance field, FCL footprint checker, the
/// space): made once, then any number of plans and drives. One query at a time per scene.
struct Scene
{
    std::shared_ptr<Map> map;
    VehicleParams vehicle;
    std::string spaceName;
    GridSetup setup;
    std::mutex busy;

    Scene(std::shared_ptr<Map> m, const py::object &v, const std::string &space)
        : map(std::move(m)), vehicle(vehicleOf(v)), spaceName(space)
    {
        SetupOptions so;
        so.space = spaceOf(space);
        std::shared_ptr<const Map> mm = map;
        VehicleParams veh = vehicle;
        py::gil_scoped_release nogil;
        try
        {
            setup = makeGridSetup(mm->grid, veh, so, mm->distanceField());
        }
        catch (const std::invalid_argument &e)
        {
            throw InputError("space " + space + ": " + e.what());
        }
    }

    std::string whyInvalid(const Pose2 &p, bool anyHeading) const
    {
        return whyPoseInvalid(*setup.checker, *map->grid, p, anyHeading);
    }

    PlanResult plan(const py::object &startObj, const py::object &goalObj, const std::string &plannerName,
                    const py::dict &settings, double timeLimit, bool smooth, const py::object &toleranceObj)
    {
        const GoalTolerance tolerance = toleranceOf(toleranceObj);
        if (!(timeLimit > 0) || !std::isfinite(timeLimit) || timeLimit > 86400)
            throw InputError("time_limit must be a positive number of seconds (at most a day)");
        bool startYaw = false, goalYaw = false;
        Pose2 start = poseOf(startObj, "start", startYaw), goal = poseOf(goalObj, "goal", goalYaw);
        PlannerParams params;
        for (const auto &kv : settings)
        {
            const std::string key = py::str(kv.first).cast<std::string>();
            const py::handle val = kv.second;
            std::string text = py::isinstance<py::bool_>(val) ? (val.cast<bool>() ? "1" : "0") : py::str(val).cast<std::string>();
            params.emplace_back(key, text);
        }
        py::gil_scoped_release nogil;
        std::lock_guard<std::mutex> lock(busy);
        for (auto [what, pose, hasYaw] : {std::make_tuple("start", &start, startYaw), std::make_tuple("goal", &goal, goalYaw)})
        {
            if (const std::string why = whyInvalid(*pose, !hasYaw); !why.empty())
                throw InputError(std::string(what) + " " + describe(*pose, hasYaw) + " is " + why);
            double yaw = 0;
            if (!hasYaw && setup.checker->fitsAtSomeHeading(pose->x, pose->y, 72, &yaw)) pose->yaw = yaw;
        }
        const ompl::base::PlannerPtr planner =
            configurePlanner(setup.ss->getSpaceInformation(), {plannerName, params, !startYaw, smooth});
        const QueryResult q = runQuery(setup, planner, start, goal, timeLimit, !goalYaw, tolerance);
        PlanResult r;
        r.status = q.status.asString();
        r.exact = q.status == ompl::base::PlannerStatus::EXACT_SOLUTION;
        r.planner = plannerName;
        r.path = q.path;
        r.rawPath = q.rawPath;
        r.seconds = q.seconds;
        r.length = q.metrics.length;
        r.cost = q.cost;
        r.turns = q.metrics.turns;
        r.cusps = q.metrics.cusps;
        r.maxTurnDeg = q.maxTurnDeg;
        r.maxTurnAngleDeg = q.metrics.maxTurnAngleDeg;
        r.maxCurvature = q.metrics.maxCurvature;
        r.minClearance = q.metrics.minClearance;
        r.minPathDistance = q.metrics.minPathDistance;
        r.expanded = q.expanded;
        r.drivable = !q.path.empty() && q.drivability.drivable;
        r.notDrivableBecause = q.path.empty() ? "no path" : q.drivability.reason;
        r.notExactBecause = q.notExactBecause;
        if (!q.path.empty())
        {
            DrivingTimeParams profile;
            profile.reversing = setup.reversing() || q.metrics.cusps > 0;
            r.drivingTimeProfile = drivingTime(q.path, vehicle, profile);
            const Pose2 &e = q.path.back();
            r.goalDistance = std::hypot(e.x - goal.x, e.y - goal.y);
            if (goalYaw) r.goalHeadingErrorDeg = std::abs(std::remainder(e.yaw - goal.yaw, 2 * M_PI)) * 180.0 / M_PI;
        }
        return r;
    }

    DriveResult drive(const py::object &pathObj, const py::object &scenarioObj, double dt, double xi, double eta, double rho0,
                      double timeLimit, const py::object &toleranceObj)
    {
        const GoalTolerance tolerance = toleranceOf(toleranceObj);
        if (!(dt > 0) || dt > 1.0) throw InputError("dt must be in (0, 1] s");
        if (!(xi >= 0) || !(eta >= 0) || !(rho0 > 0) || !std::isfinite(xi + eta + rho0))
            throw InputError("xi and eta must be >= 0 and rho0 > 0 (finite)");
        if (!(timeLimit >= 0) || !std::isfinite(timeLimit)) throw InputError("time_limit must be >= 0 s (0: from the path)");
        const std::vector<Pose2> path = posesOf(pathObj);
        Scenario sc;
        if (!scenarioObj.is_none()) sc = Scenario::load(scenarioObj.cast<std::string>());
        FollowerParams fp;
        fp.dt = dt;
        fp.xi = xi;
        fp.eta = eta;
        fp.rho0 = rho0;
        fp.timeLimit = timeLimit;
        if (tolerance.position > 0) fp.goalTolerance = tolerance.position;
        if (tolerance.yaw > 0) fp.goalYawTolerance = tolerance.yaw;
        py::gil_scoped_release nogil;
        std::lock_guard<std::mutex> lock(busy);
        if (!setup.checker->isValid(path.front()))
            throw InputError("the path starts " + describe(path.front(), true) + " off the map or in collision");
        return drivePath(path, *setup.checker, sc, fp);
    }
};

py::array_t<double> trajectoryArray(const DriveResult &r)
{
    py::array_t<double> a({py::ssize_t(r.trajectory.size()), py::ssize_t(6)});
    auto w = a.mutable_unchecked<2>();
    for (std::size_t i = 0; i < r.trajectory.size(); ++i)
    {
        const TrajectorySample &s = r.trajectory[i];
        w(i, 0) = s.t;
        w(i, 1) = s.x;
        w(i, 2) = s.y;
        w(i, 3) = s.yaw;
        w(i, 4) = s.v;
        w(i, 5) = s.steer;
    }
    return a;
}

/// A per-cell array of @p value in the requested row order.
template <typename T, typename F>
py::array_t<T> cellArray(const OccupancyGrid &g, const std::string &rowOrder, F value)
{
    const bool bottom = rowsFromBottom(rowOrder);
    py::array_t<T> a({py::ssize_t(g.height()), py::ssize_t(g.width())});
    auto w = a.template mutable_unchecked<2>();
    for (int i = 0; i < g.height(); ++i)
    {
        const int row = bottom ? g.height() - 1 - i : i;
        for (int k = 0; k < g.width(); ++k) w(i, k) = value(k, row);
    }
    return a;
}

}  // namespace
}  // namespace gridcar::python

using namespace gridcar;
using namespace gridcar::python;

PYBIND11_MODULE(_gridcar, m)
{
    m.doc() = "gridcar: vehicle-aware grid planners for OMPL (corner-weighted A*, improved A*) on occupancy-grid maps.";
    m.attr("__version__") = GRIDCAR_VERSION;
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    usePlainLog();  // warnings on stderr without OMPL's source file and line, as the program's

    // our exceptions as Python ones, with the same messages (bad input: ValueError's kind)
    static py::exception<MapLoadError> mapLoadError(m, "MapLoadError", PyExc_ValueError);
    static py::exception<InputError> inputError(m, "InputError", PyExc_ValueError);
    py::register_exception_translator([](std::exception_ptr p) {
        try
        {
            if (p) std::rethrow_exception(p);
        }
        catch (const MapLoadError &e)
        {
            mapLoadError(e.what());
        }
        catch (const InputError &e)
        {
            inputError(e.what());
        }
        catch (const ompl::Exception &e)
        {
            PyErr_SetString(PyExc_ValueError, e.what());
        }
    });
    m.attr("MapLoadError").attr("__doc__") = "A map, vehicle or scenario file (or dict) that cannot be read: the message names it and says why.";
    m.attr("InputError").attr("__doc__") = "A bad argument: a pose off the map or in collision, an unknown planner or setting, a bad value.";

    py::class_<Map, std::shared_ptr<Map>>(m, "Map", R"doc(An occupancy-grid map (immutable once made).

Cells are free, occupied or unknown; unknown cells count as blocked unless the map was made with
unknown_free=True. Coordinates are metres in the map frame (ROS's map_server convention: the
origin is the lower-left corner of the lower-left cell).)doc")
        .def_static("load", &loadMapFile, py::arg("path"), py::arg("unknown_free") = false,
                    "Reads a map file: a ROS map_server .yaml (with its image), a Moving AI .map, an OMPL .ppm or a "
                    "plain image (1 m per pixel). Raises MapLoadError naming the file and the reason.")
        .def_static("from_array", &mapFromArray, py::arg("occupancy"), py::arg("resolution"),
                    py::arg("origin") = std::vector<double>{0.0, 0.0, 0.0}, py::arg("row_order") = "bottom",
                    py::arg("occupied_threshold") = 65.0, py::arg("unknown_free") = false,
                    R"doc(A map from a 2D array of shape (rows, columns).

occupancy: bool (True: occupied) or numbers as in ROS's nav_msgs/OccupancyGrid (negative:
unknown, >= occupied_threshold: occupied, else free). resolution: metres per cell. origin:
(x, y[, yaw]) of the lower-left corner. row_order: 'bottom' (ROS: the first row is at the
origin) or 'top' (image rows: the first row is the top of the map).)doc")
        .def_property_readonly("width", [](const Map &mp) { return mp.grid->width(); }, "Columns.")
        .def_property_readonly("height", [](const Map &mp) { return mp.grid->height(); }, "Rows.")
        .def_property_readonly("resolution", [](const Map &mp) { return mp.grid->resolution(); }, "Metres per cell.")
        .def_property_readonly("origin", [](const Map &mp) { return py::make_tuple(mp.grid->originX(), mp.grid->originY(), mp.grid->originYaw()); },
                               "(x, y, yaw) of the lower-left corner, metres and radians.")
        .def_property_readonly("extent", [](const Map &mp) {
                const OccupancyGrid &g = *mp.grid;
                return py::make_tuple(g.originX(), g.originX() + g.sizeX(), g.originY(), g.originY() + g.sizeY()); },
                               "(x_min, x_max, y_min, y_max) in metres, as matplotlib's imshow takes it.")
        .def_property_readonly("unknown_free", [](const Map &mp) { return mp.grid->unknownIsFree(); }, "Whether unknown cells count as free.")
        .def_property_readonly("source", [](const Map &mp) { return mp.source; }, "The file it was read from ('array' for from_array).")
        .def("to_array", [](const Map &mp, const std::string &rowOrder) {
                const OccupancyGrid &g = *mp.grid;
                return cellArray<std::int8_t>(g, rowOrder, [&](int c, int r) {
                    const CellState s = g.at(c, r);
                    return std::int8_t(s == CellState::Occupied ? 100 : s == CellState::Unknown ? -1 : 0); }); },
             py::arg("row_order") = "bottom", "The cells as an int8 array (rows, columns) in ROS's values: 0 free, 100 occupied, -1 unknown.")
        .def("costs", [](const Map &mp, const std::string &rowOrder) -> py::object {
                const OccupancyGrid &g = *mp.grid;
                if (!g.hasCosts()) return py::none();
                return cellArray<std::uint8_t>(g, rowOrder, [&](int c, int r) { return g.cost(c, r); }); },
             py::arg("row_order") = "bottom", "The map's cost layer (uint8, 0-255) where it has one (a grey-level map read in 'scale' mode), else None.")
        .def("distance_field", [](const Map &mp, const std::string &rowOrder) {
                std::shared_ptr<const DistanceField> f;
                {
                    py::gil_scoped_release nogil;
                    f = mp.distanceField();
                }
                return cellArray<float>(*mp.grid, rowOrder, [&](int c, int r) { return float(f->cellDistance(c, r)); }); },
             py::arg("row_order") = "bottom",
             "The distance from each cell's centre to the nearest blocked cell, metres (float32, rows x columns; 0 on blocked cells). "
             "Computed once per map and shared by its scenes.")
        .def("__repr__", [](const Map &mp) {
                const OccupancyGrid &g = *mp.grid;
                std::ostringstream s;
                s << "gridcar.Map(" << g.width() << " x " << g.height() << " cells at " << g.resolution() << " m, from " << mp.source << ")";
                return s.str(); });

    py::class_<VehicleParams>(m, "Vehicle", R"doc(A vehicle: its body (rectangle or polygon around the rear axle), steering and speeds.

Vehicle(name_or_file='paper-i'): a preset (gridcar.vehicle_presets()) or a YAML vehicle file.
Vehicle.from_dict({...}): the same fields as a vehicle file (length, width, wheelbase,
rear_overhang, max_steer_deg, max_speed, ..., optional preset and scale).)doc")
        .def(py::init([](const std::string &s) { return VehicleParams::fromNameOrFile(s); }), py::arg("name_or_file") = "paper-i")
        .def_static("from_dict", [](const py::dict &d) { return vehicleOf(d); }, py::arg("fields"),
                    "A vehicle from a dict of vehicle-file fields; MapLoadError names a bad field.")
        .def_readonly("name", &VehicleParams::name, "the preset's name, or the file's")
        .def_readonly("length", &VehicleParams::length, "m, bumper to bumper")
        .def_readonly("width", &VehicleParams::width, "m")
        .def_readonly("wheelbase", &VehicleParams::wheelbase, "m")
        .def_readonly("rear_overhang", &VehicleParams::rearOverhang, "m, rear bumper to rear axle (the reference point)")
        .def_readonly("max_steer_deg", &VehicleParams::maxSteerDeg, "deg, the largest steering angle of the front wheels")
        .def_readonly("max_speed", &VehicleParams::maxSpeed, "m/s")
        .def_property_readonly("max_curvature", &VehicleParams::maxCurvature, "K_max, 1/m")
        .def_property_readonly("min_turning_radius", &VehicleParams::minTurningRadius, "R_min, m")
        .def_property_readonly("outline", [](const VehicleParams &v) {
                py::array_t<double> a({py::ssize_t(v.outline().size()), py::ssize_t(2)});
                auto w = a.mutable_unchecked<2>();
                const auto o = v.outline();
                for (std::size_t i = 0; i < o.size(); ++i) { w(i, 0) = o[i][0]; w(i, 1) = o[i][1]; }
                return a; },
                               "The body's outline in the body frame (x forward from the rear axle), N x 2, counter-clockwise.")
        .def("__repr__", [](const VehicleParams &v) {
                std::ostringstream s;
                s << "gridcar.Vehicle('" << v.name << "': " << v.length << " x " << v.width << " m, R_min " << v.minTurningRadius() << " m)";
                return s.str(); });
    m.def("vehicle_presets", &VehicleParams::presetNames, "The names of the vehicle presets.");
    m.def("planners", &plannerNames, "The names gridcar.plan() takes (ours and OMPL's).");

    py::class_<PlanResult>(m, "PlanResult", "What plan() returns: the status, the path and its measures.")
        .def_readonly("status", &PlanResult::status, "OMPL's PlannerStatus as text: 'Exact solution', 'Approximate solution', 'Timeout', ...")
        .def_readonly("exact", &PlanResult::exact, "True for an exact solution.")
        .def_readonly("planner", &PlanResult::planner, "the planner's name as given to plan()")
        .def_property_readonly("path", [](const PlanResult &r) { return posesArray(r.path); }, "N x 3 array: x, y (m), yaw (rad).")
        .def_property_readonly("raw_path", [](const PlanResult &r) { return posesArray(r.rawPath); }, "The path before smoothing (the same where none ran).")
        .def_readonly("time", &PlanResult::seconds, "s, wall time of the solve (smoothing included)")
        .def_readonly("length", &PlanResult::length, "m")
        .def_readonly("cost", &PlanResult::cost, "the planner's own search cost (the length for OMPL's planners)")
        .def_readonly("turns", &PlanResult::turns, "turns of the path: stretches where the chord directions a few metres before and after differ by more than a threshold (a 90-degree corner is one turn, sharp or smooth)")
        .def_readonly("cusps", &PlanResult::cusps, "changes between forward and reverse")
        .def_readonly("max_turn_deg", &PlanResult::maxTurnDeg, "deg, the largest heading change at one vertex (depends on the sampling)")
        .def_readonly("max_turn_angle_deg", &PlanResult::maxTurnAngleDeg,
                      "deg, the largest heading change of one turn (a sharp corner and the arc driving it alike)")
        .def_readonly("max_curvature", &PlanResult::maxCurvature, "1/m")
        .def_readonly("min_clearance", &PlanResult::minClearance, "m, smallest distance from the body to an obstacle")
        .def_readonly("min_path_distance", &PlanResult::minPathDistance, "m, smallest distance from the path line to an obstacle")
        .def_readonly("expanded", &PlanResult::expanded, "nodes the search expanded (0 for OMPL's planners)")
        .def_readonly("driving_time_profile", &PlanResult::drivingTimeProfile,
                      "s, the velocity profile's time along the path (braking for corners, stopping at cusps; no follower)")
        .def_readonly("drivable", &PlanResult::drivable,
                      "the independent check: the full body free at 2 cm steps, curvature within K_max, ending at the goal")
        .def_readonly("not_drivable_because", &PlanResult::notDrivableBecause, "why not drivable ('' when drivable)")
        .def_readonly("not_exact_because", &PlanResult::notExactBecause, "why no exact solution though time was left ('' otherwise)")
        .def_readonly("goal_distance", &PlanResult::goalDistance, "m from the path's end to the goal (NaN without a path)")
        .def_readonly("goal_heading_error_deg", &PlanResult::goalHeadingErrorDeg, "deg (NaN without a goal yaw or a path)")
        .def("__repr__", [](const PlanResult &r) {
                std::ostringstream s;
                s << "gridcar.PlanResult(" << r.planner << ": " << r.status << ", " << r.length << " m, " << r.seconds << " s, "
                  << (r.drivable ? "drivable" : "not drivable") << ")";
                return s.str(); });

    py::class_<DriveResult>(m, "DriveResult", "What drive() returns: how the simulated drive ended and its trajectory.")
        .def_property_readonly("outcome", [](const DriveResult &r) { return DriveResult::outcomeName(r.outcome); },
                               "'reached', 'collided', 'stuck' or 'timeout'")
        .def_property_readonly("reached", [](const DriveResult &r) { return r.outcome == DriveResult::Outcome::Reached; },
                               "True when the car stopped at the goal (outcome 'reached').")
        .def_readonly("reason", &DriveResult::reason, "one line: where the run stopped and which rule held it")
        .def_readonly("driving_time", &DriveResult::drivingTime, "s of simulated time")
        .def_readonly("path_length", &DriveResult::pathLength, "m")
        .def_readonly("distance_driven", &DriveResult::distanceDriven, "m")
        .def_readonly("cross_track_mean", &DriveResult::crossTrackMean, "m")
        .def_readonly("cross_track_max", &DriveResult::crossTrackMax, "m")
        .def_readonly("min_clearance", &DriveResult::minClearance, "m")
        .def_readonly("recoveries", &DriveResult::recoveries, "times the follower had to get going again after progress stalled (a virtual obstacle where it stood, the via-point moved ahead, or a back-up)")
        .def_property_readonly("trajectory", &trajectoryArray, "N x 6 array: t (s), x, y (m), yaw (rad), v (m/s, < 0 reversing), steer (rad)")
        .def("__repr__", [](const DriveResult &r) {
                std::ostringstream s;
                s << "gridcar.DriveResult(" << DriveResult::outcomeName(r.outcome) << ", " << r.drivingTime << " s)";
                return s.str(); });

    py::class_<Scene, std::shared_ptr<Scene>>(m, "Scene", R"doc(A map, a vehicle and the OMPL set-up on them, for many queries.

Scene(map, vehicle='paper-i', space='se2') builds the FCL footprint checker and the space once
(the map's distance field is shared by every scene on it); plan() and drive() then cost only
the query. space: 'se2' (gridcar's grid SE(2) space), 'dubins' or 'reeds-shepp' (OMPL's, at the
vehicle's R_min). A scene runs one query at a time (others wait); use one scene per thread to
plan side by side.)doc")
        .def(py::init<std::shared_ptr<Map>, const py::object &, const std::string &>(), py::arg("map"),
             py::arg("vehicle") = py::none(), py::arg("space") = "se2")
        .def_readonly("map", &Scene::map, "the Map the scene plans on")
        .def_readonly("vehicle", &Scene::vehicle, "the Vehicle whose body is checked")
        .def_readonly("space", &Scene::spaceName, "'se2', 'dubins' or 'reeds-shepp'")
        .def("plan", &Scene::plan, py::arg("start"), py::arg("goal"), py::arg("planner") = "corner-astar",
             py::arg("settings") = py::dict(), py::arg("time_limit") = 10.0, py::arg("smooth") = false,
             py::arg("goal_tolerance") = py::none(), R"doc(Plans start -> goal (see gridcar.plan()).)doc")
        .def("drive", &Scene::drive, py::arg("path"), py::arg("scenario") = py::none(), py::arg("dt") = 0.05,
             py::arg("xi") = 1.0, py::arg("eta") = 0.6, py::arg("rho0") = 1.5, py::arg("time_limit") = 0.0,
             py::arg("goal_tolerance") = py::none(),
             R"doc(Drives a path (see gridcar.drive()).)doc")
        .def("why_invalid", [](const Scene &s, const py::object &pose) {
                bool hasYaw = false;
                const Pose2 p = poseOf(pose, "pose", hasYaw);
                return s.whyInvalid(p, !hasYaw); }, py::arg("pose"),
             "'' where the vehicle fits at the pose (x, y[, yaw]; without a yaw: at some heading), else why not.");
}
